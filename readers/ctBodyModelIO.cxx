#include "ctBodyModelIO.h"

#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <filesystem>

namespace clothtrack
{
namespace
{
constexpr const char* kFormatName = "ClothTrackBodyModel";
constexpr int kFormatVersion = 1;

vtkSmartPointer<vtkDoubleArray> doubleArray(const char* name, int components, vtkIdType tuples)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  return a;
}

vtkDataArray* requireArray(vtkFieldData* fd, const char* array, int components, vtkIdType tuples,
                           const std::string& name)
{
  vtkDataArray* a = fd ? fd->GetArray(array) : nullptr;
  if (!a) throw Error(name + ": not a ClothTrack body model (array " + array + " missing)");
  if ((components > 0 && a->GetNumberOfComponents() != components) ||
      (tuples >= 0 && a->GetNumberOfTuples() != tuples))
    throw Error(name + ": array " + array + " has " + std::to_string(a->GetNumberOfTuples()) +
                " x " + std::to_string(a->GetNumberOfComponents()) + " values, expected " +
                std::to_string(tuples) + " x " + std::to_string(components));
  return a;
}
} // namespace

void addBodyModelArrays(const BodyModel& model, const Points& joints, vtkPolyData* mesh)
{
  const int n = model.numVertices();
  auto weights = doubleArray("SkinWeights", NumJoints, n);
  vtkNew<vtkIntArray> part;
  part->SetName("BodyPart");
  part->SetNumberOfTuples(n);
  for (int i = 0; i < n; ++i)
  {
    int best;
    model.weights.row(i).maxCoeff(&best);
    part->SetValue(i, best);
    for (int j = 0; j < NumJoints; ++j) weights->SetTypedComponent(i, j, model.weights(i, j));
  }
  mesh->GetPointData()->AddArray(weights);
  mesh->GetPointData()->AddArray(part);
  vtkNew<vtkStringArray> names;
  names->SetName("JointNames");
  for (const char* name : jointNames()) names->InsertNextValue(name);
  mesh->GetFieldData()->AddArray(names);
  auto positions = doubleArray("JointPositions", 3, NumJoints);
  for (int j = 0; j < NumJoints; ++j) positions->SetTuple(j, joints.row(j).data());
  mesh->GetFieldData()->AddArray(positions);
}

vtkSmartPointer<vtkPolyData> bodyModelToPolyData(const BodyModel& model)
{
  vtkSmartPointer<vtkPolyData> out = toPolyData(model.mesh);
  addBodyModelArrays(model, model.joints, out);
  const int n = model.numVertices(), K = model.numShapeComponents();
  auto basis = doubleArray("ShapeBasis", 3 * K, n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < K; ++k)
      for (int c = 0; c < 3; ++c)
        basis->SetTypedComponent(i, 3 * k + c, model.vertexBasis(3 * i + c, k));
  out->GetPointData()->AddArray(basis);

  vtkFieldData* fd = out->GetFieldData();
  vtkNew<vtkStringArray> format;
  format->SetName("FormatName");
  format->InsertNextValue(kFormatName);
  fd->AddArray(format);
  vtkNew<vtkIntArray> version;
  version->SetName("FormatVersion");
  version->InsertNextValue(kFormatVersion);
  fd->AddArray(version);
  vtkNew<vtkIntArray> parents;
  parents->SetName("JointParents");
  for (int p : jointParents()) parents->InsertNextValue(p);
  fd->AddArray(parents);
  auto jointBasis = doubleArray("JointShapeBasis", 3 * K, NumJoints);
  for (int j = 0; j < NumJoints; ++j)
    for (int k = 0; k < K; ++k)
      for (int c = 0; c < 3; ++c)
        jointBasis->SetTypedComponent(j, 3 * k + c, model.jointBasis(3 * j + c, k));
  fd->AddArray(jointBasis);
  auto variance = doubleArray("ExplainedVariance", 1, K);
  for (int k = 0; k < K; ++k)
    variance->SetValue(k, model.explainedVariance.size() > k ? model.explainedVariance[k] : 0.0);
  fd->AddArray(variance);
  vtkNew<vtkStringArray> landmarkNames;
  landmarkNames->SetName("LandmarkNames");
  vtkNew<vtkIntArray> landmarkVertices;
  landmarkVertices->SetName("LandmarkVertices");
  landmarkVertices->SetNumberOfComponents(2);
  for (const auto& l : model.landmarks)
  {
    landmarkNames->InsertNextValue(l.name);
    const int ids[2] = {l.vertex, l.directionVertex};
    landmarkVertices->InsertNextTypedTuple(ids);
  }
  fd->AddArray(landmarkNames);
  fd->AddArray(landmarkVertices);
  return out;
}

