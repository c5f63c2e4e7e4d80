#include "ctSequencePlayer.h"

#include "ctArrayNames.h"
#include "ctFirstPieceOnly.h"

#include <vtkAlgorithmOutput.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(ctSequencePlayer);

namespace
{
// A frame's own time, or NaN.
double blockTime(vtkDataObject* block)
{
  auto* data = vtkPolyData::SafeDownCast(block);
  vtkDataArray* time =
      data ? data->GetFieldData()->GetArray(clothtrack::arrays::TimeValue) : nullptr;
  return time && time->GetNumberOfTuples() > 0 ? time->GetTuple1(0) : std::nan("");
}
} // namespace

void ctSequencePlayer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FrameRate: " << this->FrameRate << "\n";
  os << indent << "Frames: " << this->FrameTimes.size() << "\n";
}

int ctSequencePlayer::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  return 1;
}

int ctSequencePlayer::FrameAtTime(double t) const
{
  if (this->FrameTimes.empty()) return -1;
  const auto after = std::upper_bound(this->FrameTimes.begin(), this->FrameTimes.end(), t + 1e-9);
  return std::max(0, static_cast<int>(after - this->FrameTimes.begin()) - 1);
}

int ctSequencePlayer::RequestInformation(vtkInformation*, vtkInformationVector**,
                                         vtkInformationVector* outputVector)
{
  this->FrameTimes.clear();
  vtkAlgorithmOutput* connection = this->GetInputConnection(0, 0);
  if (!connection) return 0;
  // The time steps are the input's frames, which exist only once it has run. Its time request
  // is dropped in RequestUpdateExtent, so this runs it once, not once per time step.
  vtkAlgorithm* upstream = connection->GetProducer();
  upstream->Update(connection->GetIndex());
  auto* sequence =
      vtkMultiBlockDataSet::SafeDownCast(upstream->GetOutputDataObject(connection->GetIndex()));
  if (!sequence || sequence->GetNumberOfBlocks() == 0)
  {
    vtkErrorMacro(<< "the input has no frames: connect a sequence (one block per frame)");
    return 0;
  }
  const unsigned n = sequence->GetNumberOfBlocks();
  bool ownTimes = true;
  for (unsigned k = 0; k < n; ++k)
  {
    const double t = blockTime(sequence->GetBlock(k));
    ownTimes = ownTimes && std::isfinite(t) && (k == 0 || t > this->FrameTimes.back());
    this->FrameTimes.push_back(t);
  }
  if (!ownTimes)
    for (unsigned k = 0; k < n; ++k) this->FrameTimes[k] = k / this->FrameRate;

  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), this->FrameTimes.data(),
               static_cast<int>(n));
  const double range[2] = {this->FrameTimes.front(), this->FrameTimes.back()};
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

int ctSequencePlayer::RequestUpdateExtent(vtkInformation*, vtkInformationVector** inputVector,
                                          vtkInformationVector*)
{
  // The whole sequence is needed whatever the time: a time request would only make it re-run.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  inInfo->Remove(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
  return 1;
}

int ctSequencePlayer::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                  vtkInformationVector* outputVector)
{
  if (clothtrack::leaveOtherPieceEmpty(outputVector)) return 1;
  auto* sequence = vtkMultiBlockDataSet::GetData(inputVector[0]);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  auto* output = vtkPolyData::GetData(outInfo);
  if (!sequence || sequence->GetNumberOfBlocks() != this->FrameTimes.size())
  {
    vtkErrorMacro(<< "the input sequence changed its number of frames; update the pipeline");
    return 0;
  }
  int index = 0;
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
    index = this->FrameAtTime(outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()));
  auto* frame = vtkPolyData::SafeDownCast(sequence->GetBlock(static_cast<unsigned>(index)));
  if (!frame)
  {
    vtkErrorMacro(<< "frame " << index << " of the input is not a polydata");
    return 0;
  }
  output->ShallowCopy(frame);
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), this->FrameTimes[index]);
  return 1;
}
