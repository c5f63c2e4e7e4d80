#include "ctMeshSequenceReader.h"

#include "ctArrayNames.h"
#include "ctFirstPieceOnly.h"
#include "ctMeshConversion.h"
#include "ctPointCloudFile.h"
#include "ctRequestedPortOnly.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/io/FrameList.h>
#include <clothtrack/io/PointCloudIO.h>

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkStringArray.h>

#include <cmath>
#include <filesystem>
#include <vector>

vtkStandardNewMacro(ctMeshSequenceReader);

struct ctMeshSequenceReader::Internals
{
  std::vector<std::string> Frames;
  std::string ListError;
  vtkTimeStamp ListTime;
  // The whole sequence is kept once read, until a parameter changes.
  vtkSmartPointer<vtkMultiBlockDataSet> Sequence;
  vtkTimeStamp SequenceTime;
};

ctMeshSequenceReader::ctMeshSequenceReader() : Internal(std::make_unique<Internals>())
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
}

ctMeshSequenceReader::~ctMeshSequenceReader() = default;

int ctMeshSequenceReader::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkPolyData" : "vtkMultiBlockDataSet");
  return 1;
}

vtkTypeBool ctMeshSequenceReader::ProcessRequest(vtkInformation* request,
                                                 vtkInformationVector** inputVector,
                                                 vtkInformationVector* outputVector)
{
  // Only the requested port is produced, so that playing frames never loads the whole
  // sequence; the other port is left as it is and stays out of date.
  if (clothtrack::handleRequestedPortOnly(request, outputVector)) return 1;
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

int ctMeshSequenceReader::RequestInformation(vtkInformation*, vtkInformationVector**,
                                             vtkInformationVector* outputVector)
{
  auto& in = *this->Internal;
  in.Frames.clear();
  in.ListError.clear();
  try
  {
    in.Frames = clothtrack::listFrames(this->FileName);
  }
  catch (const clothtrack::Error& e)
  {
    in.ListError = e.what();
    vtkErrorMacro(<< e.what());
    return 0;
  }
  in.ListTime.Modified();

  std::vector<double> times(in.Frames.size());
  for (size_t k = 0; k < times.size(); ++k) times[k] = static_cast<double>(k) / this->FrameRate;
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(),
               static_cast<int>(times.size()));
  const double range[2] = {times.front(), times.back()};
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

int ctMeshSequenceReader::GetNumberOfFrames()
{
  if (this->Internal->ListTime < this->GetMTime()) this->UpdateInformation();
  return static_cast<int>(this->Internal->Frames.size());
}

std::string ctMeshSequenceReader::GetFrameFileName(int index)
{
  if (index < 0 || index >= this->GetNumberOfFrames()) return {};
  return this->Internal->Frames[index];
}

bool ctMeshSequenceReader::ReadFrameInto(int index, vtkPolyData* output)
{
  const std::string& path = this->Internal->Frames[index];
  try
  {
    clothtrack::FrameConventions conventions;
    conventions.unitScale = this->LengthUnit == MILLIMETRES   ? 1e-3
                            : this->LengthUnit == CENTIMETRES ? 1e-2
                                                              : 1.0;
    conventions.upAxis = this->UpAxis;
    if (clothtrack::isPointCloudFile(path))
    {
      clothtrack::PointCloud cloud = clothtrack::loadPointCloud(path, conventions);
      if (const int dropped = clothtrack::dropInvalidPoints(cloud, path, 1))
        vtkWarningMacro(<< path << ": " << dropped << " points with NaN coordinates left out");
      output->ShallowCopy(clothtrack::toPolyData(cloud));
    }
    else
    {
      std::vector<std::string> warnings;
      const clothtrack::TriangleMesh mesh = clothtrack::loadFrame(path, conventions, &warnings);
      for (const auto& warning : warnings) vtkWarningMacro(<< warning);
      output->ShallowCopy(clothtrack::toPolyData(mesh));
    }
  }
  catch (const clothtrack::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return false;
  }

  vtkNew<vtkStringArray> source;
  source->SetName(clothtrack::arrays::SourceFile);
  source->InsertNextValue(path);
  vtkNew<vtkIntArray> frameIndex;
  frameIndex->SetName(clothtrack::arrays::FrameIndex);
  frameIndex->InsertNextValue(index);
  vtkNew<vtkIntArray> frameNumber;
  frameNumber->SetName(clothtrack::arrays::FrameNumber);
  frameNumber->InsertNextValue(static_cast<int>(clothtrack::frameNumberFromName(path)));
  vtkNew<vtkDoubleArray> time;
  time->SetName(clothtrack::arrays::TimeValue);
  time->InsertNextValue(index / this->FrameRate);
  output->GetFieldData()->AddArray(source);
  output->GetFieldData()->AddArray(frameIndex);
  output->GetFieldData()->AddArray(frameNumber);
  output->GetFieldData()->AddArray(time);
  return true;
}

vtkPolyData* ctMeshSequenceReader::ReadFrame(int index)
{
  if (index < 0 || index >= this->GetNumberOfFrames())
  {
    vtkErrorMacro(<< "frame " << index << " out of range: " << this->FileName << " has "
                  << this->Internal->Frames.size() << " frames");
    return nullptr;
  }
  vtkPolyData* frame = vtkPolyData::New();
  if (!this->ReadFrameInto(index, frame))
  {
    frame->Delete();
    return nullptr;
  }
  return frame;
}

int ctMeshSequenceReader::RequestData(vtkInformation* request, vtkInformationVector**,
                                      vtkInformationVector* outputVector)
{
  if (clothtrack::leaveOtherPieceEmpty(outputVector)) return 1;
  auto& in = *this->Internal;
  if (in.Frames.empty())
  {
    vtkErrorMacro(<< (in.ListError.empty() ? this->FileName + ": no frame" : in.ListError));
    return 0;
  }
  const int port = clothtrack::requestedPort(request);
  if (port == 1)
  {
    auto* output = vtkMultiBlockDataSet::GetData(outputVector, 1);
    if (!in.Sequence || in.SequenceTime < this->GetMTime())
    {
      auto sequence = vtkSmartPointer<vtkMultiBlockDataSet>::New();
      sequence->SetNumberOfBlocks(static_cast<unsigned int>(in.Frames.size()));
      for (size_t k = 0; k < in.Frames.size(); ++k)
      {
        if (this->GetAbortExecute()) return 0;
        vtkNew<vtkPolyData> frame;
        if (!this->ReadFrameInto(static_cast<int>(k), frame)) return 0;
        sequence->SetBlock(static_cast<unsigned int>(k), frame);
        sequence->GetMetaData(static_cast<unsigned int>(k))
            ->Set(vtkCompositeDataSet::NAME(),
                  std::filesystem::path(in.Frames[k]).stem().string().c_str());
        this->UpdateProgress(static_cast<double>(k + 1) / in.Frames.size());
      }
      in.Sequence = sequence;
      in.SequenceTime.Modified();
    }
    output->ShallowCopy(in.Sequence);
    return 1;
  }

  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int index = 0;
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    // The frame shown at time t is the last one starting at or before t.
    const double t = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    index = static_cast<int>(std::floor(t * this->FrameRate + 1e-6));
    index = std::max(0, std::min(index, static_cast<int>(in.Frames.size()) - 1));
  }
  auto* output = vtkPolyData::GetData(outputVector, 0);
  if (!this->ReadFrameInto(index, output)) return 0;
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), index / this->FrameRate);
  return 1;
}

vtkMultiBlockDataSet* ctMeshSequenceReader::GetSequenceOutput()
{
  return vtkMultiBlockDataSet::SafeDownCast(this->GetOutputDataObject(1));
}

int ctMeshSequenceReader::CanReadFile(const char* name)
{
  if (!name) return 0;
  try
  {
    return clothtrack::listFrames(name).empty() ? 0 : 1;
  }
  catch (const clothtrack::Error&)
  {
    return 0;
  }
}

void ctMeshSequenceReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
  os << indent << "FrameRate: " << this->FrameRate << "\n";
  os << indent << "LengthUnit: " << this->LengthUnit << "\n";
  os << indent << "UpAxis: " << this->UpAxis << "\n";
  os << indent << "NumberOfFrames: " << this->Internal->Frames.size() << "\n";
}
