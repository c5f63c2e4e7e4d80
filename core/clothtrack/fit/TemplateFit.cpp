#include "TemplateFit.h"

#include "FitQuadratic.h"
#include "FitSolvers.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/correspondence/PatchCorrespondence.h>
#include <clothtrack/mesh/MeshTopology.h>
#include <clothtrack/mesh/MeshValidation.h>
#include <clothtrack/mesh/PointIndex.h>
#include <clothtrack/mesh/SurfaceLocator.h>
#include <clothtrack/solver/PreconditionerFactor.h>

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
double seconds(std::chrono::steady_clock::time_point since)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

/// The frame-to-template pairs of one round: every frame vertex paired with its nearest template
/// vertex, summed per template vertex (a vertex may be the nearest of several frame vertices).
struct CoverageTargets
{
  std::vector<int> count;      ///< frame vertices paired with each template vertex
  Points sum;                  ///< their positions, summed
  std::vector<double> squares; ///< their squared norms, summed
  int pairs = 0;
};

/// Pairs closer than maxDistance whose normals are less than acos(minCosine) apart.
CoverageTargets coverageTargets(const Points& templatePositions, const Points& templateNormals,
                                const Points& framePositions, const Points& frameNormals,
                                double maxDistance, double minCosine)
{
  const int n = static_cast<int>(templatePositions.rows());
  const int frameVertices = static_cast<int>(framePositions.rows());
  const PointIndex index(templatePositions);
  std::vector<int> partner(frameVertices, -1);
  parallelFor(0, frameVertices,
              [&](int j)
              {
                const Neighbour nb = index.nearest(framePositions.row(j).transpose());
                if (nb.index < 0 || nb.distance > maxDistance) return;
                if (templateNormals.row(nb.index).dot(frameNormals.row(j)) <= minCosine) return;
                partner[j] = nb.index;
              });
  CoverageTargets t;
  t.count.assign(n, 0);
  t.sum = Points::Zero(n, 3);
  t.squares.assign(n, 0.0);
  for (int j = 0; j < frameVertices; ++j)
  {
    const int i = partner[j];
    if (i < 0) continue;
    ++t.count[i];
    t.sum.row(i) += framePositions.row(j);
    t.squares[i] += framePositions.row(j).squaredNorm();
    ++t.pairs;
  }
  return t;
}

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
  Adjacency neighbours;   // the template's vertex adjacency (MeshTopology::vertexVertices)
  int neighbourCount = 0; // sum of |N(i)|
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
  mutable std::vector<std::unique_ptr<PreconditionerFactor>> factors;
  mutable std::vector<unsigned char> stale; // per stage: renew the factor at its next round
  // Per stage, the matrix each factor was made from (TemplateFitterState), so that another
  // fitter can make the same factor.
  mutable std::vector<TemplateFitterState::Stage> factored;
  mutable Unknowns scratch[4];

  FactorBackend backend = FactorBackend::Block;

  Impl(const TriangleMesh& mesh, FactorBackend factorBackend) : backend(factorBackend)
  {
    n = mesh.numVertices();
    const MeshTopology topology = buildTopology(mesh);
    edges = topology.edges;
    neighbours = topology.vertexVertices;
    neighbourCount = static_cast<int>(neighbours.items.size());
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
  int solveExact(const Quadratic& q, Unknowns& X, size_t stage, double tolerance, FrameFit& stats,
                 bool mayRefactor = true) const
  {
    constexpr int kMaxSteps = 20; // conjugate-gradient steps before the factor is renewed
    growStages(stage + 1);
    std::unique_ptr<PreconditionerFactor>& factor = factors[stage];
    auto refactor = [&]()
    {
      const auto start = std::chrono::steady_clock::now();
      TemplateFitterState::Stage& record = factored[stage];
      record.factored = true;
      record.edgeWeight = q.edgeWeight;
      record.blocks.resize(10 * static_cast<size_t>(n));
      for (int i = 0; i < n; ++i)
      {
        int k = 0;
        for (int r = 0; r < 4; ++r)
          for (int c = 0; c <= r; ++c)
            record.blocks[10 * static_cast<size_t>(i) + k++] = q.diagonal[i](r, c);
      }
      factorise(stage);
      ++stats.factorisations;
      stats.factorSeconds += seconds(start);
    };
    if (!factor || stale[stage]) refactor();
    stale[stage] = 0;
    const double target = tolerance * q.R.norm();
    Unknowns* work[4] = {&scratch[0], &scratch[1], &scratch[2], &scratch[3]};
    double rr = 0;
    const auto start = std::chrono::steady_clock::now();
    const int step = conjugateGradients(q, *factor, target, kMaxSteps, X, work, rr);
    stats.solveSeconds += seconds(start);
    if (std::sqrt(rr) > target && mayRefactor)
    {
      // Too far from the factored matrix: renew the factor and finish from here.
      refactor();
      return step + solveExact(q, X, stage, tolerance, stats, false);
    }
    return step;
  }

  void growStages(size_t count) const
  {
    if (factors.size() >= count) return;
    factors.resize(count);
    stale.resize(count, 0);
    factored.resize(count);
  }

  /// Factorises the matrix recorded for `stage` (factored[stage]).
  void factorise(size_t stage) const
  {
    std::unique_ptr<PreconditionerFactor>& factor = factors[stage];
    if (!factor) factor = makeFactor(backend, pattern);
    try
    {
      factor->factorise(normalMatrix(factored[stage]));
    }
    catch (const Error&)
    {
      factor.reset(); // the next round starts afresh
      factored[stage] = {};
      throw Error("Template fit: the normal equations are not positive definite.");
    }
  }

  /// H (lower triangle) from its diagonal blocks and edge weight, for factorisation.
  SparseMatrix normalMatrix(const TemplateFitterState::Stage& record) const
  {
    SparseMatrix H = pattern;
    double* values = H.valuePtr();
    for (size_t e = 0; e < edges.size(); ++e)
      for (int r = 0; r < 4; ++r) values[edgeSlots[e][r]] = -record.edgeWeight;
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < 10; ++k)
        values[diagonalSlots[i][k]] = record.blocks[10 * static_cast<size_t>(i) + k];
    return H;
  }

  /// The quadratic of one round. `b` holds [t_i - centroid; 1]; targets are relative to the
  /// centroid too; weights already include the 1/count normalisations.
  Quadratic assemble(const Eigen::Matrix<double, Eigen::Dynamic, 4>& b,
                     const std::vector<unsigned char>& hasCorrespondence,
                     const Points& correspondence, double correspondenceWeight,
                     const std::vector<unsigned char>& hasNearest, const Points& nearest,
                     double nearestWeight, const CoverageTargets& coverage, double coverageWeight,
                     double smoothnessWeight, double temporalWeight) const
  {
    Quadratic q;
    q.R = Unknowns::Zero(4 * static_cast<Eigen::Index>(n), 3);
    // Each neighbour pair appears twice in sum_i sum_{j in N(i)}, hence the factor 2.
    const double edgeWeight = 2.0 * smoothnessWeight;
    q.edgeWeight = edgeWeight;
    q.neighbours = &neighbours;
    q.diagonal.resize(n);
    std::vector<double> constant(n, 0.0);
    parallelFor(0, n,
                [&](int i)
                {
                  Eigen::Matrix4d block = Eigen::Matrix4d::Identity() *
                                          (edgeWeight * neighbours.degree(i) + temporalWeight);
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
                  if (coverageWeight > 0 && coverage.count[i] > 0)
                  {
                    // sum_j w |A_i t_i - f_j|^2 over the frame vertices f_j paired with i.
                    block += coverageWeight * coverage.count[i] * bi * bi.transpose();
                    rhs += coverageWeight * bi * coverage.sum.row(i);
                    c += coverageWeight * coverage.squares[i];
                  }
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
  if (!(o.maximumNearestDistance > 0))
    throw Error("Template fit: maximumNearestDistance must be > 0.");
  if (!(o.nearestReuse >= 0) || !std::isfinite(o.nearestReuse))
    throw Error("Template fit: nearestReuse must be 0 or more.");
  if (!(o.correspondenceOutlier >= 0))
    throw Error("Template fit: correspondenceOutlier must be >= 0.");
  if (!(o.coverageWeight >= 0) || !std::isfinite(o.coverageWeight))
    throw Error("Template fit: coverageWeight must be 0 or more.");
  if (!(o.maximumNormalAngle > 0 && o.maximumNormalAngle <= 180))
    throw Error("Template fit: maximumNormalAngle must be in (0, 180] degrees.");
}
} // namespace

TemplateFitter::TemplateFitter(const TriangleMesh& templateMesh, const TemplateFitOptions& options)
    : options_(options)
{
  checkOptions(options_);
  validateMesh(templateMesh, "Template");
  impl_ = std::make_unique<Impl>(templateMesh, options_.factorBackend);
  impl_->faces.resize(templateMesh.numFaces());
  for (int f = 0; f < templateMesh.numFaces(); ++f)
    impl_->faces[f] = {templateMesh.F(f, 0), templateMesh.F(f, 1), templateMesh.F(f, 2)};
}

TemplateFitter::~TemplateFitter() = default;

TemplateFitterState TemplateFitter::state() const
{
  const Impl& m = *impl_;
  TemplateFitterState state;
  state.vertices = m.n;
  state.stages = m.factored;
  for (size_t s = 0; s < state.stages.size(); ++s) state.stages[s].stale = m.stale[s] != 0;
  return state;
}

void TemplateFitter::restore(const TemplateFitterState& state)
{
  Impl& m = *impl_;
  // Whatever goes wrong leaves a fitter without factorisations, which starts afresh.
  auto forget = [&m]()
  {
    m.factors.clear();
    m.stale.clear();
    m.factored.clear();
  };
  forget();
  if (state.vertices != m.n)
    throw Error("Template fit: the solver state was made for " + std::to_string(state.vertices) +
                " template vertices, this template has " + std::to_string(m.n) + ".");
  m.growStages(state.stages.size());
  for (size_t s = 0; s < state.stages.size(); ++s)
  {
    const TemplateFitterState::Stage& stage = state.stages[s];
    if (!stage.factored) continue;
    const bool finite =
        std::isfinite(stage.edgeWeight) && std::all_of(stage.blocks.begin(), stage.blocks.end(),
                                                       [](double x) { return std::isfinite(x); });
    if (stage.blocks.size() != 10 * static_cast<size_t>(m.n) || !finite)
    {
      forget();
      throw Error("Template fit: the solver state of stage " + std::to_string(s + 1) +
                  " is not a matrix of this template.");
    }
    m.factored[s] = stage;
    m.stale[s] = stage.stale;
    try
    {
      m.factorise(s);
    }
    catch (const Error&)
    {
      forget();
      throw;
    }
  }
}

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
  const bool usesCoverage = options_.useNearest && options_.coverageWeight > 0;
  const Points frameScaled =
      usesCoverage ? Points((frame.V.rowwise() - centroid.transpose()) * scale) : Points();
  const Points frameVertexNormals = usesCoverage ? areaWeightedVertexNormals(frame) : Points();
  CoverageTargets coverage;
  coverage.count.assign(n, 0);
  const double minCosine = std::cos(options_.maximumNormalAngle * M_PI / 180.0);
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
  // `normals`: the template's vertex normals at positions p.
  auto findNearest = [&](const Points& p, const Points& normals)
  {
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
                    if (s.distance <= options_.maximumNearestDistance) s.face = f;
                  }
                  if (!s.valid())
                  {
                    s = locator.closestPoint(query, options_.maximumNearestDistance, hint[i]);
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
      double wd = 0.0, wb = 0.0;
      if (usesNearest)
      {
        deformed.V = before;
        const Points normals = areaWeightedVertexNormals(deformed);
        result.nearestValid = findNearest(before, normals);
        wd = result.nearestValid > 0 ? stage.nearest / result.nearestValid : 0.0;
        if (usesCoverage)
        {
          coverage = coverageTargets(before, normals, frameScaled, frameVertexNormals,
                                     options_.maximumNearestDistance * scale, minCosine);
          wb = coverage.pairs > 0 ? stage.nearest * options_.coverageWeight / coverage.pairs : 0.0;
        }
      }
      const Quadratic q =
          m.assemble(b, active, correspondence, wc, hasNearest, nearest, wd, coverage, wb, ws, wt);
      if (options_.solver == FitSolver::Exact)
        result.iterations += m.solveExact(q, X, stageIndex,
                                          round + 1 == rounds ? options_.solverTolerance
                                                              : options_.intermediateTolerance,
                                          result);
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
  result.meanSurfaceDistance = n > 0 ? result.surfaceDistance.mean() : 0.0;
  result.seconds = seconds(clock);
  return result;
}

} // namespace clothtrack
