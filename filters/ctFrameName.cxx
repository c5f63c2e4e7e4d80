#include "ctFrameName.h"

#include <vtkDataObject.h>
#include <vtkFieldData.h>
#include <vtkStringArray.h>

namespace clothtrack
{
std::string frameName(vtkDataObject* block, int index)
{
  std::string name = "frame " + std::to_string(index);
  if (block)
    if (auto* files =
            vtkStringArray::SafeDownCast(block->GetFieldData()->GetAbstractArray("SourceFile")))
      if (files->GetNumberOfValues() > 0) name += " (" + files->GetValue(0) + ")";
  return name;
}
} // namespace clothtrack
