#pragma once
// Body shape and pose under clothing for a whole sequence (Shehu et al. 2016 section 4.1,
// after Yang et al. 2016): one shape beta for the sequence and a pose per frame minimising
//   E_body = w_l E_l + w_n E_n + w_w E_w
//  - E_l: detected extremities of the frame (head top, hand and toe tips: persistent maxima of
//    the geodesic distance from the surface's centre, see Extremities.h) against the same
//    extremities of the body, matched by label and proximity;
//  - E_n: body samples to their closest frame points (point-to-plane, robust Cauchy weights so
//    that body parts far under wide clothing are not dragged out to the cloth; pairs whose
//    normals disagree are dropped);
//  - E_w: body samples OUTSIDE the frame (signed distance to the closest point, positive
//    outside) are pushed in, so that the body stays under the clothing;
//  - E_c (while the shape is estimated, by default): the frame's vertices to their nearest
//    body samples, so that a body thinner than the person grows to fill the torso;
// plus a temporal term (joint rotations close to the previous frame's) and weak priors (joint
// rotations and beta towards zero: beta ~ N(0, I) in the model's units).
//
// Schedule (per frame, see BodyFitOptions::stages): landmarks dominate first (they are sparse
// but reliable and bring the limbs near their place), then the dense terms take over and the
// inside term is raised last, when the body is close enough for the inside/outside sign of
// the closest point to be right.
//
// Initialisation is automatic: the first frame tries several headings about the up axis and
// keeps the closest fit (between facings that fit about as closely, the one whose joints bend
// least against their range), each frame then starts from its neighbour's result; a frame whose fit
// looks poor is retried from all headings (the person may have turned quickly) and the better
// result kept. A frame far from its predecessor (a cut, a gap in the capture, or a collection of
// unrelated poses: see neighbourGap) is not tied to it by the temporal prior, may turn any way,
// and is also started from the poses of the frames fitted before it; the fit that explains the
// frame best, both ways (body to frame and frame to body), is kept. The shape is estimated on
// evenly spread key frames alternating with their poses, then every frame is fitted again with the
// final shape, also from its predecessor's pose and with either leg raised (a knee raised fast
// under wide trousers), the fit that explains it best both ways kept. Last, a fit that leaves much
// more of its frame unexplained than the sequence's others is poor (a limb fitted in the wrong
// place), and every poor fit is started again from the poses of the sequence's ok fits.
//
// Shared among processes (BodyFitOptions::sharing), each process tracks its own segment of the
// sequence, starting BodyFitSharing::overlap frames before it (the first from all headings, as
// the sequence's first frame) and, backwards, as many after it; the fits are exchanged after each
// pass, and the shape is estimated by every process from the same key frames, the first's kept.
#include "BodyFitSharing.h"
#include "BodyModel.h"

#include <clothtrack/base/Progress.h>
#include <clothtrack/mesh/FrameSource.h>

