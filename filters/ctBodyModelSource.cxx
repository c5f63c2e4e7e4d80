#include "ctBodyModelSource.h"

#include "ctBodyModelIO.h"
#include "ctBuiltinBodyModel.h"
#include "ctFirstPieceOnly.h"
#include "ctLandmarkPolyData.h"
#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/body/OrientedLandmarks.h>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

vtkStandardNewMacro(ctBodyModelSource);

ctBodyModelSource::ctBodyModelSource()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
  this->JointRotations.assign(clothtrack::NumJoints, {0, 0, 0});
}

ctBodyModelSource::~ctBodyModelSource() = default;

void ctBodyModelSource::SetShapeCoefficient(int index, double value)
{
  if (index < 0 || index > 1000)
  {
    vtkErrorMacro(<< "shape coefficient index " << index << " out of range");
    return;
  }
  if (static_cast<int>(this->ShapeCoefficients.size()) <= index)
    this->ShapeCoefficients.resize(index + 1, 0.0);
  if (this->ShapeCoefficients[index] != value)
  {
    this->ShapeCoefficients[index] = value;
    this->Modified();
  }
}

double ctBodyModelSource::GetShapeCoefficient(int index) const
{
  return index >= 0 && index < static_cast<int>(this->ShapeCoefficients.size())
             ? this->ShapeCoefficients[index]
             : 0.0;
}

void ctBodyModelSource::ClearShapeCoefficients()
{
  this->ShapeCoefficients.clear();
  this->Modified();
}

void ctBodyModelSource::SetJointRotation(int joint, double x, double y, double z)
{
  if (joint < 0 || joint >= clothtrack::NumJoints)
  {
    vtkErrorMacro(<< "joint " << joint << " out of range [0, " << clothtrack::NumJoints << ")");
    return;
  }
  this->JointRotations[joint] = {x, y, z};
  this->Modified();
}

void ctBodyModelSource::ClearJointRotations()
{
  this->JointRotations.assign(clothtrack::NumJoints, {0, 0, 0});
  this->Modified();
}

int ctBodyModelSource::GetNumberOfJoints() const
{
  return clothtrack::NumJoints;
}

vtkPolyData* ctBodyModelSource::GetLandmarksOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

int ctBodyModelSource::RequestData(vtkInformation*, vtkInformationVector**,
                                   vtkInformationVector* outputVector)
{
  if (clothtrack::leaveOtherPieceEmpty(outputVector)) return 1;
  using namespace clothtrack;
  try
  {
    BodyModel fromFile;
    if (!this->ModelFileName.empty()) fromFile = readBodyModel(this->ModelFileName);
    const BodyModel& model = this->ModelFileName.empty() ? builtinBodyModel() : fromFile;
    this->NumberOfShapeComponents = model.numShapeComponents();

    Eigen::VectorXd beta = Eigen::Map<const Eigen::VectorXd>(
        this->ShapeCoefficients.data(), static_cast<Eigen::Index>(this->ShapeCoefficients.size()));
    BodyPose pose;
    for (int j = 0; j < NumJoints; ++j)
      pose.rotations.row(j) << this->JointRotations[j][0], this->JointRotations[j][1],
          this->JointRotations[j][2];
    pose.translation = Vec3(this->Translation[0], this->Translation[1], this->Translation[2]);
    Points joints;
    const TriangleMesh posed = model.posed(beta, pose, &joints);

    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    output->ShallowCopy(toPolyData(posed));
    addBodyModelArrays(model, joints, output);

    // Landmarks: position, outward normal, tangent direction towards the direction vertex, ids.
    vtkPolyData* landmarks = vtkPolyData::GetData(outputVector, 1);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    vtkNew<vtkCellArray> verts;
    vtkNew<vtkDoubleArray> direction;
    direction->SetName("Direction");
    direction->SetNumberOfComponents(3);
    vtkNew<vtkDoubleArray> normal;
    normal->SetName("Normal");
    normal->SetNumberOfComponents(3);
    for (const OrientedPoint& p : orientedLandmarks(model, posed))
    {
      verts->InsertNextCell(1);
      verts->InsertCellPoint(points->InsertNextPoint(p.position.data()));
      direction->InsertNextTuple(p.direction.data());
      normal->InsertNextTuple(p.normal.data());
    }
    landmarks->SetPoints(points);
    landmarks->SetVerts(verts);
    addLandmarkIdentity(model, landmarks);
    landmarks->GetPointData()->AddArray(direction);
    landmarks->GetPointData()->AddArray(normal);
    landmarks->GetPointData()->SetActiveVectors("Direction");
  }
  catch (const clothtrack::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}

void ctBodyModelSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ModelFileName: " << this->ModelFileName << "\n";
  os << indent << "ShapeCoefficients: " << this->ShapeCoefficients.size() << "\n";
}
