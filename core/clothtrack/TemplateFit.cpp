#include "TemplateFit.h"

#include "BlockCholesky.h"
#include "Error.h"
#include "MeshTopology.h"
#include "MeshValidation.h"
#include "Parallel.h"
#include "PatchCorrespondence.h"
#include "SurfaceLocator.h"

#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace clothtrack
{
namespace
{
// Unknowns: X, 4N x 3, rows 4i..4i+3 hold the transposed affine map of vertex i, so that the
// deformed vertex is X_i^T [t_i; 1]. Its first three rows are the linear part, the fourth the
// translation; the identity map is [I3; 0].
using Unknowns = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using SparseMatrix = Eigen::SparseMatrix<double>;

Unknowns identityMaps(int n)
{
  Unknowns X = Unknowns::Zero(4 * static_cast<Eigen::Index>(n), 3);
  for (int i = 0; i < n; ++i) X.block<3, 3>(4 * i, 0).setIdentity();
  return X;
}

double dot(const Unknowns& a, const Unknowns& b)
{
  return (a.array() * b.array()).sum();
}

/// a . b, in parallel (the same sum for any thread count).
double parallelDot(const Unknowns& a, const Unknowns& b)
{
  const double* x = a.data();
  const double* y = b.data();
  return parallelSum(a.size(),
                     [&](long from, long to)
                     {
                       return Eigen::Map<const Eigen::VectorXd>(x + from, to - from)
                           .dot(Eigen::Map<const Eigen::VectorXd>(y + from, to - from));
                     });
}

double seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

/// One round's quadratic: E(X) = tr(X^T H X) - 2 tr(X^T R) + c. H is a 4x4 block per vertex on
/// the diagonal and -edgeWeight I4 per edge; products use that structure, and the sparse matrix
/// is made only when a factorisation needs it (TemplateFitter::Impl::normalMatrix).
struct Quadratic
{
  Unknowns R;
  double c = 0.0;
  std::vector<Eigen::Matrix4d> diagonal;
  double edgeWeight = 0.0;
  const std::vector<int>* neighbourStart = nullptr; // CSR vertex adjacency
  const std::vector<int>* neighbours = nullptr;

  Unknowns times(const Unknowns& X) const
  {
    Unknowns out(X.rows(), 3);
    times(X, out);
    return out;
  }
  void times(const Unknowns& X, Unknowns& out) const { timesDot(X, out); }
  /// out = H X, and returns X . out (the conjugate gradients' curvature) from the same pass.
  double timesDot(const Unknowns& X, Unknowns& out) const
  {
    out.resize(X.rows(), 3);
    const int n = static_cast<int>(diagonal.size());
    return parallelSum(n,
                       [&](long from, long to)
                       {
                         double dot = 0;
                         for (long i = from; i < to; ++i)
                         {
                           Eigen::Matrix<double, 4, 3> sum = Eigen::Matrix<double, 4, 3>::Zero();
                           for (int k = (*neighbourStart)[i]; k < (*neighbourStart)[i + 1]; ++k)
                             sum +=
                                 X.middleRows<4>(4 * static_cast<Eigen::Index>((*neighbours)[k]));
                           const auto Xi = X.middleRows<4>(4 * i);
                           const Eigen::Matrix<double, 4, 3> product =
                               diagonal[i] * Xi - edgeWeight * sum;
                           out.middleRows<4>(4 * i) = product;
                           dot += (Xi.array() * product.array()).sum();
                         }
                         return dot;
                       });
  }
  double energy(const Unknowns& X) const { return dot(X, times(X)) - 2.0 * dot(X, R) + c; }
};

} // namespace

int VertexTargets::count() const
{
  return static_cast<int>(std::count(matched.begin(), matched.end(), 1));
}

VertexTargets vertexTargets(const FrameCorrespondence& correspondence)
{
  const int n = static_cast<int>(correspondence.vertices.size());
  VertexTargets t;
  t.position = Points::Zero(n, 3);
  t.matched.assign(n, 0);
  for (int i = 0; i < n; ++i)
    if (correspondence.vertices[i].matched())
    {
      t.matched[i] = 1;
      t.position.row(i) = correspondence.vertices[i].position.transpose();
    }
  return t;
}

struct TemplateFitter::Impl
{
  int n = 0;
  std::vector<std::array<int, 2>> edges;
  std::vector<int> degree;
  std::vector<int> neighbourStart, neighbours; // CSR adjacency
  int neighbourCount = 0;                      // sum of |N(i)|
  std::vector<std::array<int, 3>> faces;
  // Storage index in pattern.valuePtr() of the lower diagonal block entries (10 per vertex) and of
  // the four diagonal entries of each edge's off-diagonal block: H's pattern never changes.
  std::vector<std::array<int, 10>> diagonalSlots;
  std::vector<std::array<int, 4>> edgeSlots;
  SparseMatrix pattern;
  // One numeric factorisation per stage, kept across rounds and frames: the normal equations
  // change little from one round to the next (a few nearest points) or from one frame to the
  // next (the template moved a little), so the old factor preconditions conjugate gradients that
  // reach the new solution in a few steps. A factor is renewed when they need too many.
  // fit() is therefore not reentrant.
  mutable std::vector<std::unique_ptr<BlockCholesky>> factors;
  mutable std::vector<unsigned char> stale; // per stage: renew the factor at its next round
  mutable Unknowns scratch[4];

  explicit Impl(const TriangleMesh& mesh)
  {
    n = mesh.numVertices();
    const MeshTopology topology = buildTopology(mesh);
    edges = topology.edges;
    degree.assign(n, 0);
    for (const auto& e : edges) ++degree[e[0]], ++degree[e[1]];
    neighbourCount = 2 * static_cast<int>(edges.size());
    neighbourStart.assign(n + 1, 0);
    for (int i = 0; i < n; ++i) neighbourStart[i + 1] = neighbourStart[i] + degree[i];
    neighbours.resize(neighbourCount);
    std::vector<int> fill(neighbourStart.begin(), neighbourStart.end() - 1);
    for (const auto& e : edges) neighbours[fill[e[0]]++] = e[1], neighbours[fill[e[1]]++] = e[0];
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(10 * static_cast<size_t>(n) + 4 * edges.size());
    for (int i = 0; i < n; ++i)
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c <= r; ++c) entries.emplace_back(4 * i + r, 4 * i + c, 1.0);
    for (const auto& e : edges)
      for (int r = 0; r < 4; ++r) entries.emplace_back(4 * e[1] + r, 4 * e[0] + r, 1.0);
    pattern.resize(4 * n, 4 * n);
    pattern.setFromTriplets(entries.begin(), entries.end());
    pattern.makeCompressed();
    auto slot = [&](int row, int col)
    { return static_cast<int>(&pattern.coeffRef(row, col) - pattern.valuePtr()); };
    diagonalSlots.resize(n);
    for (int i = 0; i < n; ++i)
    {
      int k = 0;
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c <= r; ++c) diagonalSlots[i][k++] = slot(4 * i + r, 4 * i + c);
    }
    edgeSlots.resize(edges.size());
    for (size_t e = 0; e < edges.size(); ++e)
      for (int r = 0; r < 4; ++r) edgeSlots[e][r] = slot(4 * edges[e][1] + r, 4 * edges[e][0] + r);
  }

  /// Solves H X = R to the relative residual `tolerance` with the factor of `stage`; returns the
  /// conjugate-gradient steps.
  int solveExact(const Quadratic& q, Unknowns& X, size_t stage, double tolerance,
                 int& factorisations, bool mayRefactor = true) const
  {
    constexpr int kMaxSteps = 20;
    if (factors.size() <= stage) factors.resize(stage + 1), stale.resize(stage + 1, 0);
    std::unique_ptr<BlockCholesky>& factor = factors[stage];
    auto refactor = [&]()
    {
      if (!factor) factor = std::make_unique<BlockCholesky>(pattern);
      try
      {
        factor->factorise(normalMatrix(q));
      }
      catch (const Error&)
      {
        factor.reset(); // the next round starts afresh
        throw Error("Template fit: the normal equations are not positive definite.");
      }
      ++factorisations;
    };
    if (!factor || stale[stage]) refactor();
    stale[stage] = 0;
    const double target = tolerance * q.R.norm();
    // Preconditioned conjugate gradients; the vectors are reused (each is a megabyte).
    Unknowns& r = scratch[0];
    Unknowns& z = scratch[1];
    Unknowns& p = scratch[2];
    Unknowns& Hp = scratch[3];
    q.times(X, Hp);
    r.noalias() = q.R - Hp;
    double rz = factor->solveDot(r, z);
    p = z;
    double rr = parallelDot(r, r);
    const Eigen::Index size = X.size();
    using Span = Eigen::Map<Eigen::VectorXd>;
    int step = 0;
    // Passes over the vectors are fused where a step allows (memory, not arithmetic, is what
    // they cost): H p with p . H p, the updates of X and r with r . r, z with r . z.
    for (; step < kMaxSteps && std::sqrt(rr) > target; ++step)
    {
      const double alpha = rz / q.timesDot(p, Hp);
      rr = parallelSum(size,
                       [&](long from, long to)
                       {
                         Span rk(r.data() + from, to - from);
                         Span(X.data() + from, to - from) +=
                             alpha * Span(p.data() + from, to - from);
                         rk -= alpha * Span(Hp.data() + from, to - from);
                         return rk.squaredNorm();
                       });
      const double rzNext = factor->solveDot(r, z);
      const double beta = rzNext / rz;
      forSpans(size,
               [&](long from, long to, int)
               {
                 Span pk(p.data() + from, to - from);
                 pk = Span(z.data() + from, to - from) + beta * pk;
               });
      rz = rzNext;
    }
    if (std::sqrt(rr) > target && mayRefactor)
    {
      // Too far from the factored matrix: renew the factor and finish from here.
      refactor();
      return step + solveExact(q, X, stage, tolerance, factorisations, false);
    }
    return step;
  }

  /// H of `q` as a sparse matrix (lower triangle), for factorisation.
  SparseMatrix normalMatrix(const Quadratic& q) const
  {
    SparseMatrix H = pattern;
    double* values = H.valuePtr();
    for (size_t e = 0; e < edges.size(); ++e)
      for (int r = 0; r < 4; ++r) values[edgeSlots[e][r]] = -q.edgeWeight;
    for (int i = 0; i < n; ++i)
    {
      int k = 0;
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c <= r; ++c) values[diagonalSlots[i][k++]] = q.diagonal[i](r, c);
    }
    return H;
  }

  /// The quadratic of one round. `b` holds [t_i - centroid; 1]; targets are relative to the
  /// centroid too; weights already include the 1/count normalisations.
  Quadratic assemble(const Eigen::Matrix<double, Eigen::Dynamic, 4>& b,
                     const std::vector<unsigned char>& hasCorrespondence,
                     const Points& correspondence, double correspondenceWeight,
                     const std::vector<unsigned char>& hasNearest, const Points& nearest,
                     double nearestWeight, double smoothnessWeight, double temporalWeight) const
  {
    Quadratic q;
    q.R = Unknowns::Zero(4 * static_cast<Eigen::Index>(n), 3);
    // Each neighbour pair appears twice in sum_i sum_{j in N(i)}, hence the factor 2.
    const double edgeWeight = 2.0 * smoothnessWeight;
    q.edgeWeight = edgeWeight;
    q.neighbourStart = &neighbourStart;
    q.neighbours = &neighbours;
    q.diagonal.resize(n);
    std::vector<double> constant(n, 0.0);
    parallelFor(0, n,
                [&](int i)
                {
                  Eigen::Matrix4d block =
                      Eigen::Matrix4d::Identity() * (edgeWeight * degree[i] + temporalWeight);
                  Eigen::Matrix<double, 4, 3> rhs = Eigen::Matrix<double, 4, 3>::Zero();
                  rhs.topRows<3>().setIdentity();
                  rhs *= temporalWeight;
                  double c = 3.0 * temporalWeight;
                  const Eigen::Vector4d bi = b.row(i).transpose();
                  auto addPoint = [&](double w, const Vec3& target)
                  {
                    block += w * bi * bi.transpose();
                    rhs += w * bi * target.transpose();
                    c += w * target.squaredNorm();
                  };
                  if (correspondenceWeight > 0 && hasCorrespondence[i])
                    addPoint(correspondenceWeight, correspondence.row(i).transpose());
                  if (nearestWeight > 0 && hasNearest[i])
                    addPoint(nearestWeight, nearest.row(i).transpose());
                  q.R.middleRows<4>(4 * i) = rhs;
                  q.diagonal[i] = block;
                  constant[i] = c;
                });
    for (double c : constant) q.c += c;
    return q;
  }
};

