/**
 * @class ctLandmarkTransfer
 * @brief Maps oriented anatomical points from the fitted body onto the clothed frame.
 *
 * Input port 0: the frame's surface. Input port 1: the oriented body points, as points with
 * point data Normal (outward) and Direction (tangent), e.g. output port 1 of ctBodyModelSource
 * (LandmarkId and LandmarkName are passed on when present). For each point, the line along its
 * normal is intersected with the frame: the closest crossing outside the body within
 * OutsideTolerance (tau_o, default 0.05 m), else the closest inside within InsideTolerance
 * (tau_i, default 0.2 m), else the point is dropped for this frame (Valid = 0). The direction is
 * projected onto the frame's tangent plane.
 *
 * Output: one point per body point (at the frame point when valid, at the body point when not),
 * with point data Valid, Direction, Offset (signed distance along the normal), FrameFace and
 * FrameBarycentric, and field data FoundFraction.
 */
#ifndef ctLandmarkTransfer_h
#define ctLandmarkTransfer_h

#include "ctFiltersModule.h"

#include <clothtrack/body/LandmarkTransfer.h>

#include <vtkPolyDataAlgorithm.h>

class CTFILTERS_EXPORT ctLandmarkTransfer : public vtkPolyDataAlgorithm
{
public:
  static ctLandmarkTransfer* New();
  vtkTypeMacro(ctLandmarkTransfer, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  virtual void SetOutsideTolerance(double value);
  virtual double GetOutsideTolerance();
  virtual void SetInsideTolerance(double value);
  virtual double GetInsideTolerance();

  /// The oriented body points (input port 1).
  void SetBodyLandmarksConnection(vtkAlgorithmOutput* output)
  {
    this->SetInputConnection(1, output);
  }

protected:
  ctLandmarkTransfer();
  ~ctLandmarkTransfer() override = default;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

private:
  ctLandmarkTransfer(const ctLandmarkTransfer&) = delete;
  void operator=(const ctLandmarkTransfer&) = delete;
  clothtrack::LandmarkTransferOptions Options;
};

#endif
