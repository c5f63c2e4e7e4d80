#include "Options.h"

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
                        "length unit of the input files: m, cm or mm")(
      "up", po::value(&target.up)->default_value("y"),
      "up axis of the input files: x, y or z")("fps", po::value(&target.fps)->default_value(25.0),
                                               "frames per second (time of frame k = k / fps)");
}

clothtrack::FrameConventions toConventions(const SequenceOptions& options)
{
  clothtrack::FrameConventions c;
  if (options.unit == "m")
    c.unitScale = 1.0;
  else if (options.unit == "cm")
    c.unitScale = 1e-2;
  else if (options.unit == "mm")
    c.unitScale = 1e-3;
  else
    throw UsageError{"--unit must be m, cm or mm (got '" + options.unit + "')"};
  if (options.up == "x" || options.up == "X")
    c.upAxis = 0;
  else if (options.up == "y" || options.up == "Y")
    c.upAxis = 1;
  else if (options.up == "z" || options.up == "Z")
    c.upAxis = 2;
  else
    throw UsageError{"--up must be x, y or z (got '" + options.up + "')"};
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
