#include "ctBodyFit.h"
#include "ctFirstPieceOnly.h"
#include "ctOptionProperty.h"

#include "ctArrayNames.h"
#include "ctBodyModelIO.h"
#include "ctBuiltinBodyModel.h"
#include "ctFrameName.h"
#include "ctLandmarkPolyData.h"
#include "ctMeshConversion.h"
#include "ctNamedArrays.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/body/BodyFit.h>
#include <clothtrack/body/LandmarkTransfer.h>
#include <clothtrack/body/OrientedLandmarks.h>
#include <clothtrack/mesh/MeshValidation.h>
#include <clothtrack/pipeline/BodyStage.h>

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkTable.h>

#include <memory>
#include <utility>

vtkStandardNewMacro(ctBodyFit);

ctOptionClampDefinition(ctBodyFit, TemporalWeight, double, Options.fit.temporalWeight, 0.0, 1000.0);
ctOptionClampDefinition(ctBodyFit, RootTemporalWeight, double, Options.fit.rootTemporalWeight, 0.0,
                        1000.0);
ctOptionClampDefinition(ctBodyFit, LegTemporalWeight, double, Options.fit.legTemporalWeight, 0.0,
                        1000.0);
ctOptionClampDefinition(ctBodyFit, LegRaiseStart, double, Options.fit.legRaiseStart, 0.0, 1.5);
ctOptionClampDefinition(ctBodyFit, ShapeFrames, int, Options.fit.shapeFrames, 1, 1000);
ctOptionClampDefinition(ctBodyFit, Samples, int, Options.fit.samples, 50, 100000);
ctOptionClampDefinition(ctBodyFit, OutsideTolerance, double, Options.transfer.outsideTolerance, 0.0,
                        10.0);
ctOptionClampDefinition(ctBodyFit, InsideTolerance, double, Options.transfer.insideTolerance, 0.0,
                        10.0);
ctOptionDefinition(ctBodyFit, RegisterFrames, bool, Options.registerFrames);
ctOptionDefinition(ctBodyFit, StatureStart, bool, Options.fit.statureStart);
ctOptionDefinition(ctBodyFit, LimbRestarts, bool, Options.fit.limbRestarts);
ctOptionDefinition(ctBodyFit, TwoShapes, bool, Options.fit.twoShapes);
ctOptionClampDefinition(ctBodyFit, SameShapeTolerance, double, Options.fit.sameShapeTolerance, 0.0,
                        1.0);

ctBodyFit::ctBodyFit()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(3);
}

vtkMultiBlockDataSet* ctBodyFit::GetLandmarksOutput()
{
  return vtkMultiBlockDataSet::SafeDownCast(this->GetOutputDataObject(1));
}

vtkTable* ctBodyFit::GetStatusOutput()
{
  return vtkTable::SafeDownCast(this->GetOutputDataObject(2));
}

int ctBodyFit::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  else
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int ctBodyFit::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 2 ? "vtkTable" : "vtkMultiBlockDataSet");
  return 1;
}

namespace
{
/// The frames as surfaces; a frame that cannot be read is left out (nullptr) and its error kept.
std::vector<const clothtrack::TriangleMesh*>
readFrames(vtkMultiBlockDataSet* sequence, std::vector<clothtrack::TriangleMesh>& meshes,
           std::vector<std::string>& errors)
{
  const int n = static_cast<int>(sequence->GetNumberOfBlocks());
  meshes.assign(n, {});
  std::vector<const clothtrack::TriangleMesh*> frames(n, nullptr);
  for (int k = 0; k < n; ++k)
  {
    vtkDataObject* block = sequence->GetBlock(static_cast<unsigned>(k));
    const std::string name = clothtrack::frameName(block, k);
    try
    {
      auto* poly = vtkPolyData::SafeDownCast(block);
      if (!poly) throw clothtrack::Error(name + " is not a vtkPolyData");
      meshes[k] = clothtrack::toTriangleMesh(poly, name);
      clothtrack::validateMesh(meshes[k], name);
      frames[k] = &meshes[k];
    }
    catch (const clothtrack::Error& e)
    {
      errors.push_back(e.what());
    }
  }
  return frames;
}

/// Output port 0 block: the fitted body of one frame with its pose and quality.
vtkSmartPointer<vtkPolyData> fittedBodyPolyData(const clothtrack::BodyModel& model,
                                                const clothtrack::BodyFitResult& fit, int k,
                                                double fromRest)
{
  using namespace clothtrack;
  const BodyFrameFit& f = fit.frames[k];
  Points joints;
  vtkSmartPointer<vtkPolyData> bodyData = toPolyData(model.posed(fit.beta, f.pose, &joints));
  addBodyModelArrays(model, joints, bodyData);
  vtkFieldData* fd = bodyData->GetFieldData();
  clothtrack::addFieldValue(fd, clothtrack::arrays::FrameIndex, k);
  clothtrack::addFieldValue(fd, "FitStatus", static_cast<int>(f.status));
  vtkNew<vtkDoubleArray> pose;
  pose->SetName("Pose");
  for (int j = 0; j < NumJoints; ++j)
    for (int c = 0; c < 3; ++c) pose->InsertNextValue(f.pose.rotations(j, c));
  for (int c = 0; c < 3; ++c) pose->InsertNextValue(f.pose.translation[c]);
  fd->AddArray(pose);
  clothtrack::addFieldValue(fd, clothtrack::arrays::RestPoseDistance, fromRest);
  clothtrack::addFieldValue(fd, "MedianDistance", f.medianDistance);
  clothtrack::addFieldValue(fd, "InsideFraction", f.insideFraction);
  clothtrack::addFieldValue(fd, "FrameDistance", f.frameDistance);
  clothtrack::addFieldValue(fd, "PreviousGap", f.previousGap);
  clothtrack::addFieldValue(fd, "ContinuesPrevious", static_cast<int>(f.continuesPrevious));
  clothtrack::addFieldValue(fd, "RivalScoreRatio", f.rivalScoreRatio);
  return bodyData;
}

/// Output port 2: one row per frame.
struct StatusTable
{
  vtkNew<vtkIntArray> frame, status, detected, matched;
  vtkNew<vtkDoubleArray> distance, inside, found, restPose, frameDistance, previousGap;

