#ifndef ctNamedArrays_h
#define ctNamedArrays_h
// Small builders for the named arrays filters attach to their outputs. C++ only (not wrapped).
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkSmartPointer.h>

#include <vector>

namespace clothtrack
{
/// A new array called `name` with `components` per tuple and room for `tuples` tuples.
template <class ArrayT>
vtkSmartPointer<ArrayT> namedArray(const char* name, vtkIdType tuples = 0, int components = 1)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}

/// Adds a one-value field array `name` to `data` (vtkDoubleArray).
inline void addFieldValue(vtkFieldData* data, const char* name, double value)
{
  auto array = namedArray<vtkDoubleArray>(name, 1);
  array->SetValue(0, value);
  data->AddArray(array);
}

/// Adds a one-value field array `name` to `data` (vtkIntArray).
inline void addFieldValue(vtkFieldData* data, const char* name, int value)
{
  auto array = namedArray<vtkIntArray>(name, 1);
  array->SetValue(0, value);
  data->AddArray(array);
}
/// The first value of field array `name` of `data`; `missing` when there is no such array.
inline double fieldValue(vtkFieldData* data, const char* name, double missing)
{
  vtkDataArray* array = data ? data->GetArray(name) : nullptr;
  return array && array->GetNumberOfTuples() > 0 ? array->GetTuple1(0) : missing;
}

/// fieldValue of every block of `blocks`, in block order (`missing` for an empty block).
inline std::vector<double> blockFieldValues(vtkMultiBlockDataSet* blocks, const char* name,
                                            double missing)
{
  std::vector<double> values;
  for (unsigned k = 0; k < blocks->GetNumberOfBlocks(); ++k)
  {
    vtkDataObject* block = blocks->GetBlock(k);
    values.push_back(fieldValue(block ? block->GetFieldData() : nullptr, name, missing));
  }
  return values;
}
} // namespace clothtrack

#endif
