/**
 * @class ctBodyFit
 * @brief Fits the body model under the clothing of a whole sequence and transfers its oriented
 * anatomical landmarks onto every frame.
 *
 * Input port 0: the sequence as a vtkMultiBlockDataSet of vtkPolyData frames (output port 1 of
 * ctMeshSequenceReader); frames need not share connectivity. Input port 1 (optional): a body
 * model (ctBodyModelReader); the built-in model when absent.
 *
 * One shape beta for the sequence and a pose per frame minimise w_l E_l + w_n E_n + w_w E_w
 * (automatically detected extremities, closest points, body inside the clothing) with a
 * temporal term; see clothtrack/body/BodyFit.h for the terms and the weight schedule. The
 * scales below multiply the schedule's weights. The shape is estimated two ways, and the one
 * under which the frames are explained better is kept (TwoShapes, BodyFitOptions::twoShapes).
 *
 * Output port 0: vtkMultiBlockDataSet, one fitted body per frame (the model's connectivity)
 * with field data FrameIndex, FitStatus (0 ok, 1 poor, 2 failed), Pose (22 axis-angle joint
 * rotations then the translation), RestPoseDistance (sum of the non-root joint angles in
 * radians, NaN unless the fit is ok), MedianDistance, InsideFraction, FrameDistance (mean
 * distance from the frame to the body, m), PreviousGap (mean surface distance to the frame
 * before, m), ContinuesPrevious (0 when PreviousGap is above 6 cm and the frame was fitted as
 * an unrelated pose, else 1) and RivalScoreRatio (how nearly another pose explains the frame;
 * infinity where not measured; ctTemplateFit doubts a frame below 1.2); the collection's field
 * data holds ShapeCoefficients (beta, the shape kept), MovedShape (1 when that is the one
 * estimated with the key frames' translations moving), OtherShapeCoefficients (the estimate
 * not kept; empty with TwoShapes off) and ShapeGap (the largest distance between the two
 * shapes' rest-pose vertices, m; below SameShapeTolerance pass 2 ran under the first only;
 * -1 with TwoShapes off).
 * Output port 1: vtkMultiBlockDataSet, the oriented landmarks of each frame (as
 * ctLandmarkTransfer: Valid, Direction, LandmarkId, LandmarkName, Offset, FrameFace,
 * FrameBarycentric; field data FoundFraction and RestPoseDistance, which lets
 * ctPatchCorrespondence choose the template by pose).
 * Output port 2: vtkTable, one row per frame: Frame, Status, MedianDistance, InsideFraction,
 * ExtremitiesDetected, ExtremitiesMatched, LandmarksFound, RestPoseDistance, FrameDistance,
 * PreviousGap.
 *
 * A frame that cannot be fitted (empty or corrupt) is flagged Failed with a warning and keeps
 * its neighbour's pose; the filter fails only when no frame can be fitted.
 */
#ifndef ctBodyFit_h
#define ctBodyFit_h

#include "ctFiltersModule.h"

#include <clothtrack/pipeline/BodyStage.h>

#include <vtkMultiBlockDataSetAlgorithm.h>

class vtkTable;

class CTFILTERS_EXPORT ctBodyFit : public vtkMultiBlockDataSetAlgorithm
{
public:
  static ctBodyFit* New();
  vtkTypeMacro(ctBodyFit, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Scale of the landmark term w_l over the whole schedule.
  vtkSetClampMacro(LandmarkWeight, double, 0.0, 1000.0);
  vtkGetMacro(LandmarkWeight, double);
  /// Scale of the closest-point term w_n.
  vtkSetClampMacro(NearestWeight, double, 0.0, 1000.0);
  vtkGetMacro(NearestWeight, double);
  /// Scale of the inside term w_w.
  vtkSetClampMacro(InsideWeight, double, 0.0, 1000.0);
  vtkGetMacro(InsideWeight, double);
  /// Weight of joint rotation changes between consecutive frames.
  virtual void SetTemporalWeight(double value);
  virtual double GetTemporalWeight();
  /// The same for the root's rotation (lighter: a turning body is not held back).
  virtual void SetRootTemporalWeight(double value);
  virtual double GetRootTemporalWeight();
  /// The same for the hips' and knees' rotations (lighter: a knee raised fast is not held back).
  virtual void SetLegTemporalWeight(double value);
  virtual double GetLegTemporalWeight();
  /// Hip flexion (radians) of the raised-leg starts of the final pass; 0: none.
  virtual void SetLegRaiseStart(double value);
  virtual double GetLegRaiseStart();
  /// Start the shape's estimation at the stature the key frames suggest (their height over
  /// that of the body fitted with the mean shape) rather than at the mean body.
  virtual void SetStatureStart(bool value);
  virtual bool GetStatureStart();
  vtkBooleanMacro(StatureStart, bool);
  /// Start frames unrelated to their predecessor again with their limbs at rest, aimed at the
  /// extremities their fit leaves unpaired, and swapped in pairs, and, on a collection, those
  /// explained worst also turned half round (on by default).
  virtual void SetLimbRestarts(bool value);
  virtual bool GetLimbRestarts();
  vtkBooleanMacro(LimbRestarts, bool);
  /// Estimate the shape two ways and keep the one under which the frames are explained better
  /// (on by default); off: the key frames' poses fixed only, and pass 2 runs once.
  virtual void SetTwoShapes(bool value);
  virtual bool GetTwoShapes();
  vtkBooleanMacro(TwoShapes, bool);
  /// Two shapes whose rest-pose bodies lie this close at every vertex (metres) are one body:
  /// pass 2 runs under the first only (0.01 by default; 0: always under both).
  virtual void SetSameShapeTolerance(double value);
  virtual double GetSameShapeTolerance();
  /// Key frames used to estimate the shape.
  virtual void SetShapeFrames(int value);
  virtual int GetShapeFrames();
  /// Body vertices used by the dense terms.
  virtual void SetSamples(int value);
  virtual int GetSamples();
  /// Landmark transfer: tau_o (metres).
  virtual void SetOutsideTolerance(double value);
  virtual double GetOutsideTolerance();
  /// Landmark transfer: tau_i (metres).
  virtual void SetInsideTolerance(double value);
  virtual double GetInsideTolerance();
  /// Start each frame from its predecessor's pose moved by the rigid motion between the two
  /// surfaces (generalized ICP, PCL). Off by default (it did not pay on the sequences measured).
  virtual void SetRegisterFrames(bool value);
  virtual bool GetRegisterFrames();
  vtkBooleanMacro(RegisterFrames, bool);

  /// Threads of this filter's loops (0: the process's count, every core by default).
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);

  /// The body model (output of ctBodyModelReader) on input port 1.
  void SetBodyModelConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  vtkMultiBlockDataSet* GetLandmarksOutput();
  vtkTable* GetStatusOutput();

protected:
  ctBodyFit();
  ~ctBodyFit() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

  double LandmarkWeight = 1.0;
  double NearestWeight = 1.0;
  double InsideWeight = 1.0;
  int NumberOfThreads = 0;

private:
  /// The core options with the weight multipliers applied.
  clothtrack::BodyStageOptions StageOptions() const;

  ctBodyFit(const ctBodyFit&) = delete;
  void operator=(const ctBodyFit&) = delete;
  clothtrack::BodyStageOptions Options;
};

#endif