namespace
{
/// Limited-memory BFGS on a quadratic, with the exact line search a quadratic allows.
int minimiseLBFGS(const Quadratic& q, Unknowns& X, int iterations)
{
  constexpr int kMemory = 10;
  std::deque<Unknowns> s, y;
  std::deque<double> rho;
  Unknowns g = 2.0 * (q.times(X) - q.R);
  const double g0 = g.norm();
  int done = 0;
  for (; done < iterations; ++done)
  {
    if (g.norm() <= 1e-12 * std::max(1.0, g0)) break;
    // Two-loop recursion: d = -H_k g.
    Unknowns d = -g;
    std::vector<double> alpha(s.size());
    for (int k = static_cast<int>(s.size()) - 1; k >= 0; --k)
    {
      alpha[k] = rho[k] * dot(s[k], d);
      d -= alpha[k] * y[k];
    }
    if (!s.empty()) d *= dot(s.back(), y.back()) / dot(y.back(), y.back());
    for (size_t k = 0; k < s.size(); ++k)
    {
      const double beta = rho[k] * dot(y[k], d);
      d += (alpha[k] - beta) * s[k];
    }
    const Unknowns Hd = q.times(d);
    const double curvature = 2.0 * dot(d, Hd);
    const double slope = dot(g, d);
    if (!(curvature > 0) || slope >= 0) break;
    const double step = -slope / curvature;
    const Unknowns sk = step * d;
    const Unknowns yk = 2.0 * step * Hd;
    X += sk;
    g += yk;
    const double sy = dot(sk, yk);
    if (sy <= 0) break;
    s.push_back(sk);
    y.push_back(yk);
    rho.push_back(1.0 / sy);
    if (static_cast<int>(s.size()) > kMemory) s.pop_front(), y.pop_front(), rho.pop_front();
  }
  return done;
}

void checkOptions(const TemplateFitOptions& o)
{
  if (o.stages.empty()) throw Error("Template fit: no stage given.");
  for (const auto& s : o.stages)
  {
    const double w[] = {s.correspondence, s.smoothness, s.nearest, s.temporal};
    for (double x : w)
      if (!(x >= 0) || !std::isfinite(x))
        throw Error("Template fit: stage weights must be finite and non-negative.");
    if (!(s.temporal > 0) && !(s.smoothness > 0))
      throw Error("Template fit: every stage needs a positive smoothness or temporal weight, "
                  "otherwise vertices without data are undetermined.");
  }
  if (o.roundsPerStage < 1) throw Error("Template fit: roundsPerStage must be at least 1.");
  if (!(o.lengthScale > 0 && std::isfinite(o.lengthScale)))
    throw Error("Template fit: the length scale must be positive.");
  if (!(o.solverTolerance > 0 && o.solverTolerance < 1) ||
      !(o.intermediateTolerance > 0 && o.intermediateTolerance < 1))
    throw Error("Template fit: the solver tolerances must be in (0, 1).");
  if (!(o.refactorSteps >= 0) || !std::isfinite(o.refactorSteps))
    throw Error("Template fit: refactorSteps must be 0 or more.");
  if (o.nearestEvery < 1) throw Error("Template fit: nearestEvery must be at least 1.");
  if (!(o.maxNearestDistance > 0)) throw Error("Template fit: maxNearestDistance must be > 0.");
  if (!(o.nearestReuse >= 0) || !std::isfinite(o.nearestReuse))
    throw Error("Template fit: nearestReuse must be 0 or more.");
  if (!(o.correspondenceOutlier >= 0))
    throw Error("Template fit: correspondenceOutlier must be >= 0.");
  if (!(o.maxNormalAngle > 0 && o.maxNormalAngle <= 180))
    throw Error("Template fit: maxNormalAngle must be in (0, 180] degrees.");
}
} // namespace

