// clothtrack body-model: write the built-in body model (or a shaped body) to disk.
#include "Commands.h"
#include "Options.h"

#include "ctBodyModelIO.h"
#include "ctBuiltinBodyModel.h"
#include "ctMeshConversion.h"

#include <clothtrack/io/MeshIO.h>

#include <vtkPolyData.h>

#include <cstdio>
#include <sstream>

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
} // namespace

int runBodyModel(const Args& args)
{
  std::string output, meshOutput, beta;
  po::options_description options("body-model options");
  options.add_options()("output,o", po::value(&output),
                        "write the model file (.vtp, see docs/body-model-format.md)")(
      "mesh", po::value(&meshOutput),
      "write the body of shape --beta in rest pose (.obj .off .ply .stl .vtp .vtk)")(
      "beta", po::value(&beta)->default_value(""),
      "shape coefficients in standard deviations, e.g. 1.5,-0.3");
  po::positional_options_description positional;
  po::variables_map values;
  if (!parseOptions(args, "clothtrack body-model [-o MODEL.vtp] [--mesh BODY.obj --beta B0,B1,...]",
                    options, positional, values))
    return 0;
  if (output.empty() && meshOutput.empty())
    throw UsageError{"nothing to do: give -o MODEL.vtp and/or --mesh BODY.obj"};
  const Eigen::VectorXd coefficients = beta.empty() ? Eigen::VectorXd() : parseBeta(beta);
  std::fprintf(stderr, "building the built-in body model...\n");
  const BodyModel& model = builtinBodyModel();
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
