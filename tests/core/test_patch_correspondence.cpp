// Geodesic-patch correspondence on surfaces with a known answer.
#include <clothtrack/base/Error.h>
#include <clothtrack/correspondence/PatchCorrespondence.h>
#include <clothtrack/mesh/Primitives.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <numeric>
#include <random>

using namespace clothtrack;

namespace
{
/// A rigidly moved copy of `mesh` with its vertices and faces in another order; `faceMap[f]`
/// is the copy's index of face f, its corners rotated by `shift`.
struct MovedCopy
{
  TriangleMesh mesh;
  std::vector<int> faceMap;
  int shift = 1;
};

MovedCopy movedCopy(const TriangleMesh& mesh, const Eigen::Matrix3d& rotation, const Vec3& move)
{
  std::mt19937 random(3);
  std::vector<int> vertexMap(mesh.numVertices()), faceMap(mesh.numFaces());
  std::iota(vertexMap.begin(), vertexMap.end(), 0);
  std::iota(faceMap.begin(), faceMap.end(), 0);
  std::shuffle(vertexMap.begin(), vertexMap.end(), random);
  std::shuffle(faceMap.begin(), faceMap.end(), random);
  MovedCopy copy;
  copy.faceMap = faceMap;
  copy.mesh.V.resize(mesh.numVertices(), 3);
  copy.mesh.F.resize(mesh.numFaces(), 3);
  for (int v = 0; v < mesh.numVertices(); ++v)
    copy.mesh.V.row(vertexMap[v]) = (rotation * mesh.vertex(v) + move).transpose();
  for (int f = 0; f < mesh.numFaces(); ++f)
    for (int k = 0; k < 3; ++k)
      copy.mesh.F(faceMap[f], k) = vertexMap[mesh.F(f, (k + copy.shift) % 3)];
  return copy;
}

/// Landmarks at the centres of every `stride`-th face, pointing along their first edge.
std::vector<OrientedSurfacePoint> landmarksOn(const TriangleMesh& mesh, int stride)
{
  std::vector<OrientedSurfacePoint> out;
  for (int f = 0, id = 0; f < mesh.numFaces(); f += stride, ++id)
    out.push_back({id, f, Vec3(0.2, 0.3, 0.5),
                   (mesh.vertex(mesh.F(f, 1)) - mesh.vertex(mesh.F(f, 0))).normalized()});
  return out;
}

/// The same landmarks on the moved copy.
std::vector<OrientedSurfacePoint> landmarksOnCopy(const std::vector<OrientedSurfacePoint>& l,
                                                  const MovedCopy& copy,
                                                  const Eigen::Matrix3d& rotation)
{
  std::vector<OrientedSurfacePoint> out;
  for (const auto& p : l)
  {
    Vec3 bary;
    for (int k = 0; k < 3; ++k) bary[k] = p.bary[(k + copy.shift) % 3];
    out.push_back({p.id, copy.faceMap[p.face], bary, rotation * p.direction});
  }
  return out;
}
} // namespace

TEST(PatchCorrespondence, MapsASphereOntoAMovedReorderedCopy)
{
  const TriangleMesh sphere = icosphere(4, 0.5); // 2562 vertices, edges about 2 cm
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  const Vec3 move(0.3, -1.0, 2.0);
  const MovedCopy copy = movedCopy(sphere, rotation, move);
  const auto templateLandmarks = landmarksOn(sphere, 1280); // 4 landmarks
  const TemplatePatches patches(sphere, templateLandmarks);
  const FrameCorrespondence c =
      patches.correspond(copy.mesh, landmarksOnCopy(templateLandmarks, copy, rotation));

  ASSERT_EQ(c.vertices.size(), static_cast<size_t>(sphere.numVertices()));
  ASSERT_EQ(c.patches.size(), templateLandmarks.size());
  for (const auto& p : c.patches)
  {
    EXPECT_TRUE(p.kept) << "landmark " << p.landmarkId;
    EXPECT_NEAR(p.radius, 0.25, 0.03);
    EXPECT_EQ(p.inconsistent, 0) << "an isometry keeps every vertex";
  }
  double error = 0, worst = 0;
  int matched = 0;
  for (int v = 0; v < sphere.numVertices(); ++v)
  {
    const VertexMatch& m = c.vertices[v];
    if (!m.matched()) continue;
    ++matched;
    const double e = (m.position - (rotation * sphere.vertex(v) + move)).norm();
    EXPECT_NEAR((surfacePosition(copy.mesh, m.face, m.bary) - m.position).norm(), 0.0, 1e-9);
    error += e;
    worst = std::max(worst, e);
    EXPECT_GE(m.patches, 1);
    EXPECT_GE(m.patchId, 0);
  }
  // Four discs of geodesic radius 0.25 on a sphere of radius 0.5 cover 4 (1 - cos 0.5) / 2 =
  // 24.5 % of it when they do not overlap.
  EXPECT_GT(static_cast<double>(matched) / sphere.numVertices(), 0.22);
  EXPECT_LT(error / matched, 0.005);
  EXPECT_LT(worst, 0.03);
}

