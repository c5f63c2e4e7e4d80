#include "PatchCorrespondence.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>
#include <clothtrack/mesh/Geodesic.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

namespace clothtrack
{
double FrameCorrespondence::matchedFraction() const
{
  if (vertices.empty()) return 0.0;
  int matched = 0;
  for (const auto& v : vertices) matched += v.matched();
  return static_cast<double>(matched) / vertices.size();
}

namespace
{
constexpr double kInf = std::numeric_limits<double>::infinity();

void checkLandmark(const TriangleMesh& mesh, const OrientedSurfacePoint& l, const char* where)
{
  if (l.face < 0 || l.face >= mesh.numFaces())
    throw Error(std::string("patch correspondence: ") + where + " landmark " +
                std::to_string(l.id) + " lies on face " + std::to_string(l.face) +
                ", out of range");
  if (!l.direction.allFinite() || !l.bary.allFinite())
    throw Error(std::string("patch correspondence: ") + where + " landmark " +
                std::to_string(l.id) + " has a non-finite direction or barycentric");
}

/// Geodesic distance at a surface point, interpolated from vertex distances.
double distanceAt(const TriangleMesh& mesh, const Eigen::VectorXd& d, int face, const Vec3& bary)
{
  double sum = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double dk = d[mesh.F(face, k)];
    if (!std::isfinite(dk)) return kInf;
    sum += bary[k] * dk;
  }
  return sum;
}

/// Chart index of each mesh vertex in a polar chart.
using ChartIndex = std::unordered_map<int, int>;

ChartIndex chartIndex(const PolarPatch& chart)
{
  ChartIndex local;
  for (size_t k = 0; k < chart.vertices.size(); ++k) local[chart.vertices[k]] = static_cast<int>(k);
  return local;
}

/// Point location in a polar chart: the chart's triangles laid out in the plane, bucketed in a
/// uniform grid.
class ChartLocator
{
public:
  ChartLocator(const TriangleMesh& mesh, const MeshTopology& topology, const PolarPatch& chart)
      : chart_(chart)
  {
    const ChartIndex local = chartIndex(chart);
    // Faces with all three corners in the chart.
    std::vector<int> seen;
    for (int v : chart.vertices)
      for (const int* f = topology.vertexFaces.begin(v); f != topology.vertexFaces.end(v); ++f)
        seen.push_back(*f);
    std::sort(seen.begin(), seen.end());
    seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
    double edge = 0.0;
    for (int f : seen)
    {
      std::array<int, 3> c;
      bool inside = true;
      for (int k = 0; k < 3 && inside; ++k)
      {
        const auto it = local.find(mesh.F(f, k));
        inside = it != local.end();
        if (inside) c[k] = static_cast<int>(it->second);
      }
      if (!inside) continue;
      faces_.push_back(f);
      corners_.push_back(c);
      edge += (chart_.coordinates[c[1]] - chart_.coordinates[c[0]]).norm();
    }
    if (faces_.empty()) return;
    lo_ = hi_ = chart_.coordinates[corners_[0][0]];
    for (const auto& c : corners_)
      for (int k = 0; k < 3; ++k)
      {
        lo_ = lo_.cwiseMin(chart_.coordinates[c[k]]);
        hi_ = hi_.cwiseMax(chart_.coordinates[c[k]]);
      }
    cell_ = std::max(1e-6, 2.0 * edge / faces_.size());
    nx_ = std::max(1, std::min(512, static_cast<int>((hi_.x() - lo_.x()) / cell_) + 1));
    ny_ = std::max(1, std::min(512, static_cast<int>((hi_.y() - lo_.y()) / cell_) + 1));
    cells_.assign(static_cast<size_t>(nx_) * ny_, {});
    for (size_t t = 0; t < corners_.size(); ++t)
    {
      Eigen::Vector2d a = chart_.coordinates[corners_[t][0]], b = a;
      for (int k = 1; k < 3; ++k)
      {
        a = a.cwiseMin(chart_.coordinates[corners_[t][k]]);
        b = b.cwiseMax(chart_.coordinates[corners_[t][k]]);
      }
      const auto [x0, y0] = cellOf(a);
      const auto [x1, y1] = cellOf(b);
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) cells_[static_cast<size_t>(y) * nx_ + x].push_back(t);
    }
  }