TemplateFitter::TemplateFitter(const TriangleMesh& templateMesh, const TemplateFitOptions& options)
    : options_(options)
{
  checkOptions(options_);
  validateMesh(templateMesh, "Template");
  impl_ = std::make_unique<Impl>(templateMesh);
  impl_->faces.resize(templateMesh.numFaces());
  for (int f = 0; f < templateMesh.numFaces(); ++f)
    impl_->faces[f] = {templateMesh.F(f, 0), templateMesh.F(f, 1), templateMesh.F(f, 2)};
}

TemplateFitter::~TemplateFitter() = default;

FrameFit TemplateFitter::fit(const Points& start, const TriangleMesh& frame,
                             const VertexTargets* targets) const
{
  const auto clock = std::chrono::steady_clock::now();
  const Impl& m = *impl_;
  const int n = m.n;
  if (start.rows() != n)
    throw Error("Template fit: the start positions have " + std::to_string(start.rows()) +
                " vertices, the template " + std::to_string(n) + ".");
  if (!start.allFinite()) throw Error("Template fit: the start positions are not finite.");
  validateMesh(frame, "Frame");
  if (targets && (targets->position.rows() != n || static_cast<int>(targets->matched.size()) != n))
    throw Error("Template fit: the correspondences do not have one entry per template vertex.");

  const Vec3 centroid = start.colwise().mean().transpose();
  // Lengths in the energy are in units of 1 / lengthScale metres (see the option).
  const double scale = options_.lengthScale;
  Eigen::Matrix<double, Eigen::Dynamic, 4> b(n, 4);
  b.leftCols<3>() = (start.rowwise() - centroid.transpose()) * scale;
  b.col(3).setOnes();

  FrameFit result;
  result.used.assign(n, 0);
  Points correspondence = Points::Zero(n, 3);
  if (targets && options_.useCorrespondence)
    for (int i = 0; i < n; ++i)
      if (targets->matched[i] && targets->position.row(i).allFinite())
      {
        result.used[i] = 1;
        correspondence.row(i) = (targets->position.row(i) - centroid.transpose()) * scale;
      }
  const int correspondenceCount =
      static_cast<int>(std::count(result.used.begin(), result.used.end(), 1));

  const SurfaceLocator locator(frame);
  const Points frameNormals = faceNormals(frame);
  const double minCosine = std::cos(options_.maxNormalAngle * M_PI / 180.0);
  std::vector<int> hint(n, -1);
  // Where each vertex was when its closest point was last searched for (nearestReuse).
  constexpr double kFar = std::numeric_limits<double>::infinity();
  Points searchedAt = Points::Constant(n, 3, kFar);
  std::vector<unsigned char> hasNearest(n, 0);
  Points nearest = Points::Zero(n, 3);
  TriangleMesh deformed;
  deformed.F.resize(static_cast<Eigen::Index>(m.faces.size()), 3);
  for (size_t f = 0; f < m.faces.size(); ++f)
    deformed.F.row(f) << m.faces[f][0], m.faces[f][1], m.faces[f][2];

  Unknowns X = identityMaps(n);
  auto positions = [&](const Unknowns& maps)
  {
    Points p(n, 3);
    for (int i = 0; i < n; ++i)
      p.row(i) = b.row(i) * maps.middleRows<4>(4 * static_cast<Eigen::Index>(i));
    return p;
  };
  const double reuse2 = options_.nearestReuse * options_.nearestReuse;
  std::atomic<int> searches{0};
  auto findNearest = [&](const Points& p)
  {
    deformed.V = p;
    const Points normals = areaWeightedVertexNormals(deformed);
    parallelFor(0, n,
                [&](int i)
                {
                  const Vec3 query = p.row(i).transpose() / scale + centroid;
                  SurfacePoint s;
                  if (hint[i] >= 0 &&
                      (query - searchedAt.row(i).transpose()).squaredNorm() < reuse2)
                  {
                    // Moved by d < nearestReuse since the search: that triangle is at most the
                    // old distance + d away, no point of the frame is nearer than the old - d.
                    const int f = hint[i];
                    s.position = closestPointOnTriangle(query, frame.vertex(frame.F(f, 0)),
                                                        frame.vertex(frame.F(f, 1)),
                                                        frame.vertex(frame.F(f, 2)), s.bary);
                    s.distance = (s.position - query).norm();
                    if (s.distance <= options_.maxNearestDistance) s.face = f;
                  }
                  if (!s.valid())
                  {
                    s = locator.closestPoint(query, options_.maxNearestDistance, hint[i]);
                    searches.fetch_add(1, std::memory_order_relaxed);
                    // A failed search leaves the hint as it was: nothing to reuse.
                    if (s.valid())
                      searchedAt.row(i) = query.transpose();
                    else
                      searchedAt.row(i).setConstant(kFar);
                  }
                  hasNearest[i] = 0;
                  if (!s.valid()) return;
                  hint[i] = s.face;
                  if (normals.row(i).dot(frameNormals.row(s.face)) <= minCosine) return;
                  hasNearest[i] = 1;
                  nearest.row(i) = (s.position - centroid).transpose() * scale;
                });
    return static_cast<int>(std::count(hasNearest.begin(), hasNearest.end(), 1));
  };

  // Correspondences in use: all of them, less the outliers of the fit so far (when asked).
  std::vector<unsigned char> active = result.used;
  int activeCount = correspondenceCount;
  bool firstRound = true;
  for (size_t stageIndex = 0; stageIndex < options_.stages.size(); ++stageIndex)
  {
    const FitStage& stage = options_.stages[stageIndex];
    const bool usesNearest = options_.useNearest && stage.nearest > 0;
    const double ws = m.neighbourCount > 0 ? stage.smoothness / m.neighbourCount : 0.0;
    const double wt = stage.temporal / n;
    const int rounds = usesNearest ? options_.roundsPerStage : 1;
    const int stepsBefore = result.iterations, roundsBefore = result.rounds;
    for (int round = 0; round < rounds; ++round)
    {
      Points before = positions(X);
      if (options_.correspondenceOutlier > 0 && !firstRound && stage.correspondence > 0)
      {
        activeCount = 0;
        for (int i = 0; i < n; ++i)
        {
          active[i] = result.used[i] && (before.row(i) - correspondence.row(i)).norm() <=
                                            options_.correspondenceOutlier * scale;
          activeCount += active[i];
        }
      }
      firstRound = false;
      const double wc = activeCount > 0 ? stage.correspondence / activeCount : 0.0;
      double wd = 0.0;
      if (usesNearest)
      {
        result.nearestValid = findNearest(before);
        wd = result.nearestValid > 0 ? stage.nearest / result.nearestValid : 0.0;
      }
      const Quadratic q =
          m.assemble(b, active, correspondence, wc, hasNearest, nearest, wd, ws, wt);
      if (options_.solver == FitSolver::Exact)
        result.iterations += m.solveExact(q, X, stageIndex,
                                          round + 1 == rounds ? options_.solverTolerance
                                                              : options_.intermediateTolerance,
                                          result.factorisations);
      else
        result.iterations += minimiseLBFGS(q, X, options_.nearestEvery);
      ++result.rounds;
      const double moved = (positions(X) - before).rowwise().norm().maxCoeff() / scale;
      const bool converged = options_.solver == FitSolver::Exact && moved < options_.convergence;
      if (converged || round + 1 == rounds) result.energy = q.energy(X);
      if (converged) break;
    }
    if (options_.solver == FitSolver::Exact && options_.refactorSteps > 0 &&
        result.iterations - stepsBefore > options_.refactorSteps * (result.rounds - roundsBefore))
      m.stale[stageIndex] = 1;
  }
  result.used = active;
  result.nearestSearches = searches;
  result.positions = (positions(X) / scale).rowwise() + centroid.transpose();
  if (!result.positions.allFinite()) throw Error("Template fit: the solve diverged.");
  result.surfaceDistance.resize(n);
  parallelFor(0, n,
              [&](int i)
              {
                result.surfaceDistance[i] =
                    locator
                        .closestPoint(result.positions.row(i).transpose(),
                                      std::numeric_limits<double>::infinity(), hint[i])
                        .distance;
              });
  result.seconds = seconds(clock);
  return result;
}

