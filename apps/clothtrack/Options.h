#pragma once
// Shared Boost.Program_options handling for subcommands.
#include "Commands.h"

#include "ctMeshConversion.h"

#include <clothtrack/selection/TemplateSelection.h>

#include <boost/program_options.hpp>

#include <string>

namespace clothtrack::app
{
namespace po = boost::program_options;

/// Parses args against `options` and `positional`; prints usage and returns false for --help.
/// Throws UsageError for unknown or malformed options.
bool parseOptions(const Args& args, const std::string& usage, po::options_description& options,
                  const po::positional_options_description& positional, po::variables_map& values);

/// Options shared by every command that reads a sequence.
struct SequenceOptions
{
  std::string unit = "m";
  std::string up = "y";
  double fps = 25.0;
};
void addSequenceOptions(po::options_description& options, SequenceOptions& target);
/// Checks the values (UsageError when wrong) and converts them to reader conventions.
clothtrack::FrameConventions toConventions(const SequenceOptions& options);

/// --template-criterion: "rest-pose" or "area-ratio" (UsageError otherwise).
clothtrack::TemplateCriterion parseTemplateCriterion(const std::string& name);
} // namespace clothtrack::app
