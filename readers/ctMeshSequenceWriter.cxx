#include "ctMeshSequenceWriter.h"

#include "ctArrayNames.h"
#include "ctFirstPieceOnly.h"
#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>

#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

vtkStandardNewMacro(ctMeshSequenceWriter);

ctMeshSequenceWriter::ctMeshSequenceWriter() = default;
ctMeshSequenceWriter::~ctMeshSequenceWriter() = default;

int ctMeshSequenceWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  return 1;
}

vtkTypeBool ctMeshSequenceWriter::ProcessRequest(vtkInformation* request,
                                                 vtkInformationVector** inputVector,
                                                 vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_INFORMATION()))
  {
    this->InputTimes.clear();
    if (inInfo && inInfo->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
    {
      const double* t = inInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
      this->InputTimes.assign(t,
                              t + inInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
    }
    return 1;
  }
  if (request->Has(vtkStreamingDemandDrivenPipeline::REQUEST_UPDATE_EXTENT()))
  {
    clothtrack::requestProcessPiece(inInfo); // the whole sequence arrives on the first process
    if (!this->InputTimes.empty() &&
        this->CurrentTimeIndex < static_cast<int>(this->InputTimes.size()))
      inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(),
                  this->InputTimes[this->CurrentTimeIndex]);
    return 1;
  }
  if (!request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
    return this->Superclass::ProcessRequest(request, inputVector, outputVector);

  if (this->FileName.empty())
  {
    vtkErrorMacro(<< "no output file name set");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return 0;
  }
  if (clothtrack::processIndex() > 0)
  {
    // The first process writes the files; the others' pieces are empty.
    request->Remove(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING());
    this->CurrentTimeIndex = 0;
    this->NumberOfFramesWritten = 0;
    return 1;
  }
  vtkDataObject* input = inInfo->Get(vtkDataObject::DATA_OBJECT());
  if (this->CurrentTimeIndex == 0)
  {
    this->Written.clear();
    this->NumberOfFramesWritten = 0;
    this->SetErrorCode(vtkErrorCode::NoError);
  }

  bool ok = true;
  if (auto* blocks = vtkMultiBlockDataSet::SafeDownCast(input))
  {
    const unsigned int n = blocks->GetNumberOfBlocks();
    for (unsigned int k = 0; k < n && ok; ++k)
    {
      double time = k / this->FrameRate;
      vtkDataObject* block = blocks->GetBlock(k);
      if (auto* poly = vtkPolyData::SafeDownCast(block))
        if (vtkDataArray* t = poly->GetFieldData()->GetArray(clothtrack::arrays::TimeValue))
          time = t->GetTuple1(0);
      ok = this->WriteFrame(block, static_cast<int>(k), time);
      this->UpdateProgress(static_cast<double>(k + 1) / n);
    }
    this->CurrentTimeIndex = 0;
    return this->Finish(ok);
  }

  const bool temporal = !this->InputTimes.empty();
  const double time = temporal ? this->InputTimes[this->CurrentTimeIndex] : 0.0;
  ok = this->WriteFrame(input, this->CurrentTimeIndex, time);
  ++this->CurrentTimeIndex;
  if (ok && temporal && this->CurrentTimeIndex < static_cast<int>(this->InputTimes.size()))
  {
    request->Set(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING(), 1);
    this->UpdateProgress(static_cast<double>(this->CurrentTimeIndex) / this->InputTimes.size());
    return 1;
  }
  request->Remove(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING());
  this->CurrentTimeIndex = 0;
  return this->Finish(ok);
}

int ctMeshSequenceWriter::Finish(bool framesWritten)
{
  if (framesWritten && this->WriteCollection()) return 1;
  // Write() reports success through the error code.
  this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
  return 0;
}

bool ctMeshSequenceWriter::WriteFrame(vtkDataObject* frame, int index, double time)
{
  auto* poly = vtkPolyData::SafeDownCast(frame);
  if (!poly)
  {
    vtkErrorMacro(<< this->FileName << ": frame " << index << " is not a vtkPolyData");
    return false;
  }
  std::string relative;
  try
  {
    relative = clothtrack::writeCollectionFrame(this->FileName, index, poly, this->WriteOBJ);
  }
  catch (const clothtrack::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return false;
  }
  this->Written.emplace_back(time, relative);
  ++this->NumberOfFramesWritten;
  return true;
}

bool ctMeshSequenceWriter::WriteCollection()
{
  try
  {
    clothtrack::writeCollection(this->FileName, this->Written);
  }
  catch (const clothtrack::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return false;
  }
  return true;
}

void ctMeshSequenceWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "WriteOBJ: " << this->WriteOBJ << "\n";
  os << indent << "FrameRate: " << this->FrameRate << "\n";
}