  /// The chart triangle containing `uv`; where the chart folds over itself, the one whose
  /// geodesic distance from the seed is closest to `radius`. False outside the chart.
  bool locate(const Eigen::Vector2d& uv, double radius, int& face, Vec3& bary) const
  {
    if (faces_.empty()) return false;
    const auto [x, y] = cellOf(uv);
    if (uv.x() < lo_.x() || uv.y() < lo_.y() || uv.x() > hi_.x() || uv.y() > hi_.y()) return false;
    double best = kInf;
    for (int t : cells_[static_cast<size_t>(y) * nx_ + x])
    {
      const auto& c = corners_[t];
      const Eigen::Vector2d a = chart_.coordinates[c[0]], e1 = chart_.coordinates[c[1]] - a,
                            e2 = chart_.coordinates[c[2]] - a, q = uv - a;
      const double det = e1.x() * e2.y() - e1.y() * e2.x();
      if (std::abs(det) < 1e-18) continue;
      const double l1 = (q.x() * e2.y() - q.y() * e2.x()) / det;
      const double l2 = (e1.x() * q.y() - e1.y() * q.x()) / det;
      const double l0 = 1.0 - l1 - l2;
      const double tol = -1e-9;
      if (l0 < tol || l1 < tol || l2 < tol) continue;
      const double r =
          l0 * chart_.distances[c[0]] + l1 * chart_.distances[c[1]] + l2 * chart_.distances[c[2]];
      const double mismatch = std::abs(r - radius);
      if (mismatch < best)
      {
        best = mismatch;
        face = faces_[t];
        bary = Vec3(l0, l1, l2); // corners are stored in the mesh's own order
      }
    }
    return best < kInf;
  }

private:
  std::pair<int, int> cellOf(const Eigen::Vector2d& p) const
  {
    const int x = std::clamp(static_cast<int>((p.x() - lo_.x()) / cell_), 0, nx_ - 1);
    const int y = std::clamp(static_cast<int>((p.y() - lo_.y()) / cell_), 0, ny_ - 1);
    return {x, y};
  }

  const PolarPatch& chart_;
  std::vector<int> faces_;
  std::vector<std::array<int, 3>> corners_;
  Eigen::Vector2d lo_ = Eigen::Vector2d::Zero(), hi_ = Eigen::Vector2d::Zero();
  double cell_ = 1.0;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> cells_;
};

struct Assignment
{
  int patch;
  int face;
  Vec3 bary;
  Vec3 position;
};
} // namespace

/// The template side of one landmark's patch.
struct TemplatePatches::Patch
{
  OrientedSurfacePoint landmark;
  PolarPatch disc;                                  ///< template vertices within tau_d
  std::vector<int> anchors;                         ///< indices into disc
  std::vector<std::vector<double>> anchorDistances; ///< per anchor, per disc vertex
  std::vector<std::vector<int>> neighbours;         ///< disc adjacency (indices into disc)
  std::vector<int> start;                           ///< disc indices growth starts from
};

