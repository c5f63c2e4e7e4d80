#include "AlignedOutput.h"

#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
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

void addFieldValue(vtkPolyData* mesh, const char* name, double value)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  mesh->GetFieldData()->AddArray(array);
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

std::optional<FrameFit> AlignedOutput::earlier(int frameNumber, Eigen::VectorXd* errors) const
{
  const std::filesystem::path path = framePath(frameNumber);
  if (!std::filesystem::exists(path)) return std::nullopt;
  vtkSmartPointer<vtkPolyData> mesh;
  try
  {
    mesh = readVTPFile(path.string());
  }
  catch (const Error&)
  {
    return std::nullopt; // fitted again
  }
  const int n = template_.numVertices();
  vtkDataArray* used = mesh->GetPointData()->GetArray("CorrespondenceUsed");
  vtkDataArray* distance = mesh->GetPointData()->GetArray("SurfaceDistance");
  auto* recovery =
      vtkStringArray::SafeDownCast(mesh->GetFieldData()->GetAbstractArray("FitRecovery"));
  vtkDataArray* attempts = mesh->GetFieldData()->GetArray("FitAttempts");
  vtkDataArray* doubt = mesh->GetFieldData()->GetArray("FitDoubt");
  if (mesh->GetNumberOfPoints() != n || !used || used->GetNumberOfTuples() != n || !distance ||
      distance->GetNumberOfTuples() != n || !recovery || recovery->GetNumberOfValues() != 1 ||
      !attempts || attempts->GetNumberOfTuples() != 1 || !doubt || doubt->GetNumberOfTuples() != 1)
    return std::nullopt;
  FrameFit fit;
  fit.positions.resize(n, 3);
  fit.used.resize(n);
  fit.surfaceDistance.resize(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    mesh->GetPoint(i, fit.positions.row(i).data());
    fit.used[i] = static_cast<unsigned char>(used->GetComponent(i, 0));
    fit.surfaceDistance[i] = distance->GetComponent(i, 0);
  }
  fit.attempts = static_cast<int>(attempts->GetComponent(0, 0));
  fit.doubt = doubt->GetComponent(0, 0);
  fit.recovery = recovery->GetValue(0);
  if (!fit.positions.allFinite()) return std::nullopt;
  if (errors)
  {
    errors->resize(0);
    vtkDataArray* error = mesh->GetPointData()->GetArray("Error");
    if (error && error->GetNumberOfTuples() == n && error->GetNumberOfComponents() == 1)
    {
      errors->resize(n);
      for (vtkIdType i = 0; i < n; ++i) (*errors)[i] = error->GetComponent(i, 0);
    }
  }
  return fit;
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
  addFieldValue(mesh, "FitAttempts", fit.attempts);
  addFieldValue(mesh, "FitDoubt", fit.doubt);
  vtkNew<vtkStringArray> recovery;
  recovery->SetName("FitRecovery");
  recovery->InsertNextValue(fit.recovery);
  mesh->GetFieldData()->AddArray(recovery);
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
