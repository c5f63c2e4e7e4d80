// clothtrack import-makehuman: convert MakeHuman CC0 assets into a ClothTrack body model file.
#include "Commands.h"
#include "Options.h"

#include "ctBodyModelIO.h"

#include <clothtrack/body/MakeHumanImport.h>

#include <cstdio>

namespace clothtrack::app
{
int runImportMakeHuman(const Args& args)
{
  std::string input, output;
  MakeHumanImportOptions import;
  po::options_description options("import-makehuman options");
  options.add_options()(
      "input", po::value(&input)->required(),
      "MakeHuman asset folder (base.obj, default.mhskel, default_weights.mhw, targets/)")(
      "output,o", po::value(&output)->required(), "body model file to write (.vtp)")(
      "population", po::value(&import.populationSize)->default_value(200),
      "random macro settings for the PCA")("components",
                                           po::value(&import.numComponents)->default_value(16),
                                           "shape components to keep");
  po::positional_options_description positional;
  positional.add("input", 1);
  po::variables_map values;
  if (!parseOptions(args, "clothtrack import-makehuman FOLDER -o MODEL.vtp", options, positional,
                    values))
    return 0;
  if (import.populationSize < 10 || import.numComponents < 1)
    throw UsageError{"--population must be at least 10 and --components at least 1"};
  std::fprintf(stderr, "importing %s...\n", input.c_str());
  const BodyModel model = importMakeHuman(input, import);
  writeBodyModel(output, model);
  std::printf(
      "wrote %s: %d vertices, %d shape components (%.1f %% of the variance), %zu landmarks\n",
      output.c_str(), model.numVertices(), model.numShapeComponents(),
      100 * model.explainedVariance.sum(), model.landmarks.size());
  return 0;
}
} // namespace clothtrack::app