BodyModel bodyModelFromPolyData(vtkPolyData* data, const std::string& name)
{
  BodyModel model;
  model.mesh = toTriangleMesh(data, name);
  const int n = model.numVertices();
  vtkFieldData* fd = data->GetFieldData();
  auto* format = vtkStringArray::SafeDownCast(fd->GetAbstractArray("FormatName"));
  if (!format || format->GetNumberOfValues() != 1 || format->GetValue(0) != kFormatName)
    throw Error(name + ": not a ClothTrack body model (no FormatName " + kFormatName + ")");
  auto* names = vtkStringArray::SafeDownCast(fd->GetAbstractArray("JointNames"));
  if (!names || names->GetNumberOfValues() != NumJoints)
    throw Error(name + ": the skeleton must have the " + std::to_string(NumJoints) +
                " ClothTrack joints");
  for (int j = 0; j < NumJoints; ++j)
    if (names->GetValue(j) != jointNames()[j])
      throw Error(name + ": joint " + std::to_string(j) + " is '" + names->GetValue(j) +
                  "', expected '" + jointNames()[j] + "'");
  vtkDataArray* weights = requireArray(data->GetPointData(), "SkinWeights", NumJoints, n, name);
  vtkDataArray* basis = requireArray(data->GetPointData(), "ShapeBasis", -1, n, name);
  if (basis->GetNumberOfComponents() % 3 != 0)
    throw Error(name + ": ShapeBasis must have 3 components per shape component");
  const int K = basis->GetNumberOfComponents() / 3;
  vtkDataArray* joints = requireArray(fd, "JointPositions", 3, NumJoints, name);
  vtkDataArray* jointBasis = requireArray(fd, "JointShapeBasis", 3 * K, NumJoints, name);
  vtkDataArray* variance = requireArray(fd, "ExplainedVariance", 1, K, name);
  vtkDataArray* landmarkVertices = requireArray(fd, "LandmarkVertices", 2, -1, name);
  auto* landmarkNames = vtkStringArray::SafeDownCast(fd->GetAbstractArray("LandmarkNames"));
  if (!landmarkNames || landmarkNames->GetNumberOfValues() != landmarkVertices->GetNumberOfTuples())
    throw Error(name + ": LandmarkNames and LandmarkVertices disagree");

  model.weights.resize(n, NumJoints);
  model.vertexBasis.resize(3 * n, K);
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < NumJoints; ++j) model.weights(i, j) = weights->GetComponent(i, j);
    const double sum = model.weights.row(i).sum();
    if (!(std::abs(sum - 1.0) < 1e-3))
      throw Error(name + ": skinning weights of vertex " + std::to_string(i) + " sum to " +
                  std::to_string(sum));
    for (int k = 0; k < K; ++k)
      for (int c = 0; c < 3; ++c)
        model.vertexBasis(3 * i + c, k) = basis->GetComponent(i, 3 * k + c);
  }
  model.joints.resize(NumJoints, 3);
  model.jointBasis.resize(3 * NumJoints, K);
  for (int j = 0; j < NumJoints; ++j)
  {
    for (int c = 0; c < 3; ++c) model.joints(j, c) = joints->GetComponent(j, c);
    for (int k = 0; k < K; ++k)
      for (int c = 0; c < 3; ++c)
        model.jointBasis(3 * j + c, k) = jointBasis->GetComponent(j, 3 * k + c);
  }
  model.explainedVariance.resize(K);
  for (int k = 0; k < K; ++k) model.explainedVariance[k] = variance->GetComponent(k, 0);
  for (vtkIdType l = 0; l < landmarkVertices->GetNumberOfTuples(); ++l)
  {
    OrientedLandmark landmark{landmarkNames->GetValue(l),
                              static_cast<int>(landmarkVertices->GetComponent(l, 0)),
                              static_cast<int>(landmarkVertices->GetComponent(l, 1))};
    if (landmark.vertex < 0 || landmark.vertex >= n || landmark.directionVertex < 0 ||
        landmark.directionVertex >= n)
      throw Error(name + ": landmark " + landmark.name + " refers to a vertex out of range");
    model.landmarks.push_back(landmark);
  }
  return model;
}

void writeBodyModel(const std::string& path, const BodyModel& model)
{
  if (std::filesystem::path(path).extension() != ".vtp")
    throw Error(path + ": body models are written as .vtp");
  writeMeshFile(path, bodyModelToPolyData(model));
}

BodyModel readBodyModel(const std::string& path)
{
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw Error(path + ": no such body model file");
  vtkSmartPointer<vtkPolyData> data;
  try
  {
    data = readVTPFile(path);
  }
  catch (const Error& e)
  {
    throw Error(std::string(e.what()) + " (a body model is a VTP file)");
  }
  if (data->GetNumberOfPoints() == 0)
    throw Error(path + ": cannot read body model (no point in the file)");
  return bodyModelFromPolyData(data, path);
}
} // namespace clothtrack