  void add(int k, const clothtrack::BodyFrameFit& f, double foundFraction, double fromRest)
  {
    frame->InsertNextValue(k);
    status->InsertNextValue(static_cast<int>(f.status));
    detected->InsertNextValue(f.extremitiesDetected);
    matched->InsertNextValue(f.extremitiesMatched);
    distance->InsertNextValue(f.medianDistance);
    inside->InsertNextValue(f.insideFraction);
    found->InsertNextValue(foundFraction);
    restPose->InsertNextValue(fromRest);
    frameDistance->InsertNextValue(f.frameDistance);
    previousGap->InsertNextValue(f.previousGap);
  }
  void addTo(vtkTable* table)
  {
    frame->SetName("Frame");
    status->SetName("Status");
    detected->SetName("ExtremitiesDetected");
    matched->SetName("ExtremitiesMatched");
    distance->SetName("MedianDistance");
    inside->SetName("InsideFraction");
    found->SetName("LandmarksFound");
    restPose->SetName(clothtrack::arrays::RestPoseDistance);
    frameDistance->SetName("FrameDistance");
    previousGap->SetName("PreviousGap");
    for (vtkAbstractArray* column :
         {static_cast<vtkAbstractArray*>(frame), static_cast<vtkAbstractArray*>(status),
          static_cast<vtkAbstractArray*>(distance), static_cast<vtkAbstractArray*>(inside),
          static_cast<vtkAbstractArray*>(detected), static_cast<vtkAbstractArray*>(matched),
          static_cast<vtkAbstractArray*>(found), static_cast<vtkAbstractArray*>(restPose),
          static_cast<vtkAbstractArray*>(frameDistance),
          static_cast<vtkAbstractArray*>(previousGap)})
      table->AddColumn(column);
  }
};
} // namespace

clothtrack::BodyStageOptions ctBodyFit::StageOptions() const
{
  // The weight properties scale the whole schedule of the core's stages.
  clothtrack::BodyStageOptions options = this->Options;
  for (clothtrack::BodyFitStage& stage : options.fit.stages)
  {
    stage.landmarkWeight *= this->LandmarkWeight;
    stage.nearestWeight *= this->NearestWeight;
    stage.insideWeight *= this->InsideWeight;
  }
  return options;
}

