/**
 * @class ctSyntheticCapture
 * @brief A synthetic clothed capture with ground truth, as a temporal source.
 *
 * The built-in body model performs a motion wearing a simulated garment (Preset: dress-walk,
 * skirt-turn, trousers-squat, shirt-armraise, dress-samba). Output port 0 is the ground truth
 * (body and garment, same connectivity in every frame; point data IsGarment); output port 1 is
 * what a multi-view capture delivers for the same frame (see ctCaptureSimulator), with the
 * source map to the ground truth. Frame k is at time k / FrameRate. The cloth simulation runs
 * once for the whole sequence and is cached, so scrubbing time does not recompute it.
 */
#ifndef ctSyntheticCapture_h
#define ctSyntheticCapture_h

#include "ctFiltersModule.h"

#include <vtkPolyDataAlgorithm.h>

#include <memory>
#include <string>

class CTFILTERS_EXPORT ctSyntheticCapture : public vtkPolyDataAlgorithm
{
public:
  static ctSyntheticCapture* New();
  vtkTypeMacro(ctSyntheticCapture, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetStdStringFromCharMacro(Preset);
  vtkGetCharFromStdStringMacro(Preset);
  vtkSetClampMacro(NumberOfFrames, int, 1, 100000);
  vtkGetMacro(NumberOfFrames, int);
  vtkSetClampMacro(FrameRate, double, 1e-3, 1e4);
  vtkGetMacro(FrameRate, double);
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  /// Hem height / stature for dresses and skirts; 0 keeps the preset's.
  vtkSetClampMacro(HemHeight, double, 0.0, 1.0);
  vtkGetMacro(HemHeight, double);
  vtkSetClampMacro(VoxelSize, double, 0.002, 0.2);
  vtkGetMacro(VoxelSize, double);
  vtkSetClampMacro(NumberOfHoles, int, 0, 1000);
  vtkGetMacro(NumberOfHoles, int);
  vtkSetClampMacro(NoiseLevel, double, 0.0, 0.1);
  vtkGetMacro(NoiseLevel, double);
  vtkSetMacro(FillEnclosed, bool);
  vtkGetMacro(FillEnclosed, bool);
  vtkBooleanMacro(FillEnclosed, bool);

  vtkPolyData* GetCaptureOutput();

protected:
  ctSyntheticCapture();
  ~ctSyntheticCapture() override;

  vtkTypeBool ProcessRequest(vtkInformation* request, vtkInformationVector** inputVector,
                             vtkInformationVector* outputVector) override;
  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
                         vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

  std::string Preset = "dress-walk";
  int NumberOfFrames = 40;
  double FrameRate = 25.0;
  int Seed = 7;
  double HemHeight = 0.0;
  double VoxelSize = 0.015;
  int NumberOfHoles = 0;
  double NoiseLevel = 0.0;
  bool FillEnclosed = true;

private:
  ctSyntheticCapture(const ctSyntheticCapture&) = delete;
  void operator=(const ctSyntheticCapture&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