std::vector<FrameFit> fitTemplateSequence(const TriangleMesh& templateMesh, int templateFrame,
                                          int numFrames,
                                          const std::function<const TriangleMesh&(int)>& frame,
                                          const std::function<const VertexTargets*(int)>& targets,
                                          const TemplateFitOptions& options,
                                          const std::function<bool(int, int)>& progress,
                                          const StartPrediction& start)
{
  if (templateFrame < 0 || templateFrame >= numFrames)
    throw Error("Template fit: the template frame " + std::to_string(templateFrame) +
                " is not in the sequence of " + std::to_string(numFrames) + " frames.");
  std::vector<FrameFit> fits(numFrames);
  fits[templateFrame].positions = templateMesh.V;
  fits[templateFrame].used.assign(templateMesh.numVertices(), 0);
  fits[templateFrame].surfaceDistance = Eigen::VectorXd::Zero(templateMesh.numVertices());
  // The chains j-1 .. 0 and j+1 .. N-1 are independent: with more than one thread they run side
  // by side, each with its own fitter (a fitter keeps its factorisations). The callbacks are
  // called one at a time and what they return is copied before the lock is released; progress
  // is reported from the calling thread only.
  std::mutex mutex;
  std::condition_variable changed;
  bool stop = false;
  int done = 1, running = 0;
  std::exception_ptr failure;
  auto chain = [&](int from, int to, int direction, bool reportProgress)
  {
    try
    {
      const TemplateFitter fitter(templateMesh, options);
      for (int k = from; k != to; k += direction)
      {
        const int previous = k - direction;
        TriangleMesh frameK;
        std::optional<VertexTargets> targetsK;
        Points startK;
        {
          std::unique_lock<std::mutex> lock(mutex);
          if (stop) return;
          if (reportProgress)
          {
            const int reported = done;
            lock.unlock();
            if (progress && !progress(reported, numFrames)) throw Error("Template fit: cancelled.");
            lock.lock();
          }
          frameK = frame(k);
          if (const VertexTargets* t = targets(k)) targetsK = *t;
          startK = start ? start(k, previous, fits[previous].positions) : fits[previous].positions;
        }
        try
        {
          fits[k] = fitter.fit(startK, frameK, targetsK ? &*targetsK : nullptr);
        }
        catch (const Error& e)
        {
          throw Error("Frame " + std::to_string(k) + ": " + e.what());
        }
        const std::lock_guard<std::mutex> lock(mutex);
        ++done;
        changed.notify_all();
      }
    }
    catch (...)
    {
      const std::lock_guard<std::mutex> lock(mutex);
      if (!failure) failure = std::current_exception();
      stop = true;
    }
  };
  if (templateFrame > 0 && templateFrame + 1 < numFrames && threadCount() > 1)
  {
    auto worker = [&](int from, int to, int direction)
    {
      chain(from, to, direction, false);
      const std::lock_guard<std::mutex> lock(mutex);
      --running;
      changed.notify_all();
    };
    running = 2;
    std::thread backward(worker, templateFrame - 1, -1, -1);
    std::thread forward(worker, templateFrame + 1, numFrames, +1);
    std::unique_lock<std::mutex> lock(mutex);
    int reported = -1;
    while (running > 0)
    {
      if (done != reported && !stop)
      {
        reported = done;
        lock.unlock();
        const bool goOn = !progress || progress(reported, numFrames);
        lock.lock();
        if (!goOn && !stop)
        {
          failure = std::make_exception_ptr(Error("Template fit: cancelled."));
          stop = true;
        }
        continue;
      }
      changed.wait(lock);
    }
    lock.unlock();
    backward.join();
    forward.join();
  }
  else
  {
    chain(templateFrame - 1, -1, -1, true);
    chain(templateFrame + 1, numFrames, +1, true);
  }
  if (failure) std::rethrow_exception(failure);
  if (progress) progress(done, numFrames);
  return fits;
}
} // namespace clothtrack
