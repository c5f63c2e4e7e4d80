#pragma once
// Dense template-to-frame correspondence from oriented landmark pairs by growing partial
// near-isometric geodesic patches (Shehu et al. 2016, section 4.2, after Brunton et al. 2014).
//
// One oriented point correspondence fixes an isometry between two surfaces: a template point at
// geodesic polar coordinates (r, phi) around the seed maps to the frame point at (r, phi) around
// the seed's image. Each landmark pair gives such a map f on the template disc of radius tau_d;
// a vertex is kept when the map is near-isometric there (|d_T(a, t) - d_S(f(a), f(t))| <= eps
// for the seed and a few anchor points a of the patch), and the patch grows from the seed
// through kept vertices only. An arm merged with the torso on the frame makes geodesic
// distances there short-cut, so the test fails and the patch stops at the merge. Patches whose
// radius stays below tau_s are discarded. Overlapping patches are merged per vertex into one
// point of the frame (see PatchCorrespondence.cpp for the average used).
#include <clothtrack/mesh/ExponentialMap.h>
#include <clothtrack/mesh/SurfaceLocator.h>
#include <clothtrack/mesh/TriangleMesh.h>

#include <memory>
#include <vector>

namespace clothtrack
{
struct PatchCorrespondenceOptions
{
  double epsilon = 0.25;       ///< near-isometry tolerance eps, metres
  double minimumRadius = 0.1;  ///< tau_s: smaller patches are discarded, metres
  double maximumRadius = 0.25; ///< tau_d: intrinsic radius where growth stops, metres
  int numberOfAnchors = 6;     ///< points checked besides the seed, around each patch
  double chartMargin = 1.3;    ///< the frame's chart reaches this times tau_d (stretching cloth)
  /// Assignments of one vertex closer than this to their medoid are averaged; further ones are
  /// outliers of the merge (metres).
  double agreement = 0.05;
  /// Landmarks further than this from the body (|offset|, metres) seed no patch: loose cloth
  /// slides over the body, so a body landmark carried onto it is not the same cloth point from
  /// one frame to the next.
  double maximumSeedOffset = 0.03;
  /// Seed consensus. A body landmark misplaced on a frame (an arm posed wrongly under the
  /// clothing) gives a patch that passes the near-isometry test yet is shifted as a whole. Two
  /// seed pairs agree when their geodesic distance on the frame is that on the template within
  /// seedConsensusTolerance + seedConsensusRelativeTolerance * distance; the other seeds within
  /// seedConsensusRadius of a seed on the template vote, and a seed that agrees with less than
  /// minimumSeedConsensus of at least 3 voters grows no patch (minimumSeedConsensus 0: every seed
  /// grows).
  double minimumSeedConsensus = 0.7;
  double seedConsensusRadius = 1.0;     ///< metres
  double seedConsensusTolerance = 0.03; ///< metres
  double seedConsensusRelativeTolerance = 0.08;
};

struct PatchSummary
{
  int landmarkId = -1;
  int vertices = 0;        ///< template vertices the patch maps
  double radius = 0.0;     ///< largest geodesic distance from the seed among them
  int inconsistent = 0;    ///< disc vertices that failed the near-isometry test
  bool kept = false;       ///< radius >= tau_s
  double consensus = -1.0; ///< share of the voting seeds it agrees with (-1: no vote)
  bool outvoted = false;   ///< consensus below minimumSeedConsensus: the seed grew no patch
};

/// Where one template vertex goes on the frame.
struct VertexMatch
{
  int face = -1; ///< frame triangle, -1 when unmatched
  Vec3 bary = Vec3::Zero();
  Vec3 position = Vec3::Zero();
  int patches = 0;     ///< patches that mapped the vertex
  double spread = 0.0; ///< RMS distance of the patches' assignments to the result (confidence)
  int patchId = -1;    ///< landmark id of the patch whose assignment is nearest the result
  bool matched() const { return face >= 0; }
};

struct FrameCorrespondence
{
  std::vector<VertexMatch> vertices; ///< one per template vertex
  std::vector<PatchSummary> patches; ///< one per landmark pair tried
  double seconds = 0.0;              ///< wall time spent on it
  double matchedFraction() const;
};

/// The template side, prepared once for a whole sequence: one polar chart and its anchor
/// distance fields per template landmark. correspond() may run on several frames at once.
class TemplatePatches
{
public:
  /// Throws Error on a landmark with a bad face or an unusable direction.
  TemplatePatches(const TriangleMesh& templateMesh,
                  const std::vector<OrientedSurfacePoint>& landmarks,
                  const PatchCorrespondenceOptions& options = {});
  ~TemplatePatches();

  /// Correspondence to one frame; landmarks are paired with the template's by id (ids missing
  /// on either side are skipped). Patches run in parallel (see setThreadCount).
  FrameCorrespondence correspond(const TriangleMesh& frame,
                                 const std::vector<OrientedSurfacePoint>& frameLandmarks) const;

  const TriangleMesh& templateMesh() const { return mesh_; }
  const PatchCorrespondenceOptions& options() const { return options_; }

private:
  struct Patch;
  /// Marks the seeds outvoted by the geodesic distances between the seeds (minimumSeedConsensus).
  /// The distance field from each seed's image, which reaches at least as far as a patch's, goes to
  /// `fields` (one slot per seed) for the patch to reuse.
  void voteOnSeeds(const TriangleMesh& frame, const ExponentialMapper& mapper,
                   const std::vector<const OrientedSurfacePoint*>& images,
                   std::vector<PatchSummary>& summaries,
                   std::vector<Eigen::VectorXd>& fields) const;
  /// Geodesic reach a patch needs from its seed's image on the frame.
  double seedFieldReach() const;
  const TriangleMesh& mesh_;
  PatchCorrespondenceOptions options_;
  std::vector<std::unique_ptr<Patch>> patches_;
  /// Geodesic distances between the template's seeds (within seedConsensusRadius; else infinite).
  Eigen::MatrixXd seedDistances_;
};

/// Baseline: the template moved rigidly onto the frame (least squares over the paired landmark
/// positions) and each vertex matched to its closest frame point.
FrameCorrespondence rigidNearestCorrespondence(
    const TriangleMesh& templateMesh, const std::vector<OrientedSurfacePoint>& templateLandmarks,
    const TriangleMesh& frame, const std::vector<OrientedSurfacePoint>& frameLandmarks);

} // namespace clothtrack
