#include "ctFrameName.h"

#include "ctArrayNames.h"
#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/mesh/MeshValidation.h>

#include <vtkDataObject.h>
#include <vtkFieldData.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

namespace clothtrack
{
std::string frameName(vtkDataObject* block, int index)
{
  std::string name = "frame " + std::to_string(index);
  if (block)
    if (auto* files = vtkStringArray::SafeDownCast(
            block->GetFieldData()->GetAbstractArray(clothtrack::arrays::SourceFile)))
      if (files->GetNumberOfValues() > 0) name += " (" + files->GetValue(0) + ")";
  return name;
}

TriangleMesh frameMesh(vtkMultiBlockDataSet* sequence, int index)
{
  vtkDataObject* block = sequence->GetBlock(static_cast<unsigned>(index));
  const std::string name = frameName(block, index);
  auto* poly = vtkPolyData::SafeDownCast(block);
  if (!poly) throw Error(name + " is not a vtkPolyData");
  TriangleMesh mesh = toTriangleMesh(poly, name);
  validateMesh(mesh, name);
  return mesh;
}

void checkOneBlockPerFrame(vtkMultiBlockDataSet* sequence, vtkMultiBlockDataSet* perFrame,
                           const std::string& filter, const std::string& what)
{
  const unsigned n = sequence ? sequence->GetNumberOfBlocks() : 0u;
  if (n == 0) throw Error(filter + ": the sequence has no frame");
  if (!perFrame || perFrame->GetNumberOfBlocks() != n)
    throw Error(filter + ": the " + what + " input must hold one block per frame (" +
                std::to_string(n) + " frames, " +
                std::to_string(perFrame ? perFrame->GetNumberOfBlocks() : 0u) + " " + what +
                " blocks)");
}
} // namespace clothtrack
