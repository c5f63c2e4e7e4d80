/**
 * @class ctCaptureSimulator
 * @brief Turns a frame of a consistent-connectivity sequence into what a multi-view capture
 * delivers: an independently re-meshed surface where close parts merge.
 *
 * The inside of the input is voxelised (closed parts filled by winding number along vertical
 * lines, open sheets such as garments thickened to SheetThickness), smoothed and re-extracted
 * with flying edges; NumberOfHoles random holes and normal noise (NoiseLevel) are optional.
 * Output point data: SourceFace, SourceBarycentric and SourceDistance, the closest point of the
 * input surface for every output vertex (the ground truth of the capture). The random seed of a
 * frame is Seed plus its FrameIndex field (when present), so that frames differ and runs repeat.
 */
#ifndef ctCaptureSimulator_h
#define ctCaptureSimulator_h

#include "ctFiltersModule.h"

#include <vtkPolyDataAlgorithm.h>

class CTFILTERS_EXPORT ctCaptureSimulator : public vtkPolyDataAlgorithm
{
public:
  static ctCaptureSimulator* New();
  vtkTypeMacro(ctCaptureSimulator, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetClampMacro(VoxelSize, double, 0.001, 1.0);
  vtkGetMacro(VoxelSize, double);
  vtkSetClampMacro(SheetThickness, double, 0.0, 1.0);
  vtkGetMacro(SheetThickness, double);
  vtkSetClampMacro(NumberOfHoles, int, 0, 1000);
  vtkGetMacro(NumberOfHoles, int);
  vtkSetClampMacro(HoleRadius, double, 0.0, 1.0);
  vtkGetMacro(HoleRadius, double);
  vtkSetClampMacro(NoiseLevel, double, 0.0, 1.0);
  vtkGetMacro(NoiseLevel, double);
  /// Fill regions that cameras around the person cannot see into (inside a dress, a gap closed
  /// by an arm against the torso), as a visual hull does. On by default.
  vtkSetMacro(FillEnclosed, bool);
  vtkGetMacro(FillEnclosed, bool);
  vtkBooleanMacro(FillEnclosed, bool);
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);

protected:
  ctCaptureSimulator() = default;
  ~ctCaptureSimulator() override = default;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

  double VoxelSize = 0.015;
  double SheetThickness = 0.012;
  int NumberOfHoles = 0;
  double HoleRadius = 0.03;
  double NoiseLevel = 0.0;
  int Seed = 1;
  bool FillEnclosed = true;

private:
  ctCaptureSimulator(const ctCaptureSimulator&) = delete;
  void operator=(const ctCaptureSimulator&) = delete;
};

#endif