TemplatePatches::TemplatePatches(const TriangleMesh& templateMesh,
                                 const std::vector<OrientedSurfacePoint>& landmarks,
                                 const PatchCorrespondenceOptions& options)
    : mesh_(templateMesh), options_(options)
{
  if (templateMesh.numFaces() == 0) throw Error("patch correspondence: the template is empty");
  if (!(options.maximumRadius > 0) || !(options.epsilon > 0) || options.minimumRadius < 0)
    throw Error("patch correspondence: radii and tolerance must be positive");
  for (const auto& l : landmarks) checkLandmark(templateMesh, l, "template");
  const ExponentialMapper mapper(templateMesh);
  patches_.resize(landmarks.size());
  parallelFor(
      0, static_cast<int>(landmarks.size()),
      [&](int i)
      {
        auto patch = std::make_unique<Patch>();
        patch->landmark = landmarks[i];
        if (std::abs(landmarks[i].offset) > options_.maximumSeedOffset)
        {
          patches_[i] = std::move(patch); // seeds nothing: no disc
          return;
        }
        try
        {
          patch->disc = mapper.map(landmarks[i].face, landmarks[i].bary, landmarks[i].direction,
                                   options_.maximumRadius);
        }
        catch (const Error&)
        {
          patch->disc = {}; // degenerate seed triangle or direction along the normal
        }
        const PolarPatch& disc = patch->disc;
        const int n = static_cast<int>(disc.vertices.size());
        const ChartIndex local = chartIndex(disc);
        patch->neighbours.resize(n);
        for (int k = 0; k < n; ++k)
        {
          const int v = disc.vertices[k];
          for (const int* w = mapper.topology().vertexVertices.begin(v);
               w != mapper.topology().vertexVertices.end(v); ++w)
          {
            const auto it = local.find(*w);
            if (it != local.end()) patch->neighbours[k].push_back(it->second);
          }
        }
        for (int c = 0; c < 3; ++c)
        {
          const auto it = local.find(templateMesh.F(landmarks[i].face, c));
          if (it != local.end()) patch->start.push_back(it->second);
        }
        // Anchors: around the seed at half the radius, evenly in angle.
        for (int a = 0; a < options_.numberOfAnchors && n > 0; ++a)
        {
          const double angle = 2.0 * M_PI * a / options_.numberOfAnchors;
          const Eigen::Vector2d target =
              0.5 * options_.maximumRadius * Eigen::Vector2d(std::cos(angle), std::sin(angle));
          int best = -1;
          for (int k = 0; k < n; ++k)
            if (best < 0 ||
                (disc.coordinates[k] - target).norm() < (disc.coordinates[best] - target).norm())
              best = k;
          if ((disc.coordinates[best] - target).norm() > 0.25 * options_.maximumRadius) continue;
          if (std::find(patch->anchors.begin(), patch->anchors.end(), best) != patch->anchors.end())
            continue;
          std::vector<int> reached;
          const Eigen::VectorXd d = mapper.geodesic().distancesFromSeeds(
              {{disc.vertices[best], 0.0}}, 2.0 * options_.maximumRadius, reached);
          std::vector<double> onDisc(n);
          for (int k = 0; k < n; ++k) onDisc[k] = d[disc.vertices[k]];
          patch->anchors.push_back(best);
          patch->anchorDistances.push_back(std::move(onDisc));
        }
        patches_[i] = std::move(patch);
      },
      1);
  const int m = static_cast<int>(landmarks.size());
  seedDistances_ = Eigen::MatrixXd::Constant(m, m, kInf);
  if (options_.minimumSeedConsensus > 0)
    parallelFor(0, m,
                [&](int i)
                {
                  std::vector<int> reached;
                  const Eigen::VectorXd d = mapper.geodesic().distancesFromSeeds(
                      seedsAtSurfacePoint(templateMesh, landmarks[i].face, landmarks[i].bary),
                      options_.seedConsensusRadius, reached);
                  for (int j = 0; j < m; ++j)
                    seedDistances_(i, j) =
                        distanceAt(templateMesh, d, landmarks[j].face, landmarks[j].bary);
                });
}

TemplatePatches::~TemplatePatches() = default;

double TemplatePatches::seedFieldReach() const
{
  return options_.chartMargin * options_.maximumRadius + options_.epsilon;
}

