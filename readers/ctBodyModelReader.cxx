#include "ctBodyModelReader.h"

#include "ctBodyModelIO.h"
#include "ctFirstPieceOnly.h"

#include <clothtrack/base/Error.h>

#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

vtkStandardNewMacro(ctBodyModelReader);

ctBodyModelReader::ctBodyModelReader()
{
  this->SetNumberOfInputPorts(0);
}

int ctBodyModelReader::RequestData(vtkInformation*, vtkInformationVector**,
                                   vtkInformationVector* outputVector)
{
  if (clothtrack::leaveOtherPieceEmpty(outputVector)) return 1;
  try
  {
    // Read through the model type so that every array is checked, then write it back out.
    const clothtrack::BodyModel model = clothtrack::readBodyModel(this->FileName);
    this->NumberOfShapeComponents = model.numShapeComponents();
    vtkPolyData::GetData(outputVector, 0)->ShallowCopy(clothtrack::bodyModelToPolyData(model));
  }
  catch (const clothtrack::Error& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}
