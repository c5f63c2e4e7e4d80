// Point clouds: reading and writing (PLY vertices, XYZ, PCD in every encoding), refusing clouds
// that are not a surface, the depth-camera simulator, cleaning, normals and reconstruction.
#include "TestUtil.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/cloud/CloudCleaning.h>
#include <clothtrack/cloud/CloudNormals.h>
#include <clothtrack/cloud/DepthCapture.h>
#include <clothtrack/io/PointCloudIO.h>
#include <clothtrack/mesh/Components.h>
#include <clothtrack/mesh/Primitives.h>
#include <clothtrack/pcd/PcdIO.h>
#include <clothtrack/reconstruction/SequenceCoverage.h>
#include <clothtrack/reconstruction/SurfaceReconstruction.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace clothtrack;

namespace
{
/// A few hundred points with normals and colours.
PointCloud smallCloud(int n = 300)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  PointCloud cloud;
  cloud.P.resize(n, 3);
  cloud.N.resize(n, 3);
  cloud.C.resize(n, 3);
  for (int i = 0; i < n; ++i)
  {
    cloud.P.row(i) << u(rng), u(rng), u(rng);
    cloud.N.row(i) = cloud.P.row(i).normalized();
    cloud.C.row(i) << static_cast<std::uint8_t>(i % 256), static_cast<std::uint8_t>(7 * i % 256),
        static_cast<std::uint8_t>(255 - i % 256);
  }
  return cloud;
}

void expectSameCloud(const PointCloud& a, const PointCloud& b, bool normals, bool colours)
{
  ASSERT_EQ(a.size(), b.size());
  EXPECT_LT((a.P - b.P).cwiseAbs().maxCoeff(), 1e-6); // stored as float
  ASSERT_EQ(b.hasNormals(), normals);
  if (normals)
  {
    EXPECT_LT((a.N - b.N).cwiseAbs().maxCoeff(), 1e-6);
  }
  ASSERT_EQ(b.hasColours(), colours);
  if (colours)
  {
    EXPECT_TRUE(a.C == b.C);
  }
}

/// The depth rig's view of a sphere of radius 0.3 m at 1 m height.
PointCloud sphereCapture(double noise, double outliers)
{
  DepthRig rig;
  rig.centre = Vec3(0, 1, 0);
  rig.noise = noise;
  rig.outliers = outliers;
  return captureDepth(icosphere(4, 0.3, rig.centre), rig);
}

/// Share of the points further than `distance` from the sphere.
double shareOffSphere(const Points& points, const Vec3& centre, double radius, double distance)
{
  long off = 0;
  for (long i = 0; i < points.rows(); ++i)
    off += std::abs((points.row(i).transpose() - centre).norm() - radius) > distance;
  return static_cast<double>(off) / points.rows();
}

double radialError(const Points& points, const Vec3& centre, double radius)
{
  double worst = 0;
  for (long i = 0; i < points.rows(); ++i)
    worst = std::max(worst, std::abs((points.row(i).transpose() - centre).norm() - radius));
  return worst;
}
} // namespace