void TemplatePatches::voteOnSeeds(const TriangleMesh& frame, const ExponentialMapper& mapper,
                                  const std::vector<const OrientedSurfacePoint*>& images,
                                  std::vector<PatchSummary>& summaries,
                                  std::vector<Eigen::VectorXd>& fields) const
{
  const int m = static_cast<int>(images.size());
  // Geodesic distances between the seeds' images on the frame, for the pairs that vote. Beyond
  // the voting reach every pair disagrees, so a field reaching further (for the patch) gives the
  // same votes.
  const double reach =
      std::max(seedFieldReach(),
               options_.seedConsensusRadius * (1.0 + options_.seedConsensusRelativeTolerance) +
                   options_.seedConsensusTolerance);
  Eigen::MatrixXd agree = Eigen::MatrixXd::Zero(m, m); // 1 agree, 0 disagree, -1 no vote
  parallelFor(
      0, m,
      [&](int i)
      {
        agree.col(i).setConstant(-1);
        if (!images[i]) return;
        std::vector<int> reached;
        fields[i] = mapper.geodesic().distancesFromSeeds(
            seedsAtSurfacePoint(frame, images[i]->face, images[i]->bary), reach, reached);
        const Eigen::VectorXd& d = fields[i];
        for (int j = 0; j < m; ++j)
        {
          const double dT = seedDistances_(i, j);
          if (j == i || !images[j] || !std::isfinite(dT)) continue;
          const double dS = distanceAt(frame, d, images[j]->face, images[j]->bary);
          agree(j, i) = std::abs(dS - dT) <= options_.seedConsensusTolerance +
                                                 options_.seedConsensusRelativeTolerance * dT;
        }
      },
      1);
  // Fast marching is not exactly symmetric: a pair agrees when both directions do.
  for (int i = 0; i < m; ++i)
    for (int j = 0; j < i; ++j)
      if (agree(i, j) >= 0 && agree(j, i) >= 0)
        agree(i, j) = agree(j, i) = std::min(agree(i, j), agree(j, i));
  // Drop the seed with the least consensus, one at a time, so that a misplaced seed does not
  // cost a right one with few neighbours its vote.
  std::vector<char> active(m);
  for (int i = 0; i < m; ++i) active[i] = images[i] != nullptr;
  for (;;)
  {
    int worst = -1;
    for (int i = 0; i < m; ++i)
    {
      if (!active[i]) continue;
      int voters = 0, agreeing = 0;
      for (int j = 0; j < m; ++j)
        if (active[j] && agree(i, j) >= 0) ++voters, agreeing += agree(i, j) > 0;
      summaries[i].consensus = voters ? static_cast<double>(agreeing) / voters : -1.0;
      if (voters >= 3 && summaries[i].consensus < options_.minimumSeedConsensus &&
          (worst < 0 || summaries[i].consensus < summaries[worst].consensus))
        worst = i;
    }
    if (worst < 0) break;
    summaries[worst].outvoted = true;
    active[worst] = 0;
  }
}

