// The built-in body model: topology, shape space, skinning and landmarks.
#include "ctBodyModelIO.h"
#include "ctBodyModelSource.h"
#include "ctBuiltinBodyModel.h"
#include "ctMeshConversion.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/body/BodyModel.h>
#include <clothtrack/mesh/Components.h>

#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <filesystem>

#include <random>
#include <set>

using namespace clothtrack;

namespace
{
const BodyModel& model()
{
  return builtinBodyModel();
}

void expectClosedGenusZeroManifold(const TriangleMesh& mesh)
{
  const MeshTopology topo = buildTopology(mesh);
  const ManifoldReport manifold = checkManifold(mesh, topo);
  EXPECT_TRUE(manifold.isManifold())
      << manifold.nonManifoldEdges << " edges, " << manifold.nonManifoldVertices << " vertices";
  const Components c = connectedComponents(mesh, topo);
  ASSERT_EQ(c.count(), 1);
  EXPECT_EQ(c.info[0].numBoundaries, 0);
  EXPECT_EQ(c.info[0].genus(), 0);
}
} // namespace

TEST(BodyModel, MeanBodyIsAClosedGenusZeroManifold)
{
  const BodyModel& m = model();
  EXPECT_GE(m.numVertices(), 5000);
  EXPECT_LE(m.numVertices(), 15000);
  expectClosedGenusZeroManifold(m.mesh);
  const double height = m.mesh.V.col(1).maxCoeff() - m.mesh.V.col(1).minCoeff();
  EXPECT_NEAR(height, 1.70, 0.1);
  // Faces outward, and encloses a human volume (about 60-80 litres).
  EXPECT_GT(signedVolume(m.mesh), 0.04);
  EXPECT_LT(signedVolume(m.mesh), 0.12);
}

TEST(BodyModel, RandomShapesArePlausibleManifolds)
{
  const BodyModel& m = model();
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0, 1);
  for (int trial = 0; trial < 5; ++trial)
  {
    Eigen::VectorXd beta(m.numShapeComponents());
    for (int k = 0; k < beta.size(); ++k) beta[k] = n(rng);
    Points v, j;
    m.shape(beta, v, j);
    TriangleMesh mesh{v, m.mesh.F};
    expectClosedGenusZeroManifold(mesh);
    const double height = v.col(1).maxCoeff() - v.col(1).minCoeff();
    EXPECT_GT(height, 1.40);
    EXPECT_LT(height, 2.05);
    EXPECT_GT(v.col(1).minCoeff(), -0.08); // standing near the floor
  }
}

TEST(BodyModel, ShapeSpaceIsOrthogonalAndOrderedByVariance)
{
  const BodyModel& m = model();
  ASSERT_GE(m.numShapeComponents(), 10);
  Eigen::MatrixXd full(m.vertexBasis.rows() + m.jointBasis.rows(), m.numShapeComponents());
  full << m.vertexBasis, m.jointBasis;
  const Eigen::MatrixXd gram = full.transpose() * full;
  for (int a = 0; a < gram.rows(); ++a)
    for (int b = 0; b < gram.cols(); ++b)
      if (a != b)
      {
        EXPECT_LT(std::abs(gram(a, b)), 1e-8 * std::sqrt(gram(a, a) * gram(b, b))) << a << "," << b;
      }
  for (int k = 1; k < m.numShapeComponents(); ++k)
    EXPECT_GE(gram(k - 1, k - 1), gram(k, k) * (1 - 1e-9));
  EXPECT_GT(m.explainedVariance.head(10).sum(), 0.9);
  // One standard deviation of the first component moves the body by centimetres, not metres.
  const double rms = std::sqrt(m.vertexBasis.col(0).squaredNorm() / m.numVertices());
  EXPECT_GT(rms, 0.005);
  EXPECT_LT(rms, 0.2);
}

TEST(BodyModel, SkinningIsIdentityAtRestAndRigidAlongBones)
{
  const BodyModel& m = model();
  for (int i = 0; i < m.numVertices(); ++i) ASSERT_NEAR(m.weights.row(i).sum(), 1.0, 1e-9);
  Eigen::VectorXd beta = Eigen::VectorXd::Zero(m.numShapeComponents());
  beta[0] = 1.5;
  Points v, j;
  m.shape(beta, v, j);
  const BodyPose rest;
  EXPECT_LT((m.pose(v, j, rest) - v).cwiseAbs().maxCoeff(), 1e-12);

  BodyPose bent;
  bent.rotations.row(LeftElbow) << 0, 0, 1.2;
  bent.translation = Vec3(0.1, 0, 0);
  Points posedJoints;
  const TriangleMesh posed = m.posed(beta, bent, &posedJoints);
  // Joints keep their bone lengths; the right arm only translates.
  const double forearm = (j.row(LeftWrist) - j.row(LeftElbow)).norm();
  EXPECT_NEAR((posedJoints.row(LeftWrist) - posedJoints.row(LeftElbow)).norm(), forearm, 1e-9);
  EXPECT_LT((posedJoints.row(RightWrist) - j.row(RightWrist) - bent.translation.transpose()).norm(),
            1e-9);
  EXPECT_GT((posedJoints.row(LeftWrist) - j.row(LeftWrist) - bent.translation.transpose()).norm(),
            0.1);
  int moved = 0;
  for (int i = 0; i < m.numVertices(); ++i)
    moved += (posed.V.row(i) - v.row(i) - bent.translation.transpose()).norm() > 0.01;
  EXPECT_GT(moved, 200);                 // the forearm and hand
  EXPECT_LT(moved, m.numVertices() / 8); // and little else
}

