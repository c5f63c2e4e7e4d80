#pragma once
// Template fitting (Shehu et al. 2016, section 4.3, after Allen et al. 2003): every template
// vertex t_i gets an affine map A_i, and
//
//   E = wc Ec + ws Es + wd (Ed + wb Eb) + wt Et
//   Ec = 1/|C| sum_{i in C} |A_i t_i - c_i|^2      c_i: dense correspondence on the frame
//   Ed = 1/|D| sum_{i in D} |A_i t_i - n_i|^2      n_i: closest frame point, valid when within
//                                                   maximumNearestDistance and normals < 90 deg
//                                                   apart
//   Eb = 1/|B| sum_{j in B} |A_i(j) t_i(j) - f_j|^2  f_j: frame vertex, i(j) its nearest
//                                                   template vertex (the same validity as Ed;
//                                                   wb = coverageWeight)
//   Es = 1/sum|N(i)| sum_i sum_{j in N(i)} |A_i - A_j|_F^2
//   Et = 1/N sum_i |A_i - I|_F^2                    relative to the previous frame's fit
//
// minimised in stages of decreasing smoothness, nearest points recomputed between rounds. With
// the nearest points fixed E is quadratic in the A_i, so a round is one sparse linear
// least-squares problem: the exact solver solves its normal equations (4N x 4N, symmetric
// positive definite, three right-hand sides) by sparse Cholesky; the L-BFGS solver is the
// paper's quasi-Newton reference on the same energy. Positions are taken relative to the
// template's centroid, so that the translation part of A_i stays small and comparable with
// its linear part.
#include <clothtrack/mesh/TriangleMesh.h>
#include <clothtrack/solver/PreconditionerFactor.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace clothtrack
{
/// Weights of one stage, in the order (wc, ws, wd, wt).
struct FitStage
{
  double correspondence = 1.0; ///< wc
  double smoothness = 400.0;   ///< ws
  double nearest = 0.0;        ///< wd
  double temporal = 0.1;       ///< wt
};

enum class FitSolver
{
  Exact, ///< sparse Cholesky of the normal equations, once per round
  LBFGS  ///< limited-memory quasi-Newton, nearestEvery iterations per round
};

struct TemplateFitOptions
{
  /// The paper's schedule (section 4.4): smoothness and correspondence lead while the template
  /// is far, then nearest points take over.
  std::vector<FitStage> stages = {
      {1, 400, 0, 0.1}, {1, 200, 10, 0.1}, {0, 100, 10, 0.1}, {0, 50, 10, 0.1}};
  FitSolver solver = FitSolver::Exact;
  /// Rounds of (nearest points, minimisation) per stage that uses nearest points; a stage
  /// without them is one round.
  int roundsPerStage = 5;
  /// L-BFGS iterations per round (the paper recomputes nearest points every 20 iterations).
  int nearestEvery = 20;
  /// Exact solver: a stage ends early once no vertex moved more than this in a round (metres).
  double convergence = 5e-4;
  /// Exact solver: relative residual at which the preconditioned conjugate gradients stop in a
  /// stage's last round (the default's measurements: docs/template-fit.md).
  double solverTolerance = 1e-4;
  /// Exact solver: the same for the rounds before a stage's last, whose solution only places
  /// the next round's nearest points (docs/template-fit.md weighs time against accuracy).
  double intermediateTolerance = 1e-4;
  /// Exact solver: a stage's factorisation, kept from frame to frame as the preconditioner, is
  /// renewed at the next frame once its conjugate gradients needed more than this many steps
  /// per round in a frame (the template has moved far from the factored matrix). 0: only when
  /// they fail to converge.
  double refactorSteps = 4.0;
  /// Exact solver: the factorisation behind the preconditioner (solver/PreconditionerFactor.h).
  FactorBackend factorBackend = FactorBackend::Block;
  /// Correspondences further than this from the template as fitted so far are dropped before
  /// each round but the first (metres; 0 keeps them all, as the paper does).
  double correspondenceOutlier = 0.0;
  /// The data terms (Ec, Ed) are squared lengths, the linear part of the regularisers (Es, Et)
  /// is not: the unit of length sets their balance. Lengths enter the energy multiplied by this
  /// (1: metres, 100: centimetres); thresholds and results stay in metres.
  double lengthScale = 1.0;
  double maximumNearestDistance = 0.2; ///< metres
  double maximumNormalAngle = 90.0;    ///< degrees
  /// Weight of a frame-to-template term, as a fraction of the stage's wd: in the rounds with
  /// nearest points every frame vertex also pulls its nearest template vertex (within
  /// maximumNearestDistance, normals within maximumNormalAngle), so that a part of the frame the
  /// template has slid off (a foot) draws it back; Ed alone is satisfied by any template lying
  /// on the frame. 0: template to frame only, as the paper. 0.2 lowers the frames' coverage
  /// distance by 10-50 % and the error a little (BENCHMARKS.md, "Robustness: the frame covered").
  double coverageWeight = 0.2;
  /// A vertex that moved less than this (metres) since its last closest-point search on the
  /// frame keeps that search's triangle and is projected onto it: the point found is then at
  /// most twice this much farther than the closest one. 0 searches for every vertex in every
  /// round (the searches saved: docs/template-fit.md).
  double nearestReuse = 2e-4;
  /// Ablations: without Ec (the paper's Figure 6) or without Ed.
  bool useCorrespondence = true;
  bool useNearest = true;
};

/// Dense correspondence of the template vertices on one frame (from PatchCorrespondence).
struct VertexTargets
{
  Points position;                    ///< N x 3
  std::vector<unsigned char> matched; ///< N flags
  int count() const;
};

struct FrameCorrespondence;
/// The template vertices a patch correspondence matched, as fit targets.
VertexTargets vertexTargets(const FrameCorrespondence& correspondence);

struct FrameFit
{
  Points positions;                ///< fitted template vertices
  std::vector<unsigned char> used; ///< correspondence used in the energy
  Eigen::VectorXd surfaceDistance; ///< distance of each fitted vertex to the frame's surface
  /// Mean of surfaceDistance; negative when not measured (a resumed frame).
  double meanSurfaceDistance = -1.0;
  int nearestValid = 0;       ///< valid nearest points in the last round
  int rounds = 0;             ///< minimisations run
  int iterations = 0;         ///< L-BFGS iterations, or conjugate-gradient steps
  int factorisations = 0;     ///< exact solver: Cholesky factorisations
  double factorSeconds = 0.0; ///< exact solver: time in the factorisations
  double solveSeconds = 0.0;  ///< exact solver: time in the conjugate gradients
  int nearestSearches = 0;    ///< closest-point searches (the rest reused, nearestReuse)
  double energy = 0.0;        ///< E at the end of the last stage
  double seconds = 0.0;
  bool resumed = false; ///< positions kept from an earlier run, not fitted here
  /// The sequence fit's judge of this fit (SequenceFitHooks::judge): at most 1 is trusted, more
  /// is doubtful; 0 when nothing judged it.
  double doubt = 0.0;
  int attempts = 1;     ///< fits tried for the frame (more when the first one was doubtful)
  std::string recovery; ///< empty, or the other start whose fit was kept instead of the first
};

/// What a TemplateFitter carries from one frame to the next (TemplateFitOptions::refactorSteps):
/// per stage, the normal matrix its preconditioner factorised and whether that factorisation is
/// due for renewal. The preconditioner changes the last bits of every later fit, so a fitter that
/// takes over the state another had after frame k fits the next frames exactly as that one
/// would: an interrupted sequence fit resumes to the same result.
struct TemplateFitterState
{
  struct Stage
  {
    bool factored = false; ///< the stage has a factorisation (false: none made yet)
    bool stale = false;    ///< it is renewed at the stage's next round
    /// The factorised matrix: every edge's off-diagonal block is -edgeWeight I, and each
    /// vertex's diagonal block is given by its lower triangle, 10 values row by row.
    double edgeWeight = 0.0;
    std::vector<double> blocks;
  };
  int vertices = 0;
  std::vector<Stage> stages;
};

/// Deforms one template connectivity onto frames. The symbolic factorisation is shared by all
/// frames; fit() itself is sequential and uses parallel loops inside.
class TemplateFitter
{
public:
  /// Throws Error on an empty template, bad indices, non-finite positions or bad options.
  TemplateFitter(const TriangleMesh& templateMesh, const TemplateFitOptions& options = {});
  ~TemplateFitter();
  TemplateFitter(const TemplateFitter&) = delete;
  TemplateFitter& operator=(const TemplateFitter&) = delete;

  /// Deforms the template, currently at `start` (the fit of the neighbouring frame), onto
  /// `frame`. `targets` may be null (no correspondence).
  FrameFit fit(const Points& start, const TriangleMesh& frame, const VertexTargets* targets) const;

  const TemplateFitOptions& options() const { return options_; }

  /// The state the next fit starts from (see TemplateFitterState).
  TemplateFitterState state() const;
  /// Takes over `state`, factorising its matrices again. Throws Error when it was made for
  /// another vertex count or holds non-finite or non-positive-definite matrices; the fitter is
  /// then left without factorisations.
  void restore(const TemplateFitterState& state);

private:
  struct Impl;
  TemplateFitOptions options_;
  std::unique_ptr<Impl> impl_;
};

} // namespace clothtrack