FrameCorrespondence
TemplatePatches::correspond(const TriangleMesh& frame,
                            const std::vector<OrientedSurfacePoint>& frameLandmarks) const
{
  if (frame.numFaces() == 0) throw Error("patch correspondence: the frame is empty");
  for (const auto& l : frameLandmarks) checkLandmark(frame, l, "frame");
  const ExponentialMapper mapper(frame);
  const double eps = options_.epsilon;

  FrameCorrespondence result;
  result.vertices.resize(mesh_.numVertices());
  result.patches.resize(patches_.size());
  std::vector<std::vector<Assignment>> perPatch(patches_.size());

  // The frame's image of each template seed (null when the frame lacks it or it lies off the
  // body), and the seeds that disagree with the geodesic distances between the others.
  const int m = static_cast<int>(patches_.size());
  std::vector<const OrientedSurfacePoint*> images(m, nullptr);
  for (int i = 0; i < m; ++i)
  {
    const auto image = std::find_if(frameLandmarks.begin(), frameLandmarks.end(),
                                    [&](const OrientedSurfacePoint& l)
                                    { return l.id == patches_[i]->landmark.id; });
    if (image != frameLandmarks.end() && std::abs(image->offset) <= options_.maximumSeedOffset &&
        std::abs(patches_[i]->landmark.offset) <= options_.maximumSeedOffset)
      images[i] = &*image;
  }
  std::vector<Eigen::VectorXd> seedFields(m);
  if (options_.minimumSeedConsensus > 0)
    voteOnSeeds(frame, mapper, images, result.patches, seedFields);
  parallelFor(
      0, static_cast<int>(patches_.size()),
      [&](int i)
      {
        const Patch& patch = *patches_[i];
        PatchSummary& summary = result.patches[i];
        summary.landmarkId = patch.landmark.id;
        const OrientedSurfacePoint* image = images[i];
        const int n = static_cast<int>(patch.disc.vertices.size());
        if (!image || n == 0 || summary.outvoted) return;
        PolarPatch chart;
        try
        {
          chart = mapper.map(image->face, image->bary, image->direction,
                             options_.chartMargin * options_.maximumRadius);
        }
        catch (const Error&)
        {
          return;
        }
        const ChartLocator locator(frame, mapper.topology(), chart);

        // f(t) by equal polar coordinates; then the near-isometry test against the seed.
        std::vector<int> face(n, -1);
        std::vector<Vec3> bary(n, Vec3::Zero());
        std::vector<char> consistent(n, 0);
        for (int k = 0; k < n; ++k)
        {
          if (!locator.locate(patch.disc.coordinates[k], patch.disc.distances[k], face[k], bary[k]))
          {
            face[k] = -1;
            continue;
          }
          consistent[k] = 1;
        }
        // Geodesic distances on the frame from the seed's image (the vote's, when it took one).
        std::vector<int> reached;
        if (seedFields[i].size() == 0)
          seedFields[i] = mapper.geodesic().distancesFromSeeds(
              seedsAtSurfacePoint(frame, image->face, image->bary), seedFieldReach(), reached);
        const Eigen::VectorXd& fromSeed = seedFields[i];
        for (int k = 0; k < n; ++k)
          if (consistent[k] && !(std::abs(distanceAt(frame, fromSeed, face[k], bary[k]) -
                                          patch.disc.distances[k]) <= eps))
            consistent[k] = 0;
        // ... and against each anchor whose own image passed.
        for (size_t a = 0; a < patch.anchors.size(); ++a)
        {
          const int anchor = patch.anchors[a];
          if (!consistent[anchor]) continue;
          const Eigen::VectorXd d = mapper.geodesic().distancesFromSeeds(
              seedsAtSurfacePoint(frame, face[anchor], bary[anchor]),
              2.0 * options_.maximumRadius + eps, reached);
          for (int k = 0; k < n; ++k)
            if (consistent[k] && std::isfinite(patch.anchorDistances[a][k]) &&
                !(std::abs(distanceAt(frame, d, face[k], bary[k]) - patch.anchorDistances[a][k]) <=
                  eps))
              consistent[k] = 0;
        }
        // Growth from the seed through consistent vertices only.
        std::vector<char> accepted(n, 0);
        std::vector<int> queue;
        for (int s : patch.start)
          if (consistent[s] && !accepted[s]) accepted[s] = 1, queue.push_back(s);
        for (size_t q = 0; q < queue.size(); ++q)
          for (int w : patch.neighbours[queue[q]])
            if (consistent[w] && !accepted[w]) accepted[w] = 1, queue.push_back(w);
        for (int k = 0; k < n; ++k)
        {
          summary.inconsistent += !consistent[k];
          if (!accepted[k]) continue;
          ++summary.vertices;
          summary.radius = std::max(summary.radius, patch.disc.distances[k]);
        }
        summary.kept = summary.vertices > 0 && summary.radius >= options_.minimumRadius;
        if (!summary.kept) return;
        for (int k = 0; k < n; ++k)
          if (accepted[k])
            perPatch[i].push_back({patch.disc.vertices[k], face[k], bary[k],
                                   surfacePosition(frame, face[k], bary[k])});
      },
      1);

  // Merge: per template vertex, the medoid of its assignments (the one with the least sum of
  // squared distances to the others), then the mean of the assignments that agree with it,
  // projected back onto the frame. Assignments that agree lie within a few centimetres, where
  // the extrinsic mean projected onto the surface approximates the geodesic (Karcher) mean;
  // the medoid step keeps a stray patch from pulling the result between two limbs.
  std::vector<std::vector<std::pair<int, const Assignment*>>> byVertex(mesh_.numVertices());
  for (size_t i = 0; i < perPatch.size(); ++i)
    for (const Assignment& a : perPatch[i]) byVertex[a.patch].push_back({static_cast<int>(i), &a});
  const SurfaceLocator frameLocator(frame);
  parallelFor(0, mesh_.numVertices(),
              [&](int v)
              {
                const auto& list = byVertex[v];
                if (list.empty()) return;
                VertexMatch& match = result.vertices[v];
                match.patches = static_cast<int>(list.size());
                size_t medoid = 0;
                double bestCost = kInf;
                for (size_t a = 0; a < list.size(); ++a)
                {
                  double cost = 0.0;
                  for (const auto& b : list)
                    cost += (list[a].second->position - b.second->position).squaredNorm();
                  if (cost < bestCost) bestCost = cost, medoid = a;
                }
                Vec3 mean = Vec3::Zero();
                int count = 0;
                for (const auto& b : list)
                  if ((b.second->position - list[medoid].second->position).norm() <=
                      options_.agreement)
                    mean += b.second->position, ++count;
                mean /= count;
                if (count == 1)
                {
                  match.face = list[medoid].second->face;
                  match.bary = list[medoid].second->bary;
                  match.position = list[medoid].second->position;
                }
                else
                {
                  const SurfacePoint p = frameLocator.closestPoint(mean);
                  match.face = p.face;
                  match.bary = p.bary;
                  match.position = p.position;
                }
                double spread = 0.0, nearest = kInf;
                for (const auto& b : list)
                {
                  const double d = (b.second->position - match.position).norm();
                  spread += d * d;
                  if (d < nearest) nearest = d, match.patchId = patches_[b.first]->landmark.id;
                }
                match.spread = std::sqrt(spread / list.size());
              });
  return result;
}