TEST(BodyModel, RestPoseDistanceSumsTheBends)
{
  BodyPose pose;
  EXPECT_EQ(restPoseDistance(pose), 0.0);
  // The root's rotation and the translation move the body without bending it.
  pose.rotations.row(Pelvis) << 0, 2.0, 0;
  pose.translation = Vec3(1, 2, 3);
  EXPECT_EQ(restPoseDistance(pose), 0.0);
  pose.rotations.row(LeftElbow) << 0, 0, 1.2;
  pose.rotations.row(RightKnee) << 0.3, 0, -0.4;
  EXPECT_NEAR(restPoseDistance(pose), 1.2 + 0.5, 1e-12);
}

TEST(BodyModel, FortyOrientedLandmarks)
{
  const BodyModel& m = model();
  ASSERT_EQ(m.landmarks.size(), 40u);
  std::set<std::string> names;
  std::set<int> vertices;
  for (const auto& l : m.landmarks)
  {
    names.insert(l.name);
    vertices.insert(l.vertex);
    ASSERT_GE(l.vertex, 0);
    ASSERT_LT(l.vertex, m.numVertices());
    ASSERT_NE(l.vertex, l.directionVertex);
    EXPECT_LT((m.mesh.vertex(l.vertex) - m.mesh.vertex(l.directionVertex)).norm(), 0.06) << l.name;
  }
  EXPECT_EQ(names.size(), 40u);
  EXPECT_EQ(vertices.size(), 40u);
  // Anatomy: forehead above chin, head top highest, toes in front of heels, left on +x.
  auto at = [&](const char* name)
  { return m.mesh.vertex(m.landmarks[m.landmarkIndex(name)].vertex); };
  EXPECT_GT(at("forehead").y(), at("chin").y());
  EXPECT_NEAR(at("head_top").y(), m.mesh.V.col(1).maxCoeff(), 0.01);
  EXPECT_GT(at("left_toe").z(), at("left_heel").z() + 0.15);
  EXPECT_GT(at("left_wrist").x(), 0.3);
  EXPECT_LT(at("right_wrist").x(), -0.3);
  EXPECT_GT(at("sternum").z(), at("back_upper").z() + 0.15);
  EXPECT_LT(at("left_knee").y(), at("left_hip").y());
}

TEST(BodyModel, FileRoundTripAndBadFiles)
{
  const std::string dir = std::string(CLOTHTRACK_TEST_TMP) + "/body-model";
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/model.vtp";
  writeBodyModel(path, model());
  const BodyModel back = readBodyModel(path);
  EXPECT_EQ(back.mesh.F, model().mesh.F);
  EXPECT_LT((back.mesh.V - model().mesh.V).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((back.vertexBasis - model().vertexBasis).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((back.jointBasis - model().jointBasis).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((back.weights - model().weights).cwiseAbs().maxCoeff(), 1e-12);
  ASSERT_EQ(back.landmarks.size(), model().landmarks.size());
  EXPECT_EQ(back.landmarks[7].name, model().landmarks[7].name);
  EXPECT_EQ(back.landmarks[7].vertex, model().landmarks[7].vertex);

  // An ordinary mesh file is not a body model: a clear error naming the file.
  const std::string plain = dir + "/plain.vtp";
  writeMeshFile(plain, toPolyData(model().mesh));
  try
  {
    readBodyModel(plain);
    FAIL() << "no error";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find(plain), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("not a ClothTrack body model"), std::string::npos);
  }
  EXPECT_THROW(readBodyModel(dir + "/missing.vtp"), Error);
}

TEST(BodyModelSource, PosedMeshAndLandmarksFollowTheModel)
{
  vtkNew<ctBodyModelSource> source;
  source->SetShapeCoefficient(1, -1.0);
  source->SetJointRotation(LeftShoulder, 0, 0, -0.8);
  source->SetTranslation(1, 0, 2);
  source->Update();
  vtkPolyData* mesh = source->GetOutput();
  EXPECT_EQ(mesh->GetNumberOfPoints(), model().numVertices());
  ASSERT_NE(mesh->GetPointData()->GetArray("SkinWeights"), nullptr);
  EXPECT_EQ(mesh->GetPointData()->GetArray("SkinWeights")->GetNumberOfComponents(), NumJoints);
  Eigen::VectorXd beta = Eigen::VectorXd::Zero(2);
  beta[1] = -1.0;
  BodyPose pose;
  pose.rotations.row(LeftShoulder) << 0, 0, -0.8;
  pose.translation = Vec3(1, 0, 2);
  const TriangleMesh expected = model().posed(beta, pose);
  double worst = 0;
  for (int i = 0; i < expected.numVertices(); ++i)
    worst = std::max(worst, (expected.vertex(i) - Vec3(mesh->GetPoint(i))).norm());
  EXPECT_LT(worst, 1e-9);
  vtkPolyData* landmarks = source->GetLandmarksOutput();
  ASSERT_EQ(landmarks->GetNumberOfPoints(), 40);
  vtkDataArray* direction = landmarks->GetPointData()->GetArray("Direction");
  for (vtkIdType k = 0; k < 40; ++k)
  {
    const int vertex =
        static_cast<int>(landmarks->GetPointData()->GetArray("VertexId")->GetTuple1(k));
    EXPECT_LT((Vec3(landmarks->GetPoint(k)) - expected.vertex(vertex)).norm(), 1e-9);
    EXPECT_NEAR(Vec3(direction->GetTuple3(k)).norm(), 1.0, 1e-9);
  }
}

TEST(BodyModelSource, BadModelFileFails)
{
  vtkNew<ctBodyModelSource> source;
  source->SetModelFileName("/nonexistent/model.vtp");
  source->GlobalWarningDisplayOff();
  source->Update();
  EXPECT_EQ(source->GetOutput()->GetNumberOfPoints(), 0);
  source->GlobalWarningDisplayOn();
}
