#include "ctRequestedPortOnly.h"

#include <vtkDemandDrivenPipeline.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>

#include <algorithm>

namespace clothtrack
{
bool handleRequestedPortOnly(vtkInformation* request, vtkInformationVector* outputVector)
{
  if (!request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_NOT_GENERATED())) return false;
  if (request->Has(vtkDemandDrivenPipeline::FROM_OUTPUT_PORT()))
  {
    const int requested = request->Get(vtkDemandDrivenPipeline::FROM_OUTPUT_PORT());
    if (requested >= 0)
      for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port)
        if (port != requested)
          outputVector->GetInformationObject(port)->Set(
              vtkDemandDrivenPipeline::DATA_NOT_GENERATED(), 1);
  }
  return true;
}

int requestedPort(vtkInformation* request)
{
  return request->Has(vtkDemandDrivenPipeline::FROM_OUTPUT_PORT())
             ? std::max(0, request->Get(vtkDemandDrivenPipeline::FROM_OUTPUT_PORT()))
             : 0;
}
} // namespace clothtrack