FrameCorrespondence rigidNearestCorrespondence(
    const TriangleMesh& templateMesh, const std::vector<OrientedSurfacePoint>& templateLandmarks,
    const TriangleMesh& frame, const std::vector<OrientedSurfacePoint>& frameLandmarks)
{
  if (templateMesh.numFaces() == 0 || frame.numFaces() == 0)
    throw Error("rigid correspondence: empty template or frame");
  std::vector<Vec3> from, to;
  for (const auto& t : templateLandmarks)
  {
    checkLandmark(templateMesh, t, "template");
    for (const auto& s : frameLandmarks)
      if (s.id == t.id)
      {
        checkLandmark(frame, s, "frame");
        from.push_back(surfacePosition(templateMesh, t.face, t.bary));
        to.push_back(surfacePosition(frame, s.face, s.bary));
      }
  }
  Eigen::Matrix4d transform = Eigen::Matrix4d::Identity();
  if (from.size() >= 3)
  {
    Eigen::Matrix3Xd a(3, from.size()), b(3, to.size());
    for (size_t k = 0; k < from.size(); ++k) a.col(k) = from[k], b.col(k) = to[k];
    transform = Eigen::umeyama(a, b, false);
  }
  const SurfaceLocator locator(frame);
  FrameCorrespondence result;
  result.vertices.resize(templateMesh.numVertices());
  parallelFor(0, templateMesh.numVertices(),
              [&](int v)
              {
                const Vec3 p = transform.topLeftCorner<3, 3>() * templateMesh.vertex(v) +
                               transform.topRightCorner<3, 1>();
                const SurfacePoint q = locator.closestPoint(p);
                VertexMatch& m = result.vertices[v];
                m.face = q.face;
                m.bary = q.bary;
                m.position = q.position;
                m.patches = 1;
              });
  return result;
}
} // namespace clothtrack
