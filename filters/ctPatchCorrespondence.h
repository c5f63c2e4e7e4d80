/**
 * @class ctPatchCorrespondence
 * @brief Dense template-to-frame correspondence for a whole sequence by growing near-isometric
 * geodesic patches from oriented landmark pairs.
 *
 * Input port 0: the sequence as a vtkMultiBlockDataSet of vtkPolyData frames (frames need not
 * share connectivity). Input port 1: the oriented landmarks of every frame, a
 * vtkMultiBlockDataSet with one vtkPolyData per frame carrying Valid, LandmarkId, Direction,
 * FrameFace and FrameBarycentric (output port 1 of ctBodyFit).
 *
 * The template is frame TemplateFrame, or when it is -1 the frame ctTemplateSelection's rule
 * chooses (most persistent shells, smallest genus, then the body closest to the rest pose from
 * the landmarks' RestPoseDistance field data, or with TemplateCriterion 0 or without poses the
 * most uniform areas). For each landmark
 * present on the template and on a frame, a patch of the template of intrinsic radius at most
 * MaximumRadius (tau_d) is mapped by equal geodesic polar coordinates around the two landmarks,
 * kept where the map is near-isometric (geodesic distances to the seed and to anchor points
 * differ by at most Epsilon) and grown from the seed through kept vertices; patches smaller
 * than MinimumRadius (tau_s) are dropped. Landmarks further than MaximumSeedOffset from the body
 * (their Offset array) seed no patch, nor do seeds whose geodesic distances to the other seeds
 * within SeedConsensusRadius differ from the template's (by more than SeedConsensusTolerance +
 * SeedConsensusRelativeTolerance times the distance) for more than 1 - MinimumSeedConsensus of
 * them: a landmark misplaced as a whole. See clothtrack/PatchCorrespondence.h for the method
 * and the merge of overlapping patches. Defaults are the paper's (section 4.4).
 *
 * Output port 0: vtkMultiBlockDataSet, one copy of the template per frame with point data
 * Matched (0/1), TargetPosition, TargetFace (-1 unmatched), TargetBarycentric, PatchCount,
 * Spread (RMS distance of the patches' assignments to the result, metres; a confidence) and
 * PatchId (landmark id of the nearest assignment's patch); field data FrameIndex,
 * TemplateFrame and MatchedFraction. The template frame maps to itself.
 * Output port 1: vtkTable, one row per frame: Frame, MatchedFraction, PatchesKept,
 * LandmarkPairs, SeedsOutvoted, Seconds.
 *
 * Frames are processed one after the other, the patches of a frame in parallel; memory besides
 * the output does not grow with the sequence. A frame without landmarks gets no match and a
 * warning; a corrupt frame is an error naming it.
 */
#ifndef ctPatchCorrespondence_h
#define ctPatchCorrespondence_h

#include "ctFiltersModule.h"

#include <clothtrack/correspondence/PatchCorrespondence.h>
#include <clothtrack/selection/TemplateSelection.h>

#include <vtkMultiBlockDataSetAlgorithm.h>

class vtkTable;

class CTFILTERS_EXPORT ctPatchCorrespondence : public vtkMultiBlockDataSetAlgorithm
{
public:
  static ctPatchCorrespondence* New();
  vtkTypeMacro(ctPatchCorrespondence, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Near-isometry tolerance eps (metres).
  virtual void SetEpsilon(double value);
  virtual double GetEpsilon();
  /// tau_s: patches with a smaller radius are discarded (metres).
  virtual void SetMinimumRadius(double value);
  virtual double GetMinimumRadius();
  /// tau_d: intrinsic radius where patch growth stops (metres).
  virtual void SetMaximumRadius(double value);
  virtual double GetMaximumRadius();
  /// Points checked by the near-isometry test besides the seed.
  virtual void SetNumberOfAnchors(int value);
  virtual int GetNumberOfAnchors();
  /// Landmarks further than this from the body (their Offset, metres) seed no patch: loose cloth
  /// slides over the body, so they are not the same cloth point in every frame.
  virtual void SetMaximumSeedOffset(double value);
  virtual double GetMaximumSeedOffset();
  /// Share of the nearby seeds a seed must agree with to grow a patch (0: no vote).
  virtual void SetMinimumSeedConsensus(double value);
  virtual double GetMinimumSeedConsensus();
  /// Seeds within this geodesic distance of a seed on the template vote on it (metres).
  virtual void SetSeedConsensusRadius(double value);
  virtual double GetSeedConsensusRadius();
  /// Two seeds agree when their geodesic distances on the template and on the frame differ by
  /// at most SeedConsensusTolerance (metres) + SeedConsensusRelativeTolerance * distance.
  virtual void SetSeedConsensusTolerance(double value);
  virtual double GetSeedConsensusTolerance();
  virtual void SetSeedConsensusRelativeTolerance(double value);
  virtual double GetSeedConsensusRelativeTolerance();
  /// Automatic choice: components smaller than this (m^2) are not body parts (as in
  /// ctTemplateSelection).
  virtual void SetMinimumShellArea(double value);
  virtual double GetMinimumShellArea();
  /// Automatic choice: a split counts only if it lasts this many consecutive frames.
  virtual void SetPersistence(int value);
  virtual int GetPersistence();
  /// Automatic choice, last criterion: 0 area ratio (the paper's), 1 rest pose (default).
  virtual void SetTemplateCriterion(int criterion);
  virtual int GetTemplateCriterion();
  /// Template frame index; -1 (default) chooses it automatically.
  vtkSetMacro(TemplateFrame, int);
  vtkGetMacro(TemplateFrame, int);
  /// Threads of this filter's loops (0: the process's count, every core by default).
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  /// The template frame used by the last update.
  vtkGetMacro(ChosenFrame, int);

  vtkTable* GetSummaryOutput();

protected:
  ctPatchCorrespondence();
  ~ctPatchCorrespondence() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
                  vtkInformationVector* outputVector) override;

private:
  struct Inputs;
  Inputs ReadInputs(vtkMultiBlockDataSet* sequence, vtkMultiBlockDataSet* landmarkBlocks);
  int ChooseTemplate(const Inputs& in, vtkMultiBlockDataSet* landmarkBlocks);

  ctPatchCorrespondence(const ctPatchCorrespondence&) = delete;
  void operator=(const ctPatchCorrespondence&) = delete;
  int TemplateFrame = -1;
  int NumberOfThreads = 0;
  int ChosenFrame = -1;
  clothtrack::PatchCorrespondenceOptions Patches;
  clothtrack::TemplateSelectionOptions Selection;
};

#endif
