#include "ctLandmarkTransfer.h"
#include "ctFirstPieceOnly.h"
#include "ctOptionProperty.h"

#include "ctArrayNames.h"
#include "ctLandmarkPolyData.h"
#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/body/LandmarkTransfer.h>
#include <clothtrack/mesh/MeshValidation.h>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(ctLandmarkTransfer);

ctOptionClampDefinition(ctLandmarkTransfer, OutsideTolerance, double, Options.outsideTolerance, 0.0,
                        10.0);
ctOptionClampDefinition(ctLandmarkTransfer, InsideTolerance, double, Options.insideTolerance, 0.0,
                        10.0);

ctLandmarkTransfer::ctLandmarkTransfer()
{
  this->SetNumberOfInputPorts(2);
}

int ctLandmarkTransfer::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                    vtkInformationVector* outputVector)
{
  if (clothtrack::leaveOtherPieceEmpty(outputVector)) return 1;
  using namespace clothtrack;
  vtkPolyData* frameData = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* body = vtkPolyData::GetData(inputVector[1], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!body)
  {
    vtkErrorMacro(<< "landmark transfer: no body landmarks on input port 1");
    return 0;
  }
  try
  {
    const TriangleMesh frame = toTriangleMesh(frameData, "landmark transfer frame");
    validateMesh(frame, "landmark transfer frame");
    vtkDataArray* normals = body->GetPointData()->GetArray("Normal");
    vtkDataArray* directions =
        body->GetPointData()->GetArray(clothtrack::arrays::LandmarkDirection);
    if (!normals || !directions || normals->GetNumberOfComponents() != 3 ||
        directions->GetNumberOfComponents() != 3)
      throw Error(
          "landmark transfer: the body points need 3-component Normal and Direction arrays");
    const vtkIdType n = body->GetNumberOfPoints();
    if (n == 0)
      throw Error(
          "landmark transfer: no body landmark (a frame with no landmarks cannot be aligned)");
    std::vector<OrientedPoint> points(n);
    for (vtkIdType k = 0; k < n; ++k)
      points[k] = {Vec3(body->GetPoint(k)), Vec3(normals->GetTuple3(k)),
                   Vec3(directions->GetTuple3(k))};
    const SurfaceLocator locator(frame);
    const std::vector<TransferredLandmark> result =
        transferLandmarks(points, frame, locator, this->Options);

    output->ShallowCopy(transferredLandmarksToPolyData(points, result));
    for (const char* name : {clothtrack::arrays::LandmarkId, clothtrack::arrays::LandmarkName,
                             clothtrack::arrays::LandmarkVertex})
      if (vtkAbstractArray* a = body->GetPointData()->GetAbstractArray(name))
        output->GetPointData()->AddArray(a);
    const double found =
        output->GetFieldData()->GetArray(clothtrack::arrays::LandmarksFound)->GetTuple1(0);
    if (found == 0)
      vtkWarningMacro(<< "landmark transfer: no landmark could be placed on this frame");
  }
  catch (const Error& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}

void ctLandmarkTransfer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "OutsideTolerance: " << this->Options.outsideTolerance << "\n";
  os << indent << "InsideTolerance: " << this->Options.insideTolerance << "\n";
}
