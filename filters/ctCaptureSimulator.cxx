#include "ctCaptureSimulator.h"

#include "ctArrayNames.h"
#include "ctCaptureSimulation.h"
#include "ctFirstPieceOnly.h"
#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(ctCaptureSimulator);

int ctCaptureSimulator::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                    vtkInformationVector* outputVector)
{
  if (clothtrack::leaveOtherPieceEmpty(outputVector)) return 1;
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
    if (vtkDataArray* frame = input->GetFieldData()->GetArray(clothtrack::arrays::FrameIndex))
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
