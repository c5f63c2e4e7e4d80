#include "ctGuardedPolyDataReader.h"

#include <vtkAbstractArray.h>
#include <vtkObjectFactory.h>
#include <vtkSmartPointer.h>
#include <vtkXMLDataElement.h>

vtkStandardNewMacro(ctGuardedPolyDataReader);

int ctGuardedPolyDataReader::ReadPieceData()
{
  const int piece = this->Piece;
  struct Cells
  {
    vtkXMLDataElement* element;
    vtkIdType count;
    const char* kind;
  };
  const Cells cells[] = {{this->VertElements[piece], this->NumberOfVerts[piece], "Verts"},
                         {this->LineElements[piece], this->NumberOfLines[piece], "Lines"},
                         {this->StripElements[piece], this->NumberOfStrips[piece], "Strips"},
                         {this->PolyElements[piece], this->NumberOfPolys[piece], "Polys"}};
  for (const Cells& c : cells)
    if (c.element && c.count > 0 && !this->connectivityHoldsOffsets(c.element, c.count, c.kind))
    {
      this->DataError = 1;
      return 0;
    }
  return this->Superclass::ReadPieceData();
}

bool ctGuardedPolyDataReader::connectivityHoldsOffsets(vtkXMLDataElement* cells, vtkIdType count,
                                                       const char* kind)
{
  vtkXMLDataElement* offsets = this->FindDataArrayWithName(cells, "offsets");
  vtkXMLDataElement* connectivity = this->FindDataArrayWithName(cells, "connectivity");
  if (!offsets || !connectivity) return true;
  // One value of each array, read where the reader would read it.
  auto oneValue = [&](vtkXMLDataElement* element, vtkIdType index, double& value)
  {
    vtkSmartPointer<vtkAbstractArray> array;
    array.TakeReference(this->CreateArray(element));
    if (!array || array->GetNumberOfComponents() != 1 || !array->IsA("vtkDataArray")) return false;
    array->SetNumberOfTuples(1);
    if (!this->ReadArrayValues(element, 0, array, index, 1, CELL_DATA)) return false;
    value = array->GetVariantValue(0).ToDouble();
    return true;
  };
  double last = 0;
  if (!oneValue(offsets, count - 1, last) || !(last > 0)) return true; // the reader says why
  double probe = 0;
  if (last > 1e15 || !oneValue(connectivity, static_cast<vtkIdType>(last) - 1, probe))
  {
    vtkErrorMacro(<< kind << ": the offsets ask for " << static_cast<long long>(last)
                  << " connectivity values, more than the connectivity array holds (corrupt "
                     "file)");
    return false;
  }
  return true;
}
