// clothtrack: command-line front end of the ClothTrack toolkit.
#include "Commands.h"
#include "Ranks.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/MemoryReuse.h>

#include <vtkLogger.h>
#include <vtkObject.h>
#include <vtkOutputWindow.h>

#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <map>

namespace
{
struct Command
{
  int (*run)(const clothtrack::app::Args&);
  const char* summary;
};

const std::map<std::string, Command>& commands()
{
  static const std::map<std::string, Command> table = {
      {"align",
       {clothtrack::app::runAlign,
        "align a sequence: body fit, template, correspondences, template fit, errors"}},
      {"correspond",
       {clothtrack::app::runCorrespond,
        "stages 1 and 2 alone: landmarks, template and correspondences into the work folder"}},
      {"fit",
       {clothtrack::app::runFit,
        "stage 3 alone: the template fit (and errors) from the work folder of 'correspond'"}},
      {"inspect",
       {clothtrack::app::runInspect, "read a sequence and print per-frame geometry and topology"}},
      {"body-fit",
       {clothtrack::app::runBodyFit,
        "fit the body model under the clothing and place its landmarks on every frame"}},
      {"select-template",
       {clothtrack::app::runSelectTemplate,
        "choose the template frame of a sequence (persistent splits, genus, area ratio)"}},
      {"eval",
       {clothtrack::app::runEval,
        "errors of an aligned output folder against a ground truth and/or markers"}},
      {"render",
       {clothtrack::app::runRender,
        "the report plus a movie (PNG frames, MP4 with ffmpeg) or turntable of the result"}},
      {"report",
       {clothtrack::app::runReport,
        "plots, renders and report.html for the output folder of 'align'"}},
      {"convert",
       {clothtrack::app::runConvert,
        "read a sequence and write it as a .pvd collection (and OBJ)"}},
      {"body-model",
       {clothtrack::app::runBodyModel,
        "write the built-in body model file, or a body of a given shape"}},
      {"import-makehuman",
       {clothtrack::app::runImportMakeHuman,
        "convert MakeHuman CC0 assets into a body model file"}},
      {"reconstruct",
       {clothtrack::app::runReconstruct,
        "make each point cloud of a sequence into a mesh (outliers, normals, Poisson, crop)"}},
      {"simulate-capture",
       {clothtrack::app::runSimulateCapture,
        "re-mesh a ground-truth sequence as a multi-view capture would, with the source map"}},
      {"synth",
       {clothtrack::app::runSynth,
        "generate a synthetic clothed capture with ground truth (body, garment, motion)"}},
  };
  return table;
}

void printUsage(std::FILE* out)
{
  std::fprintf(out, "usage: clothtrack <command> [options]\n\ncommands:\n");
  for (const auto& [name, command] : commands())
    std::fprintf(out, "  %-18s %s\n", name.c_str(), command.summary);
  std::fprintf(out, "\n'clothtrack <command> --help' describes a command's options.\n");
}
} // namespace

namespace
{
/// The command's exit code; an error is one line on stderr.
int runCommand(const std::string& name, int argc, char** argv)
{
  const auto it = commands().find(name);
  if (it == commands().end())
  {
    std::fprintf(stderr, "clothtrack: unknown command '%s' (try 'clothtrack --help')\n",
                 name.c_str());
    return 1;
  }
  try
  {
    return it->second.run(clothtrack::app::Args(argv + 2, argv + argc));
  }
  catch (const clothtrack::app::UsageError& e)
  {
    std::fprintf(stderr, "clothtrack %s: %s\n", name.c_str(), e.message.c_str());
  }
  catch (const clothtrack::Error& e)
  {
    std::fprintf(stderr, "clothtrack %s: error: %s\n", name.c_str(), e.what());
  }
  catch (const std::filesystem::filesystem_error& e)
  {
    // "filesystem error: cannot create directories: Not a directory [out/work]" said as
    // "out/work: Not a directory".
    const std::string path = e.path1().empty() ? std::string("a file") : e.path1().string();
    std::fprintf(stderr, "clothtrack %s: error: %s: %s\n", name.c_str(), path.c_str(),
                 e.code().message().c_str());
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "clothtrack %s: error: %s\n", name.c_str(), e.what());
  }
  return 1;
}
/// The exit code of the command line: usage, version, or a command.
int dispatch(int argc, char** argv)
{
  if (argc < 2)
  {
    printUsage(stderr);
    return 1;
  }
  const std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help")
  {
    printUsage(stdout);
    return 0;
  }
  if (name == "--version")
  {
    std::printf("clothtrack %s\n", CLOTHTRACK_VERSION);
    return 0;
  }
  return runCommand(name, argc, argv);
}
} // namespace

int main(int argc, char** argv)
{
  clothtrack::keepFreedMemoryForReuse();
  clothtrack::app::ranks::start(&argc, &argv);
  // VTK messages go to stderr as plain lines rather than to a window or a popup.
  vtkOutputWindow::GetInstance()->SetDisplayModeToAlwaysStdErr();
  // The logger would print each of them a second time, in colour, with a time stamp.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  const int code = dispatch(argc, argv);
  std::fflush(stdout);
  std::fflush(stderr);
  if (code != 0 && clothtrack::app::ranks::count() > 1) clothtrack::app::ranks::abortAll();
  clothtrack::app::ranks::stop();
  return code;
}
