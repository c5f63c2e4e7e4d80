/**
 * @class ctTemplateFit
 * @brief Deforms the template through the whole sequence (Shehu et al. 2016, section 4.3):
 * one connectivity, every frame.
 *
 * Input port 0: the sequence as a vtkMultiBlockDataSet of vtkPolyData frames (frames need not
 * share connectivity). Input port 1: the dense correspondences, output port 0 of
 * ctPatchCorrespondence: one copy of the template per frame with point data Matched and
 * TargetPosition and field data TemplateFrame. The template is the structure of those blocks.
 * Input port 2 (optional): the landmarks of every frame, output port 1 of ctBodyFit; with them
 * each frame's fit starts from its neighbour's moved by the landmarks' locally rigid motion
 * (PredictRadius, see clothtrack/MotionPrediction.h), which follows fast turns better.
 * Input port 3 (optional): the fitted bodies, output port 0 of ctBodyFit; with them (and
 * StartFromBody on) each frame's fit starts from the template posed by the body fitted to that
 * frame (clothtrack/pipeline/BodyStartPrediction.h), which does not drift along the sequence;
 * frames whose body fit is not ok start as without it.
 *
 * Every template vertex gets an affine map, found by minimising
 * wc Ec + ws Es + wd Ed + wt Et (correspondence, smoothness, nearest-point data, temporal) in
 * stages; the defaults are the paper's (wc, ws, wd, wt) = (1, 400, 0, 0.1), (1, 200, 10, 0.1),
 * (0, 100, 10, 0.1), (0, 50, 10, 0.1). Nearest points count when within MaximumNearestDistance
 * and with normals less than MaximumNormalAngle apart. Frames are fitted from the template frame
 * outwards, each started from its neighbour's fit. See clothtrack/TemplateFit.h.
 *
 * Solver 0 (default) solves each round's normal equations to the relative residual
 * SolverTolerance, 1e-4, in a stage's last round and IntermediateTolerance, 1e-4, in the others
 * (block Cholesky factors reused as preconditioners); Solver 1 is the paper's L-BFGS,
 * NearestEvery iterations per round.
 *
 * Output port 0: vtkMultiBlockDataSet, the aligned template for every frame, with point data
 * Displacement (from the template), CorrespondenceUsed (0/1) and SurfaceDistance (to the
 * frame's surface, metres); field data FrameIndex and TemplateFrame.
 * Output port 1: vtkTable, one row per frame: Frame, MeanSurfaceDistance, CorrespondencesUsed,
 * NearestValid, Rounds, Iterations, Energy, Seconds, and the frame's ground-truth-free
 * confidence (clothtrack/eval/FrameConfidence.h): CoverageDistance, Stretch, Folded,
 * BodyDistance (to the template posed by the frame's body from input 3; NaN without a trusted
 * body), ExtentGap (lowest and highest points against that posed template's; NaN likewise),
 * Confidence. A frame whose body is not ok and does not continue its predecessor (ctBodyFit's
 * FitStatus and ContinuesPrevious) had nothing to place its start and is doubtful whatever it
 * measures (confidence 0.5; clothtrack/eval/SequenceQuality.h, doubtUnplacedFrames), and so is a
 * frame whose body another pose explains almost as well (RivalScoreRatio below 1.2; confidence
 * 0.8; doubtAmbiguousBodies). A doubtful frame is also a warning saying why.
 *
 * A corrupt frame, a correspondence block that does not match the template or non-finite
 * input is an error naming the frame; a frame without correspondence is fitted from nearest
 * points alone, with a warning.
 */
#ifndef ctTemplateFit_h
#define ctTemplateFit_h

#include "ctFiltersModule.h"

#include <clothtrack/fit/MotionPrediction.h>
#include <clothtrack/fit/TemplateFit.h>
#include <clothtrack/pipeline/BodyStartPrediction.h>

#include <vtkMultiBlockDataSetAlgorithm.h>

#include <array>
#include <vector>

class vtkTable;

