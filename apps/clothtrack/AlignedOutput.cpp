#include "AlignedOutput.h"

#include "ctMeshConversion.h"

#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <cstdio>

namespace clothtrack::app
{
namespace
{
void addArray(vtkPolyData* mesh, const char* name, const Eigen::Ref<const Eigen::MatrixXd>& values)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfComponents(static_cast<int>(values.cols()));
  array->SetNumberOfTuples(values.rows());
  for (Eigen::Index i = 0; i < values.rows(); ++i)
    for (Eigen::Index c = 0; c < values.cols(); ++c) array->SetTypedComponent(i, c, values(i, c));
  mesh->GetPointData()->AddArray(array);
}

std::string frameFileName(int frameNumber)
{
  char name[32];
  std::snprintf(name, sizeof(name), "aligned_%04d.vtp", frameNumber);
  return name;
}
} // namespace

AlignedOutput::AlignedOutput(const std::filesystem::path& outputFolder,
                             const TriangleMesh& templateMesh)
    : folder_(outputFolder), template_(templateMesh)
{
}

std::filesystem::path AlignedOutput::framePath(int frameNumber) const
{
  return folder_ / "aligned" / frameFileName(frameNumber);
}

std::optional<Points> AlignedOutput::earlier(int frameNumber) const
{
  const std::filesystem::path path = framePath(frameNumber);
  if (!std::filesystem::exists(path)) return std::nullopt;
  const TriangleMesh finished = readMeshFile(path.string());
  if (finished.numVertices() != template_.numVertices() || !finished.V.allFinite())
    return std::nullopt;
  return finished.V;
}

void AlignedOutput::write(int frameNumber, const FrameFit& fit, const Eigen::VectorXd& errors) const
{
  const int n = template_.numVertices();
  vtkSmartPointer<vtkPolyData> mesh = toPolyData(TriangleMesh{fit.positions, template_.F});
  addArray(mesh, "Displacement", fit.positions - template_.V);
  addArray(mesh, "SurfaceDistance", fit.surfaceDistance);
  vtkNew<vtkUnsignedCharArray> used;
  used->SetName("CorrespondenceUsed");
  used->SetNumberOfTuples(n);
  for (int i = 0; i < n; ++i) used->SetValue(i, fit.used.empty() ? 0 : fit.used[i]);
  mesh->GetPointData()->AddArray(used);
  if (errors.size() > 0) addArray(mesh, "Error", errors);
  writeCollectionFrame((folder_ / "aligned.pvd").string(), frameNumber, mesh, false);
}

void AlignedOutput::writeCollection(const std::vector<int>& frameNumbers, double fps) const
{
  std::vector<std::pair<double, std::string>> entries;
  for (int number : frameNumbers)
    entries.push_back({number / fps, "aligned/" + frameFileName(number)});
  clothtrack::writeCollection((folder_ / "aligned.pvd").string(), entries);
}
} // namespace clothtrack::app