TEST(PatchCorrespondence, NearIsometryTestRejectsAWrongOrientation)
{
  // On a long thin ellipsoid, a landmark direction turned by 90 degrees maps the length of the
  // body onto its girth: distances to the anchors change, so the test rejects much of the map
  // (on a sphere the same turn would be an isometry).
  TriangleMesh body = icosphere(4, 1.0);
  body.V.col(0) *= 0.5;
  body.V.col(1) *= 0.08;
  body.V.col(2) *= 0.08;
  int face = 0; // the face whose centre is nearest the side of the middle
  for (int f = 0; f < body.numFaces(); ++f)
    if (surfacePosition(body, f, Vec3::Constant(1.0 / 3)).norm() <
            surfacePosition(body, face, Vec3::Constant(1.0 / 3)).norm() &&
        surfacePosition(body, f, Vec3::Constant(1.0 / 3)).y() > 0)
      face = f;
  const std::vector<OrientedSurfacePoint> along = {
      {0, face, Vec3::Constant(1.0 / 3), Vec3::UnitX()}};
  const std::vector<OrientedSurfacePoint> across = {
      {0, face, Vec3::Constant(1.0 / 3), Vec3::UnitZ()}};
  PatchCorrespondenceOptions options;
  options.epsilon = 0.05;
  const TemplatePatches patches(body, along, options);
  const FrameCorrespondence right = patches.correspond(body, along);
  const FrameCorrespondence wrong = patches.correspond(body, across);
  EXPECT_TRUE(right.patches[0].kept);
  EXPECT_EQ(right.patches[0].inconsistent, 0);
  EXPECT_GT(wrong.patches[0].inconsistent, right.patches[0].vertices / 4);
  EXPECT_LT(wrong.matchedFraction(), 0.75 * right.matchedFraction());
}

TEST(PatchCorrespondence, MissingLandmarksAndSmallPatches)
{
  const TriangleMesh sphere = icosphere(3, 0.5);
  const auto templateLandmarks = landmarksOn(sphere, 320);
  const TemplatePatches patches(sphere, templateLandmarks);
  // No landmark on the frame: nothing matched, no crash.
  const FrameCorrespondence none = patches.correspond(sphere, {});
  EXPECT_EQ(none.matchedFraction(), 0.0);
  for (const auto& p : none.patches) EXPECT_FALSE(p.kept);
  // Landmarks on loose cloth (far from the body) seed nothing.
  auto loose = templateLandmarks;
  for (auto& l : loose) l.offset = 0.08;
  EXPECT_EQ(patches.correspond(sphere, loose).matchedFraction(), 0.0);
  EXPECT_GT(patches.correspond(sphere, templateLandmarks).matchedFraction(), 0.2);
  // tau_s above tau_d: every patch is too small and discarded.
  PatchCorrespondenceOptions options;
  options.minimumRadius = 0.3;
  const TemplatePatches tooSmall(sphere, templateLandmarks, options);
  EXPECT_EQ(tooSmall.correspond(sphere, templateLandmarks).matchedFraction(), 0.0);
}

