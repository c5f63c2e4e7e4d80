// clothtrack body-model: write the built-in body model (or a shaped body) to disk.
#include "Commands.h"
#include "Options.h"

#include "ctBodyModelIO.h"
#include "ctBuiltinBodyModel.h"
#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/io/MeshIO.h>

#include <vtkPolyData.h>

#include <cstdio>
#include <optional>
#include <sstream>
#include <vector>

namespace clothtrack::app
{
namespace
{
Eigen::VectorXd parseBeta(const std::string& text)
{
  std::vector<double> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
  {
    try
    {
      size_t used = 0;
      values.push_back(std::stod(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    }
    catch (const std::exception&)
    {
      throw UsageError{"--beta takes comma-separated numbers (got '" + item + "')"};
    }
  }
  return Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
}

/// "neckLength=2.5" items into a BodySpread.
BodySpread parseSpread(const std::vector<std::string>& items)
{
  BodySpread spread;
  for (const std::string& item : items)
  {
    const size_t equals = item.find('=');
    double factor = 0.0;
    try
    {
      size_t used = 0;
      if (equals == std::string::npos) throw std::invalid_argument(item);
      factor = std::stod(item.substr(equals + 1), &used);
      if (used != item.size() - equals - 1) throw std::invalid_argument(item);
    }
    catch (const std::exception&)
    {
      throw UsageError{"--spread takes NAME=FACTOR, e.g. neckLength=2.5 (got '" + item + "')"};
    }
    try
    {
      setBodySpread(spread, item.substr(0, equals), factor);
    }
    catch (const Error& e)
    {
      throw UsageError{std::string("--spread: ") + e.what()};
    }
  }
  return spread;
}
} // namespace

int runBodyModel(const Args& args)
{
  std::string output, meshOutput, beta;
  std::vector<std::string> spreadItems;
  po::options_description options("body-model options");
  options.add_options()("output,o", po::value(&output),
                        "write the model file (.vtp, see docs/body-model-format.md)")(
      "mesh", po::value(&meshOutput),
      "write the body of shape --beta in rest pose (.obj .off .ply .stl .vtp .vtk)")(
      "beta", po::value(&beta)->default_value(""),
      "shape coefficients in standard deviations, e.g. 1.5,-0.3")(
      "spread", po::value(&spreadItems)->composing(),
      "NAME=FACTOR (repeatable): build the model from a population whose proportion NAME "
      "(legLength, armLength, torsoLength, neckLength, shoulderWidth, headSize) varies FACTOR "
      "times as much as the built-in model's");
  po::positional_options_description positional;
  po::variables_map values;
  if (!parseOptions(args,
                    "clothtrack body-model [-o MODEL.vtp] [--mesh BODY.obj --beta B0,B1,...] "
                    "[--spread NAME=FACTOR ...]",
                    options, positional, values))
    return 0;
  if (output.empty() && meshOutput.empty())
    throw UsageError{"nothing to do: give -o MODEL.vtp and/or --mesh BODY.obj"};
  const Eigen::VectorXd coefficients = beta.empty() ? Eigen::VectorXd() : parseBeta(beta);
  const BodySpread spread = parseSpread(spreadItems);
  std::fprintf(stderr, "building the %s body model...\n",
               spreadItems.empty() ? "built-in" : "wider-spread");
  std::optional<BodyModel> wider;
  if (!spreadItems.empty()) wider = proceduralBodyModel(spread);
  const BodyModel& model = wider ? *wider : builtinBodyModel();
  if (!output.empty())
  {
    writeBodyModel(output, model);
    std::printf("wrote %s: %d vertices, %d joints, %d shape components, %zu landmarks\n",
                output.c_str(), model.numVertices(), NumJoints, model.numShapeComponents(),
                model.landmarks.size());
  }
  if (!meshOutput.empty())
  {
    Points v, j;
    model.shape(coefficients, v, j);
    writeMeshFile(meshOutput, toPolyData(TriangleMesh{v, model.mesh.F}));
    std::printf("wrote %s\n", meshOutput.c_str());
  }
  return 0;
}
} // namespace clothtrack::app
