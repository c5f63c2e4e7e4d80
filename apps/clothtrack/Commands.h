#pragma once
// Subcommands of the clothtrack app. Each parses its own options from args (everything after
// the subcommand name) and returns the process exit code: 0 success, 1 user error.
#include <string>
#include <vector>

namespace clothtrack::app
{
using Args = std::vector<std::string>;

int runAlign(const Args& args);
int runCorrespond(const Args& args);
int runFit(const Args& args);
int runInspect(const Args& args);
int runReport(const Args& args);
int runEval(const Args& args);
int runRender(const Args& args);
int runConvert(const Args& args);
int runBodyModel(const Args& args);
int runSimulateCapture(const Args& args);
int runReconstruct(const Args& args);
int runSynth(const Args& args);
int runImportMakeHuman(const Args& args);
int runSelectTemplate(const Args& args);
int runBodyFit(const Args& args);

/// Raised for a user error (bad option, bad path); main prints the message as one line.
struct UsageError
{
  std::string message;
};
} // namespace clothtrack::app
