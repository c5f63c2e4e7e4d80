#include "ctBodyFit.h"

#include "ctArrayNames.h"
#include "ctBodyModelIO.h"
#include "ctBuiltinBodyModel.h"
#include "ctFrameName.h"
#include "ctLandmarkPolyData.h"
#include "ctMeshConversion.h"
#include "ctNamedArrays.h"

#include <clothtrack/base/Error.h>
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

vtkStandardNewMacro(ctBodyFit);

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

int ctBodyFit::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                           vtkInformationVector* outputVector)
{
  using namespace clothtrack;
  auto* sequence = vtkMultiBlockDataSet::GetData(inputVector[0], 0);
  const int n = sequence ? static_cast<int>(sequence->GetNumberOfBlocks()) : 0;
  if (n == 0)
  {
    vtkErrorMacro(<< "body fit: the sequence has no frame");
    return 0;
  }
  try
  {
    std::unique_ptr<BodyModel> ownModel;
    if (vtkPolyData* modelData = vtkPolyData::GetData(inputVector[1], 0))
      ownModel = std::make_unique<BodyModel>(bodyModelFromPolyData(modelData, "body model input"));
    const BodyModel& model = ownModel ? *ownModel : builtinBodyModel();

    // Frames that cannot be read as surfaces are flagged, not fatal.
    std::vector<TriangleMesh> meshes(n);
    std::vector<const TriangleMesh*> frames(n, nullptr);
    for (int k = 0; k < n; ++k)
    {
      vtkDataObject* block = sequence->GetBlock(static_cast<unsigned>(k));
      const std::string name = frameName(block, k);
      try
      {
        auto* poly = vtkPolyData::SafeDownCast(block);
        if (!poly) throw Error(name + " is not a vtkPolyData");
        meshes[k] = toTriangleMesh(poly, name);
        validateMesh(meshes[k], name);
        frames[k] = &meshes[k];
      }
      catch (const Error& e)
      {
        vtkWarningMacro(<< "body fit: " << e.what() << "; the frame is flagged failed");
      }
    }

    BodyFitOptions options;
    for (BodyFitStage& stage : options.stages)
    {
      stage.landmarkWeight *= this->LandmarkWeight;
      stage.nearestWeight *= this->NearestWeight;
      stage.insideWeight *= this->InsideWeight;
    }
    options.temporalWeight = this->TemporalWeight;
    options.shapeFrames = this->ShapeFrames;
    options.samples = this->Samples;
    BodyStageOptions stageOptions{options, {}};
    stageOptions.transfer.outsideTolerance = this->OutsideTolerance;
    stageOptions.transfer.insideTolerance = this->InsideTolerance;
    const BodyStageResult stage = fitBodyAndLandmarks(model, frames, stageOptions,
                                                      [this](double progress)
                                                      {
                                                        this->UpdateProgress(0.95 * progress);
                                                        return !this->GetAbortExecute();
                                                      });
    const BodyFitResult& fit = stage.body;

    auto* bodies = vtkMultiBlockDataSet::GetData(outputVector, 0);
    auto* landmarks = vtkMultiBlockDataSet::GetData(outputVector, 1);
    vtkTable* table = vtkTable::GetData(outputVector, 2);
    bodies->SetNumberOfBlocks(n);
    landmarks->SetNumberOfBlocks(n);
    vtkNew<vtkDoubleArray> beta;
    beta->SetName("ShapeCoefficients");
    for (Eigen::Index k = 0; k < fit.beta.size(); ++k) beta->InsertNextValue(fit.beta[k]);
    bodies->GetFieldData()->AddArray(beta);

    vtkNew<vtkIntArray> frameColumn, status, detected, matched;
    frameColumn->SetName("Frame");
    status->SetName("Status");
    detected->SetName("ExtremitiesDetected");
    matched->SetName("ExtremitiesMatched");
    vtkNew<vtkDoubleArray> distance, inside, found, restPose;
    restPose->SetName(clothtrack::arrays::RestPoseDistance);
    distance->SetName("MedianDistance");
    inside->SetName("InsideFraction");
    found->SetName("LandmarksFound");
    for (int k = 0; k < n; ++k)
    {
      const BodyFrameFit& f = fit.frames[k];
      Points joints;
      const TriangleMesh body = model.posed(fit.beta, f.pose, &joints);
      vtkSmartPointer<vtkPolyData> bodyData = toPolyData(body);
      addBodyModelArrays(model, joints, bodyData);
      vtkFieldData* fd = bodyData->GetFieldData();
      addFieldValue(fd, clothtrack::arrays::FrameIndex, k);
      addFieldValue(fd, "FitStatus", static_cast<int>(f.status));
      vtkNew<vtkDoubleArray> pose;
      pose->SetName("Pose");
      for (int j = 0; j < NumJoints; ++j)
        for (int c = 0; c < 3; ++c) pose->InsertNextValue(f.pose.rotations(j, c));
      for (int c = 0; c < 3; ++c) pose->InsertNextValue(f.pose.translation[c]);
      fd->AddArray(pose);
      const double fromRest = fittedRestPoseDistance(f.status, f.pose);
      addFieldValue(fd, clothtrack::arrays::RestPoseDistance, fromRest);
      addFieldValue(fd, "MedianDistance", f.medianDistance);
      addFieldValue(fd, "InsideFraction", f.insideFraction);
      bodies->SetBlock(k, bodyData);
      bodies->GetMetaData(static_cast<unsigned>(k))
          ->Set(vtkCompositeDataSet::NAME(), ("body_" + std::to_string(k)).c_str());

      // Landmarks (none on a frame whose fit failed).
      vtkSmartPointer<vtkPolyData> landmarkData =
          transferredLandmarksToPolyData(stage.bodyLandmarks[k], stage.transferred[k]);
      addLandmarkIdentity(model, landmarkData);
      addFieldValue(landmarkData->GetFieldData(), clothtrack::arrays::RestPoseDistance, fromRest);
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
      frameColumn->InsertNextValue(k);
      status->InsertNextValue(static_cast<int>(f.status));
      detected->InsertNextValue(f.extremitiesDetected);
      matched->InsertNextValue(f.extremitiesMatched);
      distance->InsertNextValue(f.medianDistance);
      inside->InsertNextValue(f.insideFraction);
      found->InsertNextValue(foundFraction);
      restPose->InsertNextValue(fromRest);
      this->UpdateProgress(0.95 + 0.05 * (k + 1) / n);
    }
    for (vtkAbstractArray* column :
         {static_cast<vtkAbstractArray*>(frameColumn), static_cast<vtkAbstractArray*>(status),
          static_cast<vtkAbstractArray*>(distance), static_cast<vtkAbstractArray*>(inside),
          static_cast<vtkAbstractArray*>(detected), static_cast<vtkAbstractArray*>(matched),
          static_cast<vtkAbstractArray*>(found), static_cast<vtkAbstractArray*>(restPose)})
      table->AddColumn(column);
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
  os << indent << "TemporalWeight: " << this->TemporalWeight << "\n";
  os << indent << "ShapeFrames: " << this->ShapeFrames << "\n";
  os << indent << "Samples: " << this->Samples << "\n";
  os << indent << "OutsideTolerance: " << this->OutsideTolerance << "\n";
  os << indent << "InsideTolerance: " << this->InsideTolerance << "\n";
}
