#include "ctCaptureSimulator.h"

#include "ctCaptureSimulation.h"
#include "ctMeshConversion.h"

#include <clothtrack/Error.h>

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(ctCaptureSimulator);

namespace clothtrack
{
// Attaches a source map to a captured mesh as point data (shared with the app).
void addSourceMapArrays(const SourceMap& map, vtkPolyData* mesh)
{
  const vtkIdType n = static_cast<vtkIdType>(map.face.size());
  vtkNew<vtkIntArray> face;
  face->SetName("SourceFace");
  face->SetNumberOfTuples(n);
  vtkNew<vtkDoubleArray> bary;
  bary->SetName("SourceBarycentric");
  bary->SetNumberOfComponents(3);
  bary->SetNumberOfTuples(n);
  vtkNew<vtkDoubleArray> distance;
  distance->SetName("SourceDistance");
  distance->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    face->SetValue(i, map.face[i]);
    bary->SetTuple(i, map.barycentric[i].data());
    distance->SetValue(i, map.distance[i]);
  }
  mesh->GetPointData()->AddArray(face);
  mesh->GetPointData()->AddArray(bary);
  mesh->GetPointData()->AddArray(distance);
}
} // namespace clothtrack

int ctCaptureSimulator::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                    vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  try
  {
    const clothtrack::TriangleMesh truth =
        clothtrack::toTriangleMesh(input, "capture simulator input");
    clothtrack::CaptureOptions options;
    options.voxelSize = this->VoxelSize;
    options.sheetThickness = this->SheetThickness;
    options.holes = this->NumberOfHoles;
    options.holeRadius = this->HoleRadius;
    options.noise = this->NoiseLevel;
    options.seed = static_cast<unsigned>(this->Seed);
    options.fillEnclosed = this->FillEnclosed;
    if (vtkDataArray* frame = input->GetFieldData()->GetArray("FrameIndex"))
      options.seed += static_cast<unsigned>(frame->GetTuple1(0));
    clothtrack::SourceMap map;
    const clothtrack::TriangleMesh captured = clothtrack::simulateCapture(truth, options, &map);
    output->ShallowCopy(clothtrack::toPolyData(captured));
    clothtrack::addSourceMapArrays(map, output);
    output->GetFieldData()->PassData(input->GetFieldData());
  }
  catch (const clothtrack::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}

void ctCaptureSimulator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "VoxelSize: " << this->VoxelSize << "\n";
  os << indent << "NumberOfHoles: " << this->NumberOfHoles << "\n";
  os << indent << "NoiseLevel: " << this->NoiseLevel << "\n";
}
