// clothtrack report: plots, renders and report.html for the output folder of 'clothtrack align'.
// The Python package draws them (matplotlib and VTK); without an X display it runs under a
// virtual one (xvfb-run).
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
} // namespace clothtrack::app