TEST(PatchCorrespondence, SeedConsensusDropsAMisplacedLandmark)
{
  // A landmark placed 30 cm from where it belongs on the frame (as a body posed wrongly under
  // the clothing would place it): on a sphere its patch is as isometric as a right one, so only
  // the geodesic distances to the other landmarks tell.
  const TriangleMesh sphere = icosphere(4, 0.5);
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.4, Vec3(0, 1, 1).normalized()).toRotationMatrix();
  const Vec3 move(0.1, 0.2, -0.3);
  const MovedCopy copy = movedCopy(sphere, rotation, move);
  const auto templateLandmarks = landmarksOn(sphere, 640); // 8 landmarks
  auto frameLandmarks = landmarksOnCopy(templateLandmarks, copy, rotation);
  const Vec3 truth =
      rotation * surfacePosition(sphere, templateLandmarks[0].face, templateLandmarks[0].bary) +
      move;
  int misplaced = -1;
  for (int f = 0; f < copy.mesh.numFaces(); ++f)
  {
    const double d = (surfacePosition(copy.mesh, f, Vec3::Constant(1.0 / 3)) - truth).norm();
    if (std::abs(d - 0.3) < 0.01) misplaced = f;
  }
  ASSERT_GE(misplaced, 0);
  frameLandmarks[0].face = misplaced;
  frameLandmarks[0].bary = Vec3::Constant(1.0 / 3);

  auto meanError = [&](const FrameCorrespondence& c, int patchId)
  {
    double sum = 0;
    int count = 0;
    for (int v = 0; v < sphere.numVertices(); ++v)
      if (c.vertices[v].matched() && (patchId < 0 || c.vertices[v].patchId == patchId))
        sum += (c.vertices[v].position - (rotation * sphere.vertex(v) + move)).norm(), ++count;
    return count ? sum / count : 0.0;
  };

  PatchCorrespondenceOptions noVote;
  noVote.minimumSeedConsensus = 0;
  const FrameCorrespondence trusting =
      TemplatePatches(sphere, templateLandmarks, noVote).correspond(copy.mesh, frameLandmarks);
  ASSERT_TRUE(trusting.patches[0].kept);
  EXPECT_EQ(trusting.patches[0].inconsistent, 0) << "the near-isometry test cannot see it";
  EXPECT_GT(meanError(trusting, templateLandmarks[0].id), 0.2);

  const FrameCorrespondence voted =
      TemplatePatches(sphere, templateLandmarks).correspond(copy.mesh, frameLandmarks);
  EXPECT_TRUE(voted.patches[0].outvoted);
  EXPECT_FALSE(voted.patches[0].kept);
  EXPECT_LT(voted.patches[0].consensus, 0.7);
  for (size_t i = 1; i < voted.patches.size(); ++i)
  {
    EXPECT_FALSE(voted.patches[i].outvoted) << "landmark " << i;
    EXPECT_TRUE(voted.patches[i].kept) << "landmark " << i;
    EXPECT_GE(voted.patches[i].consensus, 0.7) << "landmark " << i;
  }
  EXPECT_LT(meanError(voted, -1), 0.01);
  EXPECT_LT(voted.matchedFraction(), trusting.matchedFraction());
}

TEST(PatchCorrespondence, BadInputIsAnError)
{
  const TriangleMesh sphere = icosphere(2, 0.5);
  std::vector<OrientedSurfacePoint> bad = {{0, sphere.numFaces(), Vec3(1, 0, 0), Vec3(1, 0, 0)}};
  EXPECT_THROW(TemplatePatches(sphere, bad), Error);
  EXPECT_THROW(TemplatePatches(TriangleMesh(), {}), Error);
  const TemplatePatches patches(sphere, landmarksOn(sphere, 40));
  EXPECT_THROW(patches.correspond(TriangleMesh(), {}), Error);
  EXPECT_THROW(patches.correspond(sphere, bad), Error);
  std::vector<OrientedSurfacePoint> nan = {{0, 0, Vec3(1, 0, 0), Vec3(std::nan(""), 0, 0)}};
  EXPECT_THROW(patches.correspond(sphere, nan), Error);
}

TEST(PatchCorrespondence, RigidBaselineIsExactForARigidMotion)
{
  const TriangleMesh sphere = icosphere(3, 0.5);
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(-1.1, Vec3(0, 1, 0.2).normalized()).toRotationMatrix();
  const MovedCopy copy = movedCopy(sphere, rotation, Vec3(1, 2, 3));
  const auto landmarks = landmarksOn(sphere, 80);
  const FrameCorrespondence c = rigidNearestCorrespondence(
      sphere, landmarks, copy.mesh, landmarksOnCopy(landmarks, copy, rotation));
  double worst = 0;
  for (int v = 0; v < sphere.numVertices(); ++v)
    worst = std::max(
        worst, (c.vertices[v].position - (rotation * sphere.vertex(v) + Vec3(1, 2, 3))).norm());
  EXPECT_LT(worst, 1e-6);
  EXPECT_EQ(c.matchedFraction(), 1.0);
}
