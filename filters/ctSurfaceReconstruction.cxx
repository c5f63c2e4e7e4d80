#include "ctSurfaceReconstruction.h"

#include "ctFirstPieceOnly.h"
#include "ctMeshConversion.h"
#include "ctPointCloudFile.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/reconstruction/SurfaceReconstruction.h>

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

vtkStandardNewMacro(ctSurfaceReconstruction);

namespace
{
template <class ArrayT, class ValueT>
void addField(vtkPolyData* output, const char* name, ValueT value)
{
  vtkNew<ArrayT> array;
  array->SetName(name);
  array->InsertNextValue(value);
  output->GetFieldData()->AddArray(array);
}
} // namespace

int ctSurfaceReconstruction::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                         vtkInformationVector* outputVector)
{
  if (clothtrack::leaveOtherPieceEmpty(outputVector)) return 1;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  try
  {
    clothtrack::ReconstructionOptions options;
    options.cleaning.voxelSize = this->VoxelSize;
    options.cleaning.outlierNeighbours = this->OutlierNeighbours;
    options.cleaning.outlierDeviations = this->OutlierDeviations;
    options.normals.neighbours = this->NormalNeighbours;
    options.poisson.depth = this->PoissonDepth;
    options.cropDistance = this->CropDistance;
    clothtrack::ReconstructionReport report;
    const clothtrack::TriangleMesh mesh = clothtrack::reconstructSurface(
        clothtrack::toPointCloud(input, "surface reconstruction input"),
        "surface reconstruction input", options, &report,
        [this](double share)
        {
          this->UpdateProgress(share);
          return !this->GetAbortExecute();
        });
    output->ShallowCopy(clothtrack::toPolyData(mesh));
    output->GetFieldData()->PassData(input->GetFieldData());
    addField<vtkIntArray>(output, "ReconstructionPieces", report.pieces);
    addField<vtkIntArray>(output, "ReconstructionBoundaryLoops", report.boundaryLoops);
    addField<vtkIntArray>(output, "ReconstructionGenus", report.genus);
    addField<vtkDoubleArray>(output, "ReconstructionUnexplainedShare", report.unexplainedShare);
    addField<vtkDoubleArray>(output, "ReconstructionMeanPointDistance", report.meanPointDistance);
    vtkNew<vtkStringArray> doubts;
    doubts->SetName("ReconstructionDoubts");
    for (const std::string& doubt : report.doubts)
    {
      doubts->InsertNextValue(doubt);
      vtkWarningMacro(<< "doubtful reconstruction: " << doubt);
    }
    output->GetFieldData()->AddArray(doubts);
  }
  catch (const clothtrack::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}

void ctSurfaceReconstruction::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "VoxelSize: " << this->VoxelSize << "\n";
  os << indent << "OutlierNeighbours: " << this->OutlierNeighbours << "\n";
  os << indent << "OutlierDeviations: " << this->OutlierDeviations << "\n";
  os << indent << "NormalNeighbours: " << this->NormalNeighbours << "\n";
  os << indent << "PoissonDepth: " << this->PoissonDepth << "\n";
  os << indent << "CropDistance: " << this->CropDistance << "\n";
}