TEST(PointCloudIO, PlyPointsKeepNormalsAndColours)
{
  const std::string dir = test::scratchDir("cloud_ply");
  const PointCloud cloud = smallCloud();
  writePLYPoints(dir + "/c.ply", cloud);
  expectSameCloud(cloud, readPLYPoints(dir + "/c.ply"), true, true);
  EXPECT_TRUE(isPointCloudFile(dir + "/c.ply"));
  // A PLY with faces is a mesh.
  test::writeText(dir + "/mesh.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                     "property float y\nproperty float z\nelement face 1\n"
                                     "property list uchar int vertex_indices\nend_header\n"
                                     "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_FALSE(isPointCloudFile(dir + "/mesh.ply"));
}

TEST(PointCloudIO, XyzRoundTripAndErrorsNameTheLine)
{
  const std::string dir = test::scratchDir("cloud_xyz");
  PointCloud cloud = smallCloud();
  cloud.C.resize(0, 3);
  writeXYZ(dir + "/c.xyz", cloud);
  expectSameCloud(cloud, readXYZ(dir + "/c.xyz"), true, false);
  test::writeText(dir + "/mixed.xyz", "# comment\n0 0 0\n1 2 3 0 0 1\n");
  try
  {
    readXYZ(dir + "/mixed.xyz");
    FAIL() << "mixed column counts accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("mixed.xyz:3:"), std::string::npos) << e.what();
  }
  test::writeText(dir + "/word.xyz", "0 0 zero\n");
  EXPECT_THROW(readXYZ(dir + "/word.xyz"), Error);
}

TEST(PointCloudIO, PcdRoundTripsInEveryEncoding)
{
  const std::string dir = test::scratchDir("cloud_pcd");
  const PointCloud full = smallCloud();
  PointCloud bare;
  bare.P = full.P;
  for (const auto encoding :
       {PcdEncoding::Ascii, PcdEncoding::Binary, PcdEncoding::BinaryCompressed})
  {
    const std::string path = dir + "/c" + std::to_string(static_cast<int>(encoding)) + ".pcd";
    writePCD(path, full, encoding);
    expectSameCloud(full, readPCD(path), true, true);
    writePCD(path, bare, encoding);
    expectSameCloud(bare, readPCD(path), false, false);
  }
  test::writeText(dir + "/bad.pcd", "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\n"
                                    "TYPE F F F\nCOUNT 1 1 1\nWIDTH 5\nHEIGHT 1\nPOINTS 5\n"
                                    "DATA ascii\n0 0 0\n");
  EXPECT_THROW(readPCD(dir + "/bad.pcd"), Error);
  test::writeText(dir + "/nofields.pcd", "# .PCD v0.7\nVERSION 0.7\nFIELDS a b\nSIZE 4 4\n"
                                         "TYPE F F\nCOUNT 1 1\nWIDTH 1\nHEIGHT 1\nPOINTS 1\n"
                                         "DATA ascii\n0 0\n");
  EXPECT_THROW(readPCD(dir + "/nofields.pcd"), Error);
}

TEST(PointCloudIO, RefusesEmptyAllNaNAndTooFewPoints)
{
  auto message = [](PointCloud cloud)
  {
    try
    {
      dropInvalidPoints(cloud, "frame.pcd");
    }
    catch (const Error& e)
    {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(PointCloud{}).find("frame.pcd: the point cloud is empty"), std::string::npos);
  PointCloud nan = smallCloud();
  nan.P.setConstant(std::nan(""));
  EXPECT_NE(message(nan).find("no point of the cloud has finite coordinates"), std::string::npos);
  EXPECT_NE(message(smallCloud(40)).find("40 valid points, too few"), std::string::npos);
  PointCloud someNaN = smallCloud();
  someNaN.P.topRows(10).setConstant(std::nan(""));
  EXPECT_EQ(dropInvalidPoints(someNaN, "frame.pcd"), 10);
  EXPECT_EQ(someNaN.size(), 290);
  EXPECT_TRUE(someNaN.hasNormals() && someNaN.hasColours());
}

TEST(DepthCapture, SeesTheSurfaceWithItsNoiseAndAddsStrays)
{
  const PointCloud clean = sphereCapture(0.0, 0.0);
  ASSERT_GT(clean.size(), 5000);
  EXPECT_LT(radialError(clean.P, Vec3(0, 1, 0), 0.3), 0.003); // icosphere facets
  const PointCloud noisy = sphereCapture(0.003, 0.05);
  EXPECT_NEAR(noisy.size(), std::lround(clean.size() * 1.05), 2);
  // The same pixels come first: the depth error along each ray is the noise, 68 % of it within
  // one deviation.
  int within = 0;
  for (int i = 0; i < clean.size(); ++i) within += (noisy.P.row(i) - clean.P.row(i)).norm() < 0.003;
  EXPECT_NEAR(static_cast<double>(within) / clean.size(), 0.683, 0.02);
}

TEST(CloudCleaning, RemovesStrayPointsAndThins)
{
  const PointCloud noisy = sphereCapture(0.002, 0.05);
  CloudCleaningReport report;
  const PointCloud cleaned = cleanCloud(noisy, {}, &report);
  EXPECT_EQ(report.input, noisy.size());
  EXPECT_GT(report.outliers, 0.6 * 0.05 / 1.05 * noisy.size());
  // Strays near the surface stay (the reconstruction averages them away); the far ones go.
  EXPECT_GT(shareOffSphere(noisy.P, Vec3(0, 1, 0), 0.3, 0.02), 0.03);
  EXPECT_LT(shareOffSphere(cleaned.P, Vec3(0, 1, 0), 0.3, 0.02), 0.005);
  EXPECT_LT(cleaned.size(), noisy.size() - report.outliers);
}

TEST(CloudNormals, PointOutwardOnASphere)
{
  PointCloud cloud = cleanCloud(sphereCapture(0.001, 0.0), {});
  NormalReport report;
  estimateNormals(cloud, {}, &report);
  int outward = 0;
  for (int i = 0; i < cloud.size(); ++i)
    outward += cloud.N.row(i).dot(cloud.P.row(i) - Vec3(0, 1, 0).transpose()) > 0;
  EXPECT_EQ(outward, cloud.size());
  EXPECT_EQ(report.trees, 1);
  EXPECT_LT(report.medianSurfaceVariation, 0.05);
}

TEST(SurfaceReconstruction, ClosedSurfaceOfANoisySphere)
{
  ReconstructionReport report;
  const TriangleMesh mesh = reconstructSurface(sphereCapture(0.003, 0.01), "sphere", {}, &report);
  EXPECT_LT(radialError(mesh.V, Vec3(0, 1, 0), 0.3), 0.01);
  EXPECT_EQ(report.pieces, 1);
  EXPECT_EQ(report.genus, 0);
  EXPECT_LT(report.unexplainedShare, 0.01);
  EXPECT_TRUE(report.doubts.empty());
  EXPECT_GT(mesh.numVertices(), 500);
}

TEST(SurfaceReconstruction, CropOpensWhatNoPointSupports)
{
  const TriangleMesh sphere = icosphere(4, 0.3);
  std::vector<bool> upper(sphere.numVertices());
  for (int v = 0; v < sphere.numVertices(); ++v) upper[v] = sphere.V(v, 1) > 0.05;
  PointCloud points;
  points.P = sphere.V;
  points = selectPoints(points, upper);
  const TriangleMesh cropped = cropToPoints(sphere, points.P, 0.02, 0.01);
  EXPECT_GT(cropped.V.col(1).minCoeff(), 0.02);
  const MeshTopology topology = buildTopology(cropped);
  EXPECT_EQ(boundaryLoops(cropped, topology).size(), 1u);
}

TEST(SurfaceReconstruction, RefusesPointsThatFillAVolume)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  PointCloud noise;
  noise.P.resize(20000, 3);
  for (int i = 0; i < 20000; ++i) noise.P.row(i) << u(rng), u(rng), u(rng);
  try
  {
    reconstructSurface(noise, "noise.pcd");
    FAIL() << "a cloud of noise was reconstructed";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("noise.pcd: the points do not lie on a surface"),
              std::string::npos)
        << e.what();
  }
}

TEST(SequenceCoverage, DoubtsAFrameThatLostPartOfTheSubject)
{
  // Frame 3 shows two thirds of the subject; frame 4 was not reconstructed (area 0).
  const std::vector<double> areas = {1.95, 2.0, 2.05, 1.3, 0.0, 1.98};
  const std::vector<std::string> doubts = areaDoubts(areas);
  ASSERT_EQ(doubts.size(), areas.size());
  for (size_t k = 0; k < areas.size(); ++k)
    EXPECT_EQ(doubts[k].empty(), k != 3) << k << ": " << doubts[k];
  EXPECT_NE(doubts[3].find("66 % of the sequence's median"), std::string::npos) << doubts[3];
  // A share of 0.6 lets it pass; two frames are too few to judge.
  for (const std::string& d : areaDoubts(areas, 0.6)) EXPECT_TRUE(d.empty()) << d;
  for (const std::string& d : areaDoubts({2.0, 0.5})) EXPECT_TRUE(d.empty()) << d;
}