int ctBodyFit::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                           vtkInformationVector* outputVector)
{
  if (clothtrack::leaveOtherPieceEmpty(outputVector)) return 1;
  using namespace clothtrack;
  auto* sequence = vtkMultiBlockDataSet::GetData(inputVector[0], 0);
  const int n = sequence ? static_cast<int>(sequence->GetNumberOfBlocks()) : 0;
  if (n == 0)
  {
    vtkErrorMacro(<< "body fit: the sequence has no frame");
    return 0;
  }
  ThreadBudget threads(this->NumberOfThreads);
  try
  {
    std::unique_ptr<BodyModel> ownModel;
    if (vtkPolyData* modelData = vtkPolyData::GetData(inputVector[1], 0))
      ownModel = std::make_unique<BodyModel>(bodyModelFromPolyData(modelData, "body model input"));
    const BodyModel& model = ownModel ? *ownModel : builtinBodyModel();
    // Frames that cannot be read as surfaces are flagged, not fatal.
    std::vector<TriangleMesh> meshes;
    std::vector<std::string> unreadable;
    const std::vector<const TriangleMesh*> frames = readFrames(sequence, meshes, unreadable);
    for (const std::string& message : unreadable)
      vtkWarningMacro(<< "body fit: " << message << "; the frame is flagged failed");
    const BodyStageResult stage = fitBodyAndLandmarks(model, frames, this->StageOptions(),
                                                      [this](double progress)
                                                      {
                                                        this->UpdateProgress(0.95 * progress);
                                                        return !this->GetAbortExecute();
                                                      });
    const BodyFitResult& fit = stage.body;

    auto* bodies = vtkMultiBlockDataSet::GetData(outputVector, 0);
    auto* landmarks = vtkMultiBlockDataSet::GetData(outputVector, 1);
    bodies->SetNumberOfBlocks(n);
    landmarks->SetNumberOfBlocks(n);
    for (const auto& [name, coefficients] :
         {std::pair{"ShapeCoefficients", &fit.beta}, {"OtherShapeCoefficients", &fit.otherBeta}})
    {
      vtkNew<vtkDoubleArray> beta;
      beta->SetName(name);
      for (double b : *coefficients) beta->InsertNextValue(b);
      bodies->GetFieldData()->AddArray(beta);
    }
    addFieldValue(bodies->GetFieldData(), "MovedShape", static_cast<int>(fit.movedShape));
    addFieldValue(bodies->GetFieldData(), "ShapeGap", fit.shapeGap);
    StatusTable table;
    const std::vector<double> restPoses = restPoseDistances(fit);
    for (int k = 0; k < n; ++k)
    {
      const BodyFrameFit& f = fit.frames[k];
      const double fromRest = restPoses[k];
      bodies->SetBlock(k, fittedBodyPolyData(model, fit, k, fromRest));
      bodies->GetMetaData(static_cast<unsigned>(k))
          ->Set(vtkCompositeDataSet::NAME(), ("body_" + std::to_string(k)).c_str());
      // Landmarks (none on a frame whose fit failed).
      vtkSmartPointer<vtkPolyData> landmarkData =
          transferredLandmarksToPolyData(stage.bodyLandmarks[k], stage.transferred[k]);
      addLandmarkIdentity(model, landmarkData);
      clothtrack::addFieldValue(landmarkData->GetFieldData(), clothtrack::arrays::RestPoseDistance,
                                fromRest);
      landmarks->SetBlock(k, landmarkData);
      const double foundFraction =
          landmarkData->GetFieldData()->GetArray(clothtrack::arrays::LandmarksFound)->GetTuple1(0);
      if (f.status != BodyFitStatus::Ok)
        vtkWarningMacro(<< "body fit: " << frameName(sequence->GetBlock(k), k) << ": "
                        << bodyFitStatusName(f.status) << (f.message.empty() ? "" : ": ")
                        << f.message);
      else if (foundFraction == 0.0)
        vtkWarningMacro(<< "body fit: " << frameName(sequence->GetBlock(k), k)
                        << ": no landmark could be placed");
      table.add(k, f, foundFraction, fromRest);
      this->UpdateProgress(0.95 + 0.05 * (k + 1) / n);
    }
    table.addTo(vtkTable::GetData(outputVector, 2));
  }
  catch (const Error& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}

void ctBodyFit::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LandmarkWeight: " << this->LandmarkWeight << "\n";
  os << indent << "NearestWeight: " << this->NearestWeight << "\n";
  os << indent << "InsideWeight: " << this->InsideWeight << "\n";
  os << indent << "TemporalWeight: " << this->Options.fit.temporalWeight << "\n";
  os << indent << "RootTemporalWeight: " << this->Options.fit.rootTemporalWeight << "\n";
  os << indent << "LegTemporalWeight: " << this->Options.fit.legTemporalWeight << "\n";
  os << indent << "LegRaiseStart: " << this->Options.fit.legRaiseStart << "\n";
  os << indent << "ShapeFrames: " << this->Options.fit.shapeFrames << "\n";
  os << indent << "Samples: " << this->Options.fit.samples << "\n";
  os << indent << "OutsideTolerance: " << this->Options.transfer.outsideTolerance << "\n";
  os << indent << "InsideTolerance: " << this->Options.transfer.insideTolerance << "\n";
  os << indent << "RegisterFrames: " << this->Options.registerFrames << "\n";
  os << indent << "StatureStart: " << this->Options.fit.statureStart << "\n";
  os << indent << "LimbRestarts: " << this->Options.fit.limbRestarts << "\n";
  os << indent << "TwoShapes: " << this->Options.fit.twoShapes << "\n";
  os << indent << "SameShapeTolerance: " << this->Options.fit.sameShapeTolerance << "\n";
}