class CTFILTERS_EXPORT ctTemplateFit : public vtkMultiBlockDataSetAlgorithm
{
public:
  static ctTemplateFit* New();
  vtkTypeMacro(ctTemplateFit, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Solvers
  {
    EXACT = 0,
    LBFGS = 1
  };
  virtual void SetSolver(int solver);
  virtual int GetSolver();

  /// Exact solver: the factorisation behind the preconditioner, the block Cholesky (default)
  /// or CHOLMOD's supernodal one (where the build has it; see docs/template-fit.md).
  enum FactorBackends
  {
    BLOCK = 0,
    CHOLMOD = 1
  };
  virtual void SetFactorBackend(int backend);
  virtual int GetFactorBackend();

  /// Stages of weights (wc, ws, wd, wt), applied in order. AddStage appends one;
  /// RemoveAllStages clears them (an update with no stage is an error).
  void AddStage(double correspondence, double smoothness, double nearest, double temporal);
  void RemoveAllStages();
  int GetNumberOfStages() const { return static_cast<int>(this->Options.stages.size()); }
  /// Restores the paper's four stages.
  void SetDefaultStages();

  /// Rounds of (nearest points, minimisation) per stage that uses nearest points.
  virtual void SetRoundsPerStage(int value);
  virtual int GetRoundsPerStage();
  /// Exact solver: relative residual at which each round's solve stops.
  virtual void SetSolverTolerance(double value);
  virtual double GetSolverTolerance();
  virtual void SetIntermediateTolerance(double value);
  virtual double GetIntermediateTolerance();
  /// Exact solver: a stage's factorisation is renewed after a frame whose rounds needed more
  /// conjugate-gradient steps than this on average (0: only when they fail to converge).
  virtual void SetRefactorSteps(double value);
  virtual double GetRefactorSteps();
  /// A template vertex that moved less than this (metres) since its last closest-point search
  /// is projected onto the same triangle: the point found is at most twice this much farther
  /// than the closest. 0 searches every round.
  virtual void SetNearestReuse(double value);
  virtual double GetNearestReuse();
  /// L-BFGS iterations per round (the paper: nearest points every 20 iterations).
  virtual void SetNearestEvery(int value);
  virtual int GetNearestEvery();
  /// Nearest points further than this are not used (metres).
  virtual void SetMaximumNearestDistance(double value);
  virtual double GetMaximumNearestDistance();
  /// Nearest points whose normal is this far or further from the template's are not used.
  virtual void SetMaximumNormalAngle(double value);
  virtual double GetMaximumNormalAngle();
  /// Weight of the frame-to-template term (each frame vertex pulls its nearest template vertex),
  /// as a fraction of each stage's nearest-point weight; 0: template to frame only.
  virtual void SetCoverageWeight(double value);
  virtual double GetCoverageWeight();
  /// Ablations: the correspondence term Ec, the nearest-point term Ed.
  virtual void SetUseCorrespondence(bool value);
  virtual bool GetUseCorrespondence();
  vtkBooleanMacro(UseCorrespondence, bool);
  virtual void SetUseNearest(bool value);
  virtual bool GetUseNearest();
  vtkBooleanMacro(UseNearest, bool);

  /// With landmarks on input port 2: Gaussian width (metres) of the locally rigid motion that
  /// predicts each frame's start; 0 starts from the neighbour's fit as it is.
  virtual void SetPredictRadius(double value);
  virtual double GetPredictRadius();
  /// With landmarks: landmark pairs that the locally rigid motion of their neighbours does not
  /// carry within this distance (metres) are left out of the prediction (random sample
  /// consensus, PCL); 0 keeps every pair.
  virtual void SetLandmarkConsensus(double value);
  virtual double GetLandmarkConsensus();

  /// With bodies on input port 3: each frame starts from the template posed by its body
  /// (default on).
  vtkSetMacro(StartFromBody, bool);
  vtkGetMacro(StartFromBody, bool);
  vtkBooleanMacro(StartFromBody, bool);

  /// With StartFromBody: the posed template is first stretched along Y to the frame's lowest
  /// and highest points (clothtrack::stretchToFrameExtent). Default on.
  vtkSetMacro(StretchStartToFrame, bool);
  vtkGetMacro(StretchStartToFrame, bool);
  vtkBooleanMacro(StretchStartToFrame, bool);

  /// With StartFromBody: correspondences further than this (metres) from the template posed by
  /// the frame's body are dropped (clothtrack::targetsAgreeingWithBodyStart); 0 keeps them all.
  vtkSetClampMacro(CorrespondenceGate, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(CorrespondenceGate, double);

  /// A frame whose fit is clearly doubtful (clothtrack/pipeline/FitJudge.h) is fitted again
  /// from other starts and the most confident fit kept (default on).
  vtkSetMacro(RetryDoubtfulFrames, bool);
  vtkGetMacro(RetryDoubtfulFrames, bool);
  vtkBooleanMacro(RetryDoubtfulFrames, bool);

  /// Threads of this filter's loops (0: the process's count, every core by default).
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);

  vtkTable* GetSummaryOutput();

protected:
  ctTemplateFit();
  ~ctTemplateFit() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

private:
  ctTemplateFit(const ctTemplateFit&) = delete;
  void operator=(const ctTemplateFit&) = delete;

  int NumberOfThreads = 0;
  bool RetryDoubtfulFrames = true;
  bool StartFromBody = true;
  bool StretchStartToFrame = true;
  double CorrespondenceGate = clothtrack::kDefaultCorrespondenceGate;
  clothtrack::TemplateFitOptions Options;
  clothtrack::StartPredictionOptions Prediction;
};

#endif
