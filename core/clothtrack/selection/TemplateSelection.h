#pragma once
// Automatic template frame selection (Shehu et al. 2016, section 4.2, after Letouzey and Boyer):
// the true topology is fixed, acquisition can only merge parts, so observed splits are real when
// they persist. Candidates are the frames with the most (persistent) shells; among them, the
// smallest genus of the largest shell. The paper then takes the candidate with the smallest area
// ratio (largest / smallest mixed Voronoi vertex area of the largest shell): the most uniform
// mesh. When the body fit is known, the default instead takes the candidate whose fitted body is
// closest to the model's rest pose (limbs straight and apart): topology cannot see a forearm
// pressed to the chest or a bent knee under a skirt, and these are the frames where the
// correspondences and the fit of the other frames go wrong. The area ratio breaks ties.
#include <clothtrack/mesh/TriangleMesh.h>

#include <vector>

namespace clothtrack
{
struct FrameTopology
{
  int components = 0; ///< all connected components
  int shells = 0;     ///< components with area >= the minimum shell area
  int genus = 0;      ///< genus of the largest component
  double areaRatio = 0.0;
  double area = 0.0;  ///< area of the largest component
  int boundaries = 0; ///< boundary loops (holes) of the largest component
  int nonManifoldEdges = 0;
};

/// The last criterion, among the topological candidates.
enum class TemplateCriterion : int
{
  AreaRatio = 0, ///< the paper's: most uniform vertex areas
  RestPose = 1   ///< body closest to the rest pose; the area ratio when poses are unknown
};

const char* templateCriterionName(TemplateCriterion criterion);

struct TemplateSelectionOptions
{
  double minimumShellArea = 0.1; ///< m^2: smaller components are noise, not body parts
  int persistence = 3;           ///< a split counts only if it lasts this many consecutive frames
  TemplateCriterion templateCriterion = TemplateCriterion::RestPose;
};

struct TemplateSelection
{
  int chosen = -1;
  std::vector<int> persistentShells; ///< per frame: shell count once short-lived splits are ignored
  std::vector<char> candidate;       ///< passed the topological criteria
  TemplateCriterion decidedBy = TemplateCriterion::AreaRatio; ///< the criterion that chose
  std::vector<FrameTopology> frames; ///< per frame: its criteria (filled by chooseTemplateFrame)
};

/// The criteria of one frame.
FrameTopology frameTopology(const TriangleMesh& mesh, double minimumShellArea);

/// Chooses the template among frames described by their criteria. `restPoseDistance` (optional,
/// one per frame, radians, see clothtrack::restPoseDistance) is the distance of each frame's
/// fitted body from the rest pose; NaN or infinity where the fit failed or is poor. Frames
/// without a known pose are chosen only when no candidate has one. Ties go to the earliest frame.
TemplateSelection selectTemplate(const std::vector<FrameTopology>& frames,
                                 const TemplateSelectionOptions& options,
                                 const std::vector<double>& restPoseDistance = {});

/// The topological candidates of `selection` with a known pose (a finite `restPoseDistance`),
/// nearest the rest pose first (ties to the earliest frame): the frames the rest-pose criterion
/// would choose in turn. Empty when `restPoseDistance` does not have one entry per frame.
std::vector<int> templateFramesByPose(const TemplateSelection& selection,
                                      const std::vector<double>& restPoseDistance);

/// Whether frames fitted one after the other are a collection of unrelated poses rather than a
/// sequence: at least half of the frames after the first do not continue their predecessor
/// (`continuesPrevious`, one per frame, BodyFrameFit::continuesPrevious).
bool isCollectionOfPoses(const std::vector<bool>& continuesPrevious);

/// Template frames worth aligning under when none is asked for: 3 on a collection of poses, where
/// the pose alone can choose a frame whose body is wrong and every frame starts from the template
/// (BENCHMARKS.md, "Collections of unrelated poses: the template chosen by the alignment"); 1 on
/// a sequence, whose neighbouring frames carry each other.
int defaultTemplateCandidates(const std::vector<bool>& continuesPrevious);
} // namespace clothtrack
