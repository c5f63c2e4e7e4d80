#include "ctSyntheticCapture.h"

#include "ctArrayNames.h"
#include "ctBuiltinBodyModel.h"
#include "ctCaptureSimulation.h"
#include "ctFirstPieceOnly.h"
#include "ctMeshConversion.h"
#include "ctRequestedPortOnly.h"
#include "ctSyntheticSequence.h"

#include <clothtrack/base/Error.h>

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <cmath>

vtkStandardNewMacro(ctSyntheticCapture);

struct ctSyntheticCapture::Internals
{
  // The simulated sequence (ground truth), recomputed only when a parameter of the simulation
  // changes; capture parameters only invalidate the captured frame.
  std::vector<clothtrack::Points> Frames;
  clothtrack::Triangles Faces;
  int GarmentOffset = 0;
  std::string Key;
};

ctSyntheticCapture::ctSyntheticCapture() : Internal(std::make_unique<Internals>())
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
}

ctSyntheticCapture::~ctSyntheticCapture() = default;

vtkPolyData* ctSyntheticCapture::GetCaptureOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

vtkTypeBool ctSyntheticCapture::ProcessRequest(vtkInformation* request,
                                               vtkInformationVector** inputVector,
                                               vtkInformationVector* outputVector)
{
  // Produce only the requested port: a capture is not simulated when only the truth is shown.
  if (clothtrack::handleRequestedPortOnly(request, outputVector)) return 1;
  return this->Superclass::ProcessRequest(request, inputVector, outputVector);
}

int ctSyntheticCapture::RequestInformation(vtkInformation*, vtkInformationVector**,
                                           vtkInformationVector* outputVector)
{
  std::vector<double> times(this->NumberOfFrames);
  for (int k = 0; k < this->NumberOfFrames; ++k) times[k] = k / this->FrameRate;
  const double range[2] = {times.front(), times.back()};
  for (int port = 0; port < 2; ++port)
  {
    vtkInformation* info = outputVector->GetInformationObject(port);
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(),
              static_cast<int>(times.size()));
    info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  }
  return 1;
}

int ctSyntheticCapture::RequestData(vtkInformation* request, vtkInformationVector**,
                                    vtkInformationVector* outputVector)
{
  if (clothtrack::leaveOtherPieceEmpty(outputVector)) return 1;
  using namespace clothtrack;
  auto& in = *this->Internal;
  try
  {
    SyntheticOptions options;
    options.preset = this->Preset;
    options.frames = this->NumberOfFrames;
    options.fps = this->FrameRate;
    options.seed = static_cast<unsigned>(this->Seed);
    options.hemHeight = this->HemHeight;
    const std::string key = options.preset + "/" + std::to_string(options.frames) + "/" +
                            std::to_string(options.fps) + "/" + std::to_string(options.seed) + "/" +
                            std::to_string(options.hemHeight);
    if (key != in.Key)
    {
      in.Frames.clear();
      in.Key.clear();
      generateSyntheticSequence(builtinBodyModel(), options,
                                [&](const SyntheticFrame& frame)
                                {
                                  in.Frames.push_back(frame.clothed.V);
                                  in.Faces = frame.clothed.F;
                                  in.GarmentOffset = frame.garmentOffset;
                                  this->UpdateProgress(0.9 * (frame.index + 1) / options.frames);
                                });
      in.Key = key;
    }

    const int port = clothtrack::requestedPort(request);
    vtkInformation* outInfo = outputVector->GetInformationObject(port);
    int index = 0;
    if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
      index = static_cast<int>(std::floor(
          outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()) * this->FrameRate +
          1e-6));
    index = std::clamp(index, 0, static_cast<int>(in.Frames.size()) - 1);
    const TriangleMesh truth{in.Frames[index], in.Faces};

    vtkPolyData* output = vtkPolyData::GetData(outputVector, port);
    if (port == 0)
    {
      output->ShallowCopy(toPolyData(truth));
      vtkNew<vtkIntArray> garment;
      garment->SetName("IsGarment");
      garment->SetNumberOfTuples(truth.numVertices());
      for (int i = 0; i < truth.numVertices(); ++i)
        garment->SetValue(i, i >= in.GarmentOffset ? 1 : 0);
      output->GetPointData()->AddArray(garment);
    }
    else
    {
      CaptureOptions capture;
      capture.voxelSize = this->VoxelSize;
      capture.holes = this->NumberOfHoles;
      capture.noise = this->NoiseLevel;
      capture.fillEnclosed = this->FillEnclosed;
      capture.seed = static_cast<unsigned>(this->Seed) * 1000003u + static_cast<unsigned>(index);
      SourceMap map;
      output->ShallowCopy(toPolyData(simulateCapture(truth, capture, &map)));
      addSourceMapArrays(map, output);
    }
    vtkNew<vtkIntArray> frameIndex;
    frameIndex->SetName(clothtrack::arrays::FrameIndex);
    frameIndex->InsertNextValue(index);
    output->GetFieldData()->AddArray(frameIndex);
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), index / this->FrameRate);
  }
  catch (const clothtrack::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}

void ctSyntheticCapture::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Preset: " << this->Preset << "\n";
  os << indent << "NumberOfFrames: " << this->NumberOfFrames << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
}
