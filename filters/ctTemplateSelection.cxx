#include "ctTemplateSelection.h"
#include "ctFirstPieceOnly.h"
#include "ctOptionProperty.h"

#include "ctArrayNames.h"
#include "ctNamedArrays.h"

#include "ctFrameName.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/pipeline/TemplateStage.h>

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

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(ctTemplateSelection);

ctOptionClampDefinition(ctTemplateSelection, MinimumShellArea, double, Options.minimumShellArea,
                        0.0, 100.0);
ctOptionClampDefinition(ctTemplateSelection, Persistence, int, Options.persistence, 1, 10000);

ctOptionEnumDefinition(ctTemplateSelection, TemplateCriterion, clothtrack::TemplateCriterion,
                       Options.templateCriterion, 0, 1);

ctTemplateSelection::ctTemplateSelection()
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

vtkTable* ctTemplateSelection::GetCriteriaOutput()
{
  return vtkTable::SafeDownCast(this->GetOutputDataObject(1));
}

int ctTemplateSelection::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkMultiBlockDataSet");
  if (port == 1) info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int ctTemplateSelection::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkPolyData" : "vtkTable");
  return 1;
}

namespace
{
/// Output port 1: every frame's criteria and the choice.
void addCriteriaRows(vtkTable* table, const clothtrack::TemplateSelection& selection,
                     const std::vector<double>& restPose, int chosenFrame)
{
  const auto& frames = selection.frames;
  const int n = static_cast<int>(frames.size());
  // Where each frame comes in the order the rest-pose criterion would choose them (-1: not a
  // candidate, or the choice was not made by pose).
  std::vector<int> poseOrder(n, -1);
  if (selection.decidedBy == clothtrack::TemplateCriterion::RestPose)
  {
    const std::vector<int> byPose = clothtrack::templateFramesByPose(selection, restPose);
    for (size_t i = 0; i < byPose.size(); ++i) poseOrder[byPose[i]] = static_cast<int>(i);
  }
  auto column = [&](const char* name, auto&& value, auto* array)
  {
    array->SetName(name);
    array->SetNumberOfTuples(n);
    for (int k = 0; k < n; ++k) array->SetValue(k, value(k));
    table->AddColumn(array);
  };
  column(
      "Frame", [](int k) { return k; }, vtkNew<vtkIntArray>().GetPointer());
  column(
      "Components", [&](int k) { return frames[k].components; },
      vtkNew<vtkIntArray>().GetPointer());
  column(
      "Shells", [&](int k) { return frames[k].shells; }, vtkNew<vtkIntArray>().GetPointer());
  column(
      "PersistentShells", [&](int k) { return selection.persistentShells[k]; },
      vtkNew<vtkIntArray>().GetPointer());
  column(
      "Genus", [&](int k) { return frames[k].genus; }, vtkNew<vtkIntArray>().GetPointer());
  column(
      "AreaRatio", [&](int k) { return frames[k].areaRatio; },
      vtkNew<vtkDoubleArray>().GetPointer());
  column(
      "Area", [&](int k) { return frames[k].area; }, vtkNew<vtkDoubleArray>().GetPointer());
  column(
      clothtrack::arrays::RestPoseDistance,
      [&](int k) { return restPose.empty() ? NAN : restPose[k]; },
      vtkNew<vtkDoubleArray>().GetPointer());
  column(
      "Candidate", [&](int k) { return static_cast<int>(selection.candidate[k]); },
      vtkNew<vtkIntArray>().GetPointer());
  column(
      "PoseOrder", [&](int k) { return poseOrder[k]; }, vtkNew<vtkIntArray>().GetPointer());
  column(
      "Chosen", [&](int k) { return k == chosenFrame ? 1 : 0; },
      vtkNew<vtkIntArray>().GetPointer());
}
} // namespace

int ctTemplateSelection::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                     vtkInformationVector* outputVector)
{
  if (clothtrack::leaveOtherPieceEmpty(outputVector)) return 1;
  using namespace clothtrack;
  vtkMultiBlockDataSet* sequence = vtkMultiBlockDataSet::GetData(inputVector[0], 0);
  ThreadBudget threads(this->NumberOfThreads);
  try
  {
    const int n = sequence ? static_cast<int>(sequence->GetNumberOfBlocks()) : 0;
    if (n == 0) throw Error("template selection: the sequence has no frame");
    if (this->TemplateFrame >= n)
      throw Error("template frame " + std::to_string(this->TemplateFrame) +
                  " out of range: the sequence has " + std::to_string(n) + " frames");
    std::vector<TriangleMesh> frames(n);
    std::vector<const TriangleMesh*> pointers(n);
    for (int k = 0; k < n; ++k)
    {
      frames[k] = frameMesh(sequence, k);
      pointers[k] = &frames[k];
    }
    std::vector<double> restPose;
    std::vector<bool> continuesPrevious;
    if (auto* body = vtkMultiBlockDataSet::GetData(inputVector[1], 0))
    {
      checkOneBlockPerFrame(sequence, body, "template selection", "body fit");
      restPose = blockFieldValues(body, clothtrack::arrays::RestPoseDistance, NAN);
      for (double c : blockFieldValues(body, "ContinuesPrevious", 1.0))
        continuesPrevious.push_back(c != 0.0);
    }
    const TemplateSelection selection = chooseTemplateFrame(pointers, this->Options, restPose);
    this->ChosenFrame = this->TemplateFrame >= 0 ? this->TemplateFrame : selection.chosen;

    vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
    output->ShallowCopy(sequence->GetBlock(static_cast<unsigned>(this->ChosenFrame)));
    clothtrack::addFieldValue(output->GetFieldData(), clothtrack::arrays::TemplateFrame,
                              this->ChosenFrame);
    vtkNew<vtkStringArray> decidedBy;
    decidedBy->SetName("TemplateCriterion");
    decidedBy->InsertNextValue(
        this->TemplateFrame >= 0 ? "given" : templateCriterionName(selection.decidedBy));
    output->GetFieldData()->AddArray(decidedBy);
    clothtrack::addFieldValue(output->GetFieldData(), "CollectionOfPoses",
                              static_cast<int>(isCollectionOfPoses(continuesPrevious)));
    clothtrack::addFieldValue(output->GetFieldData(), "DefaultTemplateCandidates",
                              defaultTemplateCandidates(continuesPrevious));
    addCriteriaRows(vtkTable::GetData(outputVector, 1), selection, restPose, this->ChosenFrame);
  }
  catch (const Error& e)
  {
    vtkErrorMacro(<< "template selection: " << e.what());
    return 0;
  }
  return 1;
}

void ctTemplateSelection::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MinimumShellArea: " << this->Options.minimumShellArea << "\n";
  os << indent << "Persistence: " << this->Options.persistence << "\n";
  os << indent << "TemplateCriterion: " << this->GetTemplateCriterion() << "\n";
  os << indent << "TemplateFrame: " << this->TemplateFrame << "\n";
}