#include <Eigen/Geometry>

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace clothtrack
{
/// The rigid motion carrying the surface of one frame onto the next one's, or nullopt.
using FrameMotion = std::function<std::optional<Eigen::Isometry3d>(const TriangleMesh& from,
                                                                   const TriangleMesh& to)>;

struct BodyFitStage
{
  double landmarkWeight; ///< w_l
  double nearestWeight;  ///< w_n
  double insideWeight;   ///< w_w
  int iterations;
  /// Closest frame points are searched this far (metres): wide while the body is far, narrow
  /// later, where a sample with nothing near is deep under the cloth and should not pull.
  double searchRadius;
  /// w_c, E_c: each of up to 1000 frame vertices pulls its nearest body sample towards its
  /// tangent plane (Cauchy weights of scale BodyFitOptions::coverScale; pairs whose normals
  /// disagree dropped). 0: off. E_n lets a body thinner than the person hug one side of the
  /// torso, as the robust weights favour one close side over two half-way ones; the far side
  /// pulls it back here.
  double coverWeight = 0.0;
};

struct BodyFitOptions
{
  std::vector<BodyFitStage> stages = {
      {1.0, 0.1, 0.0, 6, 0.4}, {0.5, 1.0, 1.0, 8, 0.15}, {0.2, 1.0, 4.0, 8, 0.1}};
  double temporalWeight = 0.01; ///< on joint rotation changes from the previous frame (1/rad^2)
  /// The same on the root's rotation. Light: the dense terms of a good fit are ~1e-4 (squared
  /// metres), and a heavier prior there holds a turning body back, which then twists its spine
  /// and crosses its legs to follow the frame.
  double rootTemporalWeight = 0.0003;
  /// The same on the hips' and knees' rotations. A knee raised at 5 rad/s (a marching walk, 0.2
  /// rad a frame) costs 0.01 x 0.04 = 4e-4 at the general weight, several times a good fit's
  /// dense terms: the leg was held half-way. 0.003 on every joint cost pjump 0.5 cm (BENCHMARKS.md,
  /// "knees raised fast").
  double legTemporalWeight = 0.003;
  double posePriorWeight = 0.0002; ///< on joint rotations (root excluded)
  /// Prior multiplier on rotations a joint barely makes (a knee's sideways bend; fractions of it
  /// on hip twist, ankle, toe, clavicle and wrist rotations)
  double hingeStiffness = 100.0;
  double shapePriorWeight = 2e-5; ///< on beta
  /// w_c in the shape's estimation (its steps on beta and the key frames' poses between them):
  /// the frame's vertices pull their nearest body samples, so that a body thinner than the
  /// person (pjump) grows to fill the torso rather than lie against one side of it. The passes
  /// over the sequence leave it at 0 (BodyFitStage::coverWeight).
  double shapeCoverWeight = 1.0;
  int shapeComponents = 16; ///< leading components fitted (at most the model's)
  int shapeFrames = 8;      ///< key frames for the shape
  int shapeRounds = 3;      ///< alternations of shape and key-frame poses
  /// The shape is estimated twice: once with the key frames' poses fixed between its steps, once
  /// with their translations moving with beta (with the pose fixed, a body growing towards a
  /// tall person's stature pushes its feet through the floor, so it stays near the mean's; with
  /// them moving, a body whose proportions the shape space lacks can float off the floor). The
  /// final pass runs under each, and the sequence keeps the shape under which its median frame
  /// distance (BodyFrameFit::frameDistance) is lower: the median, so that a frame that is not a
  /// person (a box, in app.align) does not choose the shape for the others, and then go
  /// unflagged because the shape it chose fits it. A few frames cannot tell: pjump's key
  /// frames, and 24 others refitted from their first-pass poses, favour the second shape, its
  /// whole sequence the first. Off: the first shape only, and half the final pass.
  bool twoShapes = true;
  /// Two shapes whose rest-pose bodies lie within this of each other at every vertex (metres)
  /// are one body under the clothing: pass 2 runs under the first only, and the sequence keeps
  /// it. Samba's two shapes, 6.3 mm apart, give median frame distances of 42.27 and 42.22 mm:
  /// a choice not worth a second pass 2 (15 % of samba's alignment time). 0: pass 2 always runs
  /// under both.
  double sameShapeTolerance = 0.01;
  /// The shape's estimation starts from the mean body scaled, along the shape space, to the
  /// stature the key frames suggest: the median over them of the frame's height over the height
  /// of the body fitted to it with the mean shape (pose-independent: a squat or raised arms
  /// change both). The alternation of shape and poses grows a body towards a tall person's
  /// stature only slowly. Off by default: it halves the stature error of the synthetic people,
  /// but pjump's body, its proportions outside the shape space, then floats out of its boots in
  /// six frames that no confidence check flags (BENCHMARKS.md).
  bool statureStart = false;
  int samples = 600;         ///< body vertices used by the dense terms
  double robustScale = 0.03; ///< Cauchy scale of E_n, metres
  /// Cauchy scale of the cover term (BodyFitStage::coverWeight), metres.
  double coverScale = 0.05;
  double extremityPersistence = 0.13; ///< metres
  double extremityGate =
      0.35; ///< head and toes: detected and body extremities further apart are not paired
  double handGate = 0.8; ///< the same for the hands, which move fastest and furthest
  /// A detected extremity pairs with a body extremity only within this multiple of the limb's
  /// length (root joint to tip) from the root joint: tips of cloth folds are left out.
  double reachTolerance = 1.1;
  /// The same while the shape is still estimated (first pass and shape rounds). The mean body's
  /// limbs are much shorter than a tall person's; with the toes refused for being out of reach,
  /// the shape never grows to reach them (a 1.97 m person was fitted 1.65 m tall).
  double shapeReachTolerance = 1.4;
  /// The final pass also starts each frame with one leg raised: its hip flexed by this much
  /// (radians) and its knee folded by 1.5 times it, with the temporal prior towards that start,
  /// and keeps the result when it explains the frame better both ways. A straight leg inside wide
  /// trousers still lies inside the cloth, so the dense terms do not lift it towards a raised
  /// knee. 0: off.
  double legRaiseStart = 0.6;
  /// A frame that does not continue its predecessor (neighbourGap) is also started again, in the
  /// first and the final pass (the first frame in the final pass, when its successor does not
  /// continue it), with each limb back in the rest pose and with each limb aimed at
  /// a detected extremity its fit leaves unpaired, and with both arms, then both legs, aimed at
  /// each other's extremity; a start is kept where it explains the frame better both ways and
  /// does not put more of the arms inside the torso. Extremities are paired by proximity, so
  /// limbs that crossed to the other side's hand or foot stay crossed until swapped, and a leg
  /// kicked out lies beyond the pairing gate of a foot hanging down (BENCHMARKS.md, "collections
  /// of unrelated poses: limbs started again" and "crossed limbs").
  bool limbRestarts = true;
  /// With limbRestarts, on a collection (at least 3 unrelated frames), each unrelated frame whose
  /// two-sided score exceeds this factor times their median is also fitted turned half round,
  /// limbs at rest then restarted, and the better fit kept: a body started from an unrelated pose
  /// can settle facing backwards, and the heading search then still favours that facing.
  double turnRoundRatio = 1.2;
  int headings = 8; ///< headings tried when (re)initialising
  /// First-frame fits facing more than 90 degrees apart whose scores are within this factor are
  /// told apart by the pose prior (front and back look alike under loose clothing).
  double headingAmbiguity = 1.1;
  /// Consecutive frames whose surfaces lie further apart than this (meanSurfaceGap, metres) are
  /// not treated as neighbours. Consecutive frames of the captures measured lie within 4.5 cm of
  /// each other even in fast motion, unrelated poses tens of centimetres apart.
  double neighbourGap = 0.06;
  /// A fit whose frameDistance exceeds the sequence's median by this factor and by
  /// unexplainedMargin (metres) is poor: its body leaves a limb of the frame unexplained (the
  /// frames of correct fits measured stay within 1.41 times their median, wrong ones 2.2).
  double unexplainedRatio = 1.6;
  double unexplainedMargin = 0.03;
  Vec3 up = Vec3::UnitY(); ///< up axis of the frames
  /// Median body-to-frame distance above which a fit is poor. Correct fits measured stay under
  /// 2.6 cm (pjump, unclothed collections, dresses); the body crammed into a 60 cm box where a
  /// person stood lies 4.8-6.1 cm from it, depending on the frames around it.
  double poorDistance = 0.035;
  double insideTolerance = 0.02; ///< a body sample this far outside still counts as inside
  double poorInside = 0.75;      ///< fraction of the body inside the frame below which it is poor
  /// Optional: the rigid motion carrying one frame's surface onto the next one's (for instance
  /// registerRigidly in the cloud stage), or nullopt when it is not known. The first pass then
  /// moves the predecessor's pose by it before fitting a frame, so that a turn or a step already
  /// made is not left to the fit to find. Empty: the predecessor's pose as it is.
  FrameMotion frameMotion;
  /// The processes this fit is shared with; by default none.
  BodyFitSharing sharing;
};

/// Changes whenever the fit's results change for the same options, so that results cached by an
/// older release are not reused.
inline constexpr int kBodyFitRevision = 7;

enum class BodyFitStatus : int
{
  Ok = 0,
  Poor = 1,  ///< fitted, but the body is far from or outside the frame: check it
  Failed = 2 ///< not fitted (bad frame); the pose is the neighbour's
};

const char* bodyFitStatusName(BodyFitStatus status);

struct BodyFrameFit
{
  BodyPose pose;
  BodyFitStatus status = BodyFitStatus::Ok;
  std::string message;
  double energy = 0.0;
  double medianDistance = 0.0; ///< body samples to the frame, metres
  double insideFraction = 0.0; ///< body samples inside the frame or within insideTolerance
  /// Mean distance from the frame to the body (metres): what of the frame the body leaves
  /// unexplained. Clothing raises it evenly over a sequence; a wrongly fitted limb raises it on
  /// its frame alone.
  double frameDistance = 0.0;
  int extremitiesDetected = 0;
  int extremitiesMatched = 0;
  std::vector<Vec3> extremities; ///< detected on the frame
  /// meanSurfaceGap to the previous fitted frame (metres; 0 for the first).
  double previousGap = 0.0;
  /// False when previousGap exceeds BodyFitOptions::neighbourGap: the frame was fitted as an
  /// unrelated pose, not from its predecessor alone.
  bool continuesPrevious = true;
  /// The lowest two-sided score of another fit whose body lies more than 30 cm from this one's
  /// somewhere (a limb elsewhere), relative to this fit's: near 1, two readings of the frame
  /// explain it about as well. Measured on the unrelated frames of a collection, from the
  /// other frames' joints (SequenceFitter::refitFromPeerJoints); infinity where not measured.
  double rivalScoreRatio = std::numeric_limits<double>::infinity();
};

/// The median frameDistance of the ok fits; nullopt with fewer than `minimumFits` of them.
std::optional<double> medianFrameDistance(const std::vector<BodyFrameFit>& fits,
                                          size_t minimumFits = 1);

/// The fitted pose's restPoseDistance when the fit is ok; NaN for a poor or failed fit, whose
/// pose must not choose the template.
double fittedRestPoseDistance(BodyFitStatus status, const BodyPose& pose);

struct BodyFitResult
{
  Eigen::VectorXd beta; ///< the shape every frame is fitted under
  /// BodyFitOptions::twoShapes: the estimate not kept (empty when only one was made), and
  /// whether `beta` is the one estimated with the key frames' translations moving.
  Eigen::VectorXd otherBeta;
  bool movedShape = false;
  /// The largest distance between the two shapes' rest-pose vertices (metres); below
  /// BodyFitOptions::sameShapeTolerance pass 2 ran under `beta` only. Negative with one shape.
  double shapeGap = -1.0;
  std::vector<BodyFrameFit> frames;
};

/// Fits the model to every frame (frames need not share connectivity; null or empty frames are
/// flagged Failed). Throws Error when no frame can be fitted at all.
BodyFitResult fitBodySequence(const BodyModel& model,
                              const std::vector<const TriangleMesh*>& frames,
                              const BodyFitOptions& options = {},
                              const StageProgress& progress = {});
/// The same over frames read when needed: a frame is held while its passes use it.
BodyFitResult fitBodySequence(const BodyModel& model, const FrameSource& frames,
                              const BodyFitOptions& options = {},
                              const StageProgress& progress = {});

/// The body's extremity vertices, in the order head top, left hand, right hand, left toe,
/// right toe (the geodesically most distant vertex of each end segment in the rest pose).
std::vector<int> bodyExtremityVertices(const BodyModel& model);
} // namespace clothtrack
