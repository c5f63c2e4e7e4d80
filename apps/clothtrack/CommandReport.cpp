// clothtrack report: plots, renders and report.html for the output folder of 'clothtrack align';
// clothtrack render: the same, plus a movie of the aligned sequence (PNG frames, MP4 with ffmpeg).
// The Python package draws them (matplotlib and VTK); without an X display it starts a virtual
// one of its own (Xvfb).
#include "Commands.h"
#include "Options.h"
#include "Report.h"

#include <cstdio>

namespace clothtrack::app
{
int runReport(const Args& args)
{
  std::string folder;
  po::options_description options("report options");
  options.add_options()("folder", po::value(&folder)->required(),
                        "output folder of 'clothtrack align' (with metrics.json)");
  po::positional_options_description positional;
  positional.add("folder", 1);
  po::variables_map values;
  if (!parseOptions(args, "clothtrack report OUT", options, positional, values)) return 0;
  writeReport(folder);
  return 0;
}

int runRender(const Args& args)
{
  std::string folder, size = "720x720";
  int turntable = -1;
  po::options_description options("render options");
  options.add_options()("folder", po::value(&folder)->required(),
                        "output folder of 'clothtrack align' (with metrics.json)")(
      "turntable", po::value(&turntable)->default_value(-1),
      "a turntable of this frame number instead of the sequence (-1: the sequence)")(
      "size", po::value(&size)->default_value(size), "movie frame size WxH")(
      "movie-only", po::bool_switch(), "skip the report's plots and renders");
  po::positional_options_description positional;
  positional.add("folder", 1);
  po::variables_map values;
  if (!parseOptions(args, "clothtrack render OUT [--turntable FRAME] [--size WxH]", options,
                    positional, values))
    return 0;
  if (!values["movie-only"].as<bool>())
  {
    writeReport(folder);
    std::printf("report: %s/report.html\n", folder.c_str());
  }
  std::vector<std::string> movieOptions = {"--size", size};
  if (turntable >= 0)
    movieOptions.insert(movieOptions.end(), {"--turntable", std::to_string(turntable)});
  writeMovie(folder, movieOptions);
  return 0;
}
} // namespace clothtrack::app
