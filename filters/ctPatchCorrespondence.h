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

#include <vtkMultiBlockDataSetAlgorithm.h>

class vtkTable;

class CTFILTERS_EXPORT ctPatchCorrespondence : public vtkMultiBlockDataSetAlgorithm
{
public:
  static ctPatchCorrespondence* New();
  vtkTypeMacro(ctPatchCorrespondence, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Near-isometry tolerance eps (metres).
  vtkSetClampMacro(Epsilon, double, 1e-4, 10.0);
  vtkGetMacro(Epsilon, double);
  /// tau_s: patches with a smaller radius are discarded (metres).
  vtkSetClampMacro(MinimumRadius, double, 0.0, 10.0);
  vtkGetMacro(MinimumRadius, double);
  /// tau_d: intrinsic radius where patch growth stops (metres).
  vtkSetClampMacro(MaximumRadius, double, 1e-3, 10.0);
  vtkGetMacro(MaximumRadius, double);
  /// Points checked by the near-isometry test besides the seed.
  vtkSetClampMacro(NumberOfAnchors, int, 0, 64);
  vtkGetMacro(NumberOfAnchors, int);
  /// Landmarks further than this from the body (their Offset, metres) seed no patch: loose cloth
  /// slides over the body, so they are not the same cloth point in every frame.
  vtkSetClampMacro(MaximumSeedOffset, double, 0.0, 100.0);
  vtkGetMacro(MaximumSeedOffset, double);
  /// Share of the nearby seeds a seed must agree with to grow a patch (0: no vote).
  vtkSetClampMacro(MinimumSeedConsensus, double, 0.0, 1.0);
  vtkGetMacro(MinimumSeedConsensus, double);
  /// Seeds within this geodesic distance of a seed on the template vote on it (metres).
  vtkSetClampMacro(SeedConsensusRadius, double, 0.01, 100.0);
  vtkGetMacro(SeedConsensusRadius, double);
  /// Two seeds agree when their geodesic distances on the template and on the frame differ by
  /// at most SeedConsensusTolerance (metres) + SeedConsensusRelativeTolerance * distance.
  vtkSetClampMacro(SeedConsensusTolerance, double, 0.0, 10.0);
  vtkGetMacro(SeedConsensusTolerance, double);
  vtkSetClampMacro(SeedConsensusRelativeTolerance, double, 0.0, 10.0);
  vtkGetMacro(SeedConsensusRelativeTolerance, double);
  /// Automatic choice: components smaller than this (m^2) are not body parts (as in
  /// ctTemplateSelection).
  vtkSetClampMacro(MinimumShellArea, double, 0.0, 2.0);
  vtkGetMacro(MinimumShellArea, double);
  /// Automatic choice: a split counts only if it lasts this many consecutive frames.
  vtkSetClampMacro(Persistence, int, 1, 50);
  vtkGetMacro(Persistence, int);
  /// Automatic choice, last criterion: 0 area ratio (the paper's), 1 rest pose (default).
  vtkSetClampMacro(TemplateCriterion, int, 0, 1);
  vtkGetMacro(TemplateCriterion, int);
  /// Template frame index; -1 (default) chooses it automatically.
  vtkSetMacro(TemplateFrame, int);
  vtkGetMacro(TemplateFrame, int);
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
  ctPatchCorrespondence(const ctPatchCorrespondence&) = delete;
  void operator=(const ctPatchCorrespondence&) = delete;

  double Epsilon = 0.25;
  double MinimumRadius = 0.1;
  double MaximumRadius = 0.25;
  int NumberOfAnchors = 6;
  double MaximumSeedOffset = 0.03;
  double MinimumSeedConsensus = 0.7;
  double SeedConsensusRadius = 1.0;
  double SeedConsensusTolerance = 0.03;
  double SeedConsensusRelativeTolerance = 0.08;
  double MinimumShellArea = 0.1; // TemplateSelectionOptions::minimumShellArea
  int Persistence = 3;           // TemplateSelectionOptions::persistence
  int TemplateCriterion = 1;
  int TemplateFrame = -1;
  int ChosenFrame = -1;
};

#endif
