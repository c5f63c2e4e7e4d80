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
  std::string unit = "m"; ///< m, dm, cm, mm, or auto until resolveAutomatic
  std::string up = "y";   ///< x, y, z, or auto until resolveAutomatic
  double scale = 0.0;     ///< metres per file unit when given; replaces --unit
  double fps = 25.0;
};
void addSequenceOptions(po::options_description& options, SequenceOptions& target);
/// Replaces "auto" in --unit and --up by what the first frame of `input` suggests (the longest
/// side up; the unit that makes it a person's height) and says so on stderr, so that all that
/// follows (the work cache, metrics.json) sees the values used. UsageError when no unit fits.
void resolveAutomatic(SequenceOptions& options, const std::string& input);
/// Checks the values (UsageError when wrong, or still auto) and converts them to reader
/// conventions.
clothtrack::FrameConventions toConventions(const SequenceOptions& options);

/// --template-criterion: "rest-pose" or "area-ratio" (UsageError otherwise).
clothtrack::TemplateCriterion parseTemplateCriterion(const std::string& name);
} // namespace clothtrack::app
