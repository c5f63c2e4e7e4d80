/**
 * @class ctBodyModelReader
 * @brief Reads a ClothTrack body model file (docs/body-model-format.md) and checks it.
 *
 * The output is the model's mean body in rest pose with all its arrays (SkinWeights,
 * ShapeBasis, joints, landmarks). A file that is not a valid body model is an error naming the
 * file and the problem. To pose a model, give its file to ctBodyModelSource.
 */
#ifndef ctBodyModelReader_h
#define ctBodyModelReader_h

#include "ctReadersModule.h"

#include <vtkPolyDataAlgorithm.h>

#include <string>

class CTREADERS_EXPORT ctBodyModelReader : public vtkPolyDataAlgorithm
{
public:
  static ctBodyModelReader* New();
  vtkTypeMacro(ctBodyModelReader, vtkPolyDataAlgorithm);

  vtkSetStdStringFromCharMacro(FileName);
  vtkGetCharFromStdStringMacro(FileName);

  /// Number of shape components of the model read (after Update()).
  vtkGetMacro(NumberOfShapeComponents, int);

protected:
  ctBodyModelReader();
  ~ctBodyModelReader() override = default;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

  std::string FileName;
  int NumberOfShapeComponents = 0;

private:
  ctBodyModelReader(const ctBodyModelReader&) = delete;
  void operator=(const ctBodyModelReader&) = delete;
};

#endif
