#include "ctTemplateSelection.h"

#include "ctArrayNames.h"
#include "ctMeshConversion.h"
#include "ctNamedArrays.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/mesh/MeshValidation.h>
#include <clothtrack/selection/TemplateSelection.h>

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkStringArray.h>
#include <vtkTable.h>

#include <atomic>
#include <cmath>

vtkStandardNewMacro(ctTemplateSelection);

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

int ctTemplateSelection::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                                     vtkInformationVector* outputVector)
{
  using namespace clothtrack;
  auto* sequence = vtkMultiBlockDataSet::GetData(inputVector[0], 0);
  const int n = static_cast<int>(sequence->GetNumberOfBlocks());
  if (n == 0)
  {
    vtkErrorMacro(<< "template selection: the sequence has no frame");
    return 0;
  }
  std::vector<FrameTopology> frames(n);
  std::vector<std::string> errors(n);
  std::atomic<int> done{0};
  // Frames are independent: analyse them in parallel.
  vtkSMPTools::For(0, n,
                   [&](vtkIdType begin, vtkIdType end)
                   {
                     for (vtkIdType k = begin; k < end; ++k)
                     {
                       try
                       {
                         auto* poly = vtkPolyData::SafeDownCast(
                             sequence->GetBlock(static_cast<unsigned>(k)));
                         const std::string name = "frame " + std::to_string(k);
                         if (!poly) throw Error(name + " is not a vtkPolyData");
                         const TriangleMesh mesh = toTriangleMesh(poly, name);
                         validateMesh(mesh, name);
                         frames[k] = frameTopology(mesh, this->MinimumShellArea);
                       }
                       catch (const Error& e)
                       {
                         errors[k] = e.what();
                       }
                       ++done;
                     }
                   });
  for (const auto& e : errors)
    if (!e.empty())
    {
      vtkErrorMacro(<< "template selection: " << e);
      return 0;
    }
  std::vector<double> restPose;
  if (auto* body = vtkMultiBlockDataSet::GetData(inputVector[1], 0))
  {
    if (static_cast<int>(body->GetNumberOfBlocks()) != n)
    {
      vtkErrorMacro(<< "template selection: the body fit has " << body->GetNumberOfBlocks()
                    << " frames, the sequence " << n);
      return 0;
    }
    restPose = blockFieldValues(body, clothtrack::arrays::RestPoseDistance, NAN);
  }
  TemplateSelectionOptions options;
  options.minimumShellArea = this->MinimumShellArea;
  options.persistence = this->Persistence;
  options.criterion = static_cast<TemplateCriterion>(this->Criterion);
  const TemplateSelection selection = selectTemplate(frames, options, restPose);
  if (this->TemplateFrame >= n)
  {
    vtkErrorMacro(<< "template frame " << this->TemplateFrame << " out of range: the sequence has "
                  << n << " frames");
    return 0;
  }
  this->ChosenFrame = this->TemplateFrame >= 0 ? this->TemplateFrame : selection.chosen;

  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->ShallowCopy(sequence->GetBlock(static_cast<unsigned>(this->ChosenFrame)));
  vtkNew<vtkIntArray> chosen;
  chosen->SetName(clothtrack::arrays::TemplateFrame);
  chosen->InsertNextValue(this->ChosenFrame);
  output->GetFieldData()->AddArray(chosen);
  vtkNew<vtkStringArray> decidedBy;
  decidedBy->SetName("TemplateCriterion");
  decidedBy->InsertNextValue(this->TemplateFrame >= 0 ? "given"
                                                      : templateCriterionName(selection.decidedBy));
  output->GetFieldData()->AddArray(decidedBy);

  vtkTable* table = vtkTable::GetData(outputVector, 1);
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
      "Chosen", [&](int k) { return k == this->ChosenFrame ? 1 : 0; },
      vtkNew<vtkIntArray>().GetPointer());
  return 1;
}

void ctTemplateSelection::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MinimumShellArea: " << this->MinimumShellArea << "\n";
  os << indent << "Persistence: " << this->Persistence << "\n";
  os << indent << "Criterion: " << this->Criterion << "\n";
  os << indent << "TemplateFrame: " << this->TemplateFrame << "\n";
}
