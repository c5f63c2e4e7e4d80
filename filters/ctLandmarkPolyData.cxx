#include "ctLandmarkPolyData.h"

#include "ctArrayNames.h"

#include <clothtrack/base/Error.h>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>

namespace clothtrack
{
vtkSmartPointer<vtkPolyData>
transferredLandmarksToPolyData(const std::vector<OrientedPoint>& bodyPoints,
                               const std::vector<TransferredLandmark>& transferred)
{
  vtkNew<vtkPoints> positions;
  positions->SetDataTypeToDouble();
  vtkNew<vtkCellArray> verts;
  vtkNew<vtkIntArray> valid, face;
  valid->SetName(clothtrack::arrays::LandmarkValid);
  face->SetName(clothtrack::arrays::LandmarkFace);
  vtkNew<vtkDoubleArray> direction, bary, offset;
  direction->SetName(clothtrack::arrays::LandmarkDirection);
  direction->SetNumberOfComponents(3);
  bary->SetName(clothtrack::arrays::LandmarkBarycentric);
  bary->SetNumberOfComponents(3);
  offset->SetName(clothtrack::arrays::LandmarkOffset);
  int found = 0;
  for (size_t k = 0; k < transferred.size(); ++k)
  {
    const TransferredLandmark& t = transferred[k];
    found += t.valid;
    const Vec3 p = t.valid ? t.point.position : bodyPoints[k].position;
    verts->InsertNextCell(1);
    verts->InsertCellPoint(positions->InsertNextPoint(p.data()));
    valid->InsertNextValue(t.valid ? 1 : 0);
    face->InsertNextValue(t.valid ? t.point.face : -1);
    const Vec3 d = t.valid ? t.direction : bodyPoints[k].direction;
    direction->InsertNextTuple(d.data());
    bary->InsertNextTuple(t.point.bary.data());
    offset->InsertNextValue(t.offset);
  }
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->SetPoints(positions);
  output->SetVerts(verts);
  output->GetPointData()->AddArray(valid);
  output->GetPointData()->AddArray(direction);
  output->GetPointData()->SetActiveVectors(clothtrack::arrays::LandmarkDirection);
  output->GetPointData()->AddArray(offset);
  output->GetPointData()->AddArray(face);
  output->GetPointData()->AddArray(bary);
  vtkNew<vtkDoubleArray> fraction;
  fraction->SetName(clothtrack::arrays::LandmarksFound);
  fraction->InsertNextValue(transferred.empty() ? 0.0
                                                : static_cast<double>(found) / transferred.size());
  output->GetFieldData()->AddArray(fraction);
  return output;
}

void addLandmarkIdentity(const BodyModel& model, vtkPolyData* landmarks)
{
  vtkNew<vtkIntArray> ids, vertexIds;
  ids->SetName(clothtrack::arrays::LandmarkId);
  vertexIds->SetName(clothtrack::arrays::LandmarkVertex);
  vtkNew<vtkStringArray> names;
  names->SetName(clothtrack::arrays::LandmarkName);
  for (size_t k = 0; k < model.landmarks.size(); ++k)
  {
    ids->InsertNextValue(static_cast<int>(k));
    vertexIds->InsertNextValue(model.landmarks[k].vertex);
    names->InsertNextValue(model.landmarks[k].name);
  }
  landmarks->GetPointData()->AddArray(ids);
  landmarks->GetPointData()->AddArray(vertexIds);
  landmarks->GetPointData()->AddArray(names);
}

std::vector<OrientedSurfacePoint> landmarkSurfacePoints(vtkPolyData* landmarks, int numFaces,
                                                        const std::string& name)
{
  std::vector<OrientedSurfacePoint> out;
  if (!landmarks || landmarks->GetNumberOfPoints() == 0) return out;
  vtkPointData* pd = landmarks->GetPointData();
  vtkDataArray* valid = pd->GetArray(clothtrack::arrays::LandmarkValid);
  vtkDataArray* face = pd->GetArray(clothtrack::arrays::LandmarkFace);
  vtkDataArray* bary = pd->GetArray(clothtrack::arrays::LandmarkBarycentric);
  vtkDataArray* direction = pd->GetArray(clothtrack::arrays::LandmarkDirection);
  vtkDataArray* ids = pd->GetArray(clothtrack::arrays::LandmarkId);
  vtkDataArray* offset = pd->GetArray(clothtrack::arrays::LandmarkOffset);
  if (!valid || !face || !bary || !direction || bary->GetNumberOfComponents() != 3 ||
      direction->GetNumberOfComponents() != 3)
    throw Error(name + ": landmarks need point arrays Valid, FrameFace, FrameBarycentric (3) and "
                       "Direction (3), as ctBodyFit and ctLandmarkTransfer write them");
  for (vtkIdType i = 0; i < landmarks->GetNumberOfPoints(); ++i)
  {
    if (valid->GetTuple1(i) == 0) continue;
    OrientedSurfacePoint p;
    p.id = ids ? static_cast<int>(ids->GetTuple1(i)) : static_cast<int>(i);
    p.face = static_cast<int>(face->GetTuple1(i));
    p.offset = offset ? offset->GetTuple1(i) : 0.0;
    if (p.face < 0 || p.face >= numFaces)
      throw Error(name + ": landmark " + std::to_string(p.id) + " lies on face " +
                  std::to_string(p.face) + ", but the frame has " + std::to_string(numFaces) +
                  " faces (landmarks of another frame?)");
    double t[3];
    bary->GetTuple(i, t);
    p.bary = Vec3(t[0], t[1], t[2]);
    direction->GetTuple(i, t);
    p.direction = Vec3(t[0], t[1], t[2]);
    if (!p.bary.allFinite() || !p.direction.allFinite())
      throw Error(name + ": landmark " + std::to_string(p.id) + " has non-finite values");
    out.push_back(p);
  }
  return out;
}
} // namespace clothtrack
