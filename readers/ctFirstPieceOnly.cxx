#include "ctFirstPieceOnly.h"

#include <vtkDataObject.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkStreamingDemandDrivenPipeline.h>

namespace clothtrack
{
bool leaveOtherPieceEmpty(vtkInformationVector* outputVector)
{
  using Pipeline = vtkStreamingDemandDrivenPipeline;
  bool other = false;
  for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port)
  {
    vtkInformation* info = outputVector->GetInformationObject(port);
    if (info->Has(Pipeline::UPDATE_PIECE_NUMBER()) &&
        info->Get(Pipeline::UPDATE_PIECE_NUMBER()) > 0)
      other = true;
  }
  if (!other) return false;
  for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port)
    if (vtkDataObject* output =
            outputVector->GetInformationObject(port)->Get(vtkDataObject::DATA_OBJECT()))
      output->Initialize();
  return true;
}

int processIndex()
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  return controller ? controller->GetLocalProcessId() : 0;
}

void requestProcessPiece(vtkInformation* inputInformation)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (!controller || controller->GetNumberOfProcesses() < 2 || !inputInformation) return;
  using Pipeline = vtkStreamingDemandDrivenPipeline;
  inputInformation->Set(Pipeline::UPDATE_PIECE_NUMBER(), controller->GetLocalProcessId());
  inputInformation->Set(Pipeline::UPDATE_NUMBER_OF_PIECES(), controller->GetNumberOfProcesses());
}
} // namespace clothtrack
