#include "ctModelChoice.h"

#include "ctNamedArrays.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/eval/ModelChoice.h>

#include <vtkAlgorithm.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkStringArray.h>
#include <vtkTable.h>

#include <string>
#include <vector>

vtkStandardNewMacro(ctModelChoice);

namespace
{
/// Mean over the frames of column `name` of alignment `index`'s per-frame table.
double meanColumn(vtkTable* table, const char* name, int index)
{
  const std::string which = "Model choice: alignment " + std::to_string(index);
  vtkDataArray* column = table ? vtkDataArray::SafeDownCast(table->GetColumnByName(name)) : nullptr;
  if (!column)
    throw clothtrack::Error(which + " has no per-frame column " + name +
                            " (connect output port 1 of ctTemplateFit).");
  std::vector<double> values(column->GetNumberOfTuples());
  for (vtkIdType k = 0; k < column->GetNumberOfTuples(); ++k) values[k] = column->GetTuple1(k);
  try
  {
    return clothtrack::meanOverFrames(values);
  }
  catch (const clothtrack::Error&)
  {
    throw clothtrack::Error(which + " has no frame with a finite " + name + ".");
  }
}
} // namespace

ctModelChoice::ctModelChoice() : Margin(clothtrack::kModelChoiceMargin) {}

int ctModelChoice::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkTable");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

int ctModelChoice::RequestData(vtkInformation*, vtkInformationVector** inputVector,
                               vtkInformationVector* outputVector)
{
  this->KeptAlignment = -1;
  const int count = inputVector[0]->GetNumberOfInformationObjects();
  try
  {
    std::vector<clothtrack::AlignmentFigures> figures;
    for (int i = 0; i < count; ++i)
    {
      vtkTable* table = vtkTable::GetData(inputVector[0], i);
      figures.push_back(
          {meanColumn(table, "Stretch", i), meanColumn(table, "MeanSurfaceDistance", i)});
    }
    this->KeptAlignment = clothtrack::preferredAlignment(figures, this->Margin);
    auto alignment = clothtrack::namedArray<vtkIntArray>("Alignment", count);
    auto stretch = clothtrack::namedArray<vtkDoubleArray>("MeanStretch", count);
    auto distance = clothtrack::namedArray<vtkDoubleArray>("MeanSurfaceDistance", count);
    auto kept = clothtrack::namedArray<vtkIntArray>("Kept", count);
    for (int i = 0; i < count; ++i)
    {
      alignment->SetValue(i, i);
      stretch->SetValue(i, figures[i].stretch);
      distance->SetValue(i, figures[i].surfaceDistance);
      kept->SetValue(i, i == this->KeptAlignment ? 1 : 0);
    }
    vtkTable* output = vtkTable::GetData(outputVector, 0);
    for (vtkAbstractArray* column :
         {static_cast<vtkAbstractArray*>(alignment), static_cast<vtkAbstractArray*>(stretch),
          static_cast<vtkAbstractArray*>(distance), static_cast<vtkAbstractArray*>(kept)})
      output->AddColumn(column);
    clothtrack::addFieldValue(output->GetFieldData(), "KeptAlignment", this->KeptAlignment);
    vtkNew<vtkStringArray> criterion;
    criterion->SetName("Criterion");
    criterion->InsertNextValue(clothtrack::modelChoiceCriterion(this->Margin));
    output->GetFieldData()->AddArray(criterion);
    vtkNew<vtkStringArray> templateCriterion;
    templateCriterion->SetName("TemplateChoiceCriterion");
    templateCriterion->InsertNextValue(clothtrack::templateChoiceCriterion(this->Margin));
    output->GetFieldData()->AddArray(templateCriterion);
  }
  catch (const clothtrack::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}

void ctModelChoice::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Margin: " << this->Margin << "\n";
  os << indent << "KeptAlignment: " << this->KeptAlignment << "\n";
}
