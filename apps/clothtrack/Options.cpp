#include "Options.h"

#include "ctPointCloudFile.h"

#include <clothtrack/io/FrameList.h>
#include <clothtrack/mesh/SubjectSize.h>

#include <cmath>
#include <cstdio>
#include <iostream>

namespace clothtrack::app
{
bool parseOptions(const Args& args, const std::string& usage, po::options_description& options,
                  const po::positional_options_description& positional, po::variables_map& values)
{
  options.add_options()("help,h", "show this help");
  try
  {
    po::store(po::command_line_parser(args).options(options).positional(positional).run(), values);
    if (values.count("help"))
    {
      std::cout << "usage: " << usage << "\n\n" << options << "\n";
      return false;
    }
    po::notify(values);
  }
  catch (const po::error& e)
  {
    throw UsageError{std::string(e.what()) + " (usage: " + usage + ")"};
  }
  return true;
}

void addSequenceOptions(po::options_description& options, SequenceOptions& target)
{
  options.add_options()("unit", po::value(&target.unit)->default_value("m"),
                        "length unit of the input files: m, dm, cm, mm, or auto (from the "
                        "subject's height in the first frame)")(
      "scale", po::value(&target.scale)->default_value(0.0),
      "metres per file unit, for any other unit (replaces --unit)")(
      "up", po::value(&target.up)->default_value("y"),
      "up axis of the input files: x, y, z, or auto (the first frame's longest side)")(
      "fps", po::value(&target.fps)->default_value(25.0),
      "frames per second (time of frame k = k / fps)");
}

void resolveAutomatic(SequenceOptions& options, const std::string& input)
{
  if (options.unit != "auto" && options.up != "auto") return;
  const std::vector<std::string> frames = clothtrack::listFrames(input);
  clothtrack::TriangleMesh first;
  if (clothtrack::isPointCloudFile(frames.front()))
    first.V = clothtrack::readPointCloudFile(frames.front()).P;
  else
    first = clothtrack::readMeshFile(frames.front());
  if (options.up == "auto")
  {
    options.up = std::string(1, "xyz"[clothtrack::inferUpAxis(first)]);
    std::fprintf(stderr, "--up auto: %s (the longest side of %s)\n", options.up.c_str(),
                 frames.front().c_str());
  }
  if (options.unit == "auto")
  {
    const int up = options.up == "x" || options.up == "X"   ? 0
                   : options.up == "z" || options.up == "Z" ? 2
                                                            : 1;
    const double scale = clothtrack::inferUnitScale(first, up);
    if (scale == 0)
      throw UsageError{frames.front() + ": no unit of m, dm, cm or mm makes the subject a " +
                       "person's height; give --scale (metres per file unit)"};
    options.unit = clothtrack::unitName(scale);
    std::fprintf(stderr, "--unit auto: %s (the subject's height in %s)\n", options.unit.c_str(),
                 frames.front().c_str());
  }
}

clothtrack::FrameConventions toConventions(const SequenceOptions& options)
{
  clothtrack::FrameConventions c;
  if (options.unit == "m")
    c.unitScale = 1.0;
  else if (options.unit == "dm")
    c.unitScale = 0.1;
  else if (options.unit == "cm")
    c.unitScale = 1e-2;
  else if (options.unit == "mm")
    c.unitScale = 1e-3;
  else if (options.unit == "auto")
    throw UsageError{"--unit auto is not available for this command; give the unit"};
  else
    throw UsageError{"--unit must be m, dm, cm, mm or auto (got '" + options.unit + "')"};
  if (options.scale < 0 || !std::isfinite(options.scale))
    throw UsageError{"--scale must be positive (metres per file unit)"};
  if (options.scale > 0)
  {
    if (options.unit != "m") throw UsageError{"give --unit or --scale, not both"};
    c.unitScale = options.scale;
  }
  if (options.up == "x" || options.up == "X")
    c.upAxis = 0;
  else if (options.up == "y" || options.up == "Y")
    c.upAxis = 1;
  else if (options.up == "z" || options.up == "Z")
    c.upAxis = 2;
  else if (options.up == "auto")
    throw UsageError{"--up auto is not available for this command; give the axis"};
  else
    throw UsageError{"--up must be x, y, z or auto (got '" + options.up + "')"};
  if (!(options.fps > 0)) throw UsageError{"--fps must be positive"};
  return c;
}

clothtrack::TemplateCriterion parseTemplateCriterion(const std::string& name)
{
  if (name == "rest-pose") return clothtrack::TemplateCriterion::RestPose;
  if (name == "area-ratio") return clothtrack::TemplateCriterion::AreaRatio;
  throw UsageError{"--template-criterion must be rest-pose or area-ratio (got '" + name + "')"};
}
} // namespace clothtrack::app
