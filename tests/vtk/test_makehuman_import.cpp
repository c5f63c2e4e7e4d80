// The MakeHuman importer, on the CC0 assets in ../shared/data/makehuman (skipped without them).
#include "ctBodyModelIO.h"

#include <clothtrack/base/Error.h>
#include <clothtrack/body/MakeHumanImport.h>
#include <clothtrack/mesh/Components.h>

#include <gtest/gtest.h>

#include <filesystem>

using namespace clothtrack;

namespace
{
std::string assets()
{
  return std::string(CLOTHTRACK_SHARED_DATA) + "/makehuman";
}
} // namespace

TEST(MakeHumanImport, ClosedGenusZeroModelWithShapeSpaceAndLandmarks)
{
  if (!std::filesystem::exists(assets()))
    GTEST_SKIP() << "MakeHuman assets not found at " << assets() << "; skipping the importer test";
  MakeHumanImportOptions options;
  options.populationSize = 60;
  const BodyModel model = importMakeHuman(assets(), options);
  const MeshTopology topo = buildTopology(model.mesh);
  EXPECT_TRUE(checkManifold(model.mesh, topo).isManifold());
  const Components c = connectedComponents(model.mesh, topo);
  ASSERT_EQ(c.count(), 1);
  EXPECT_EQ(c.info[0].numBoundaries, 0);
  EXPECT_EQ(c.info[0].genus(), 0);
  const double height = model.mesh.V.col(1).maxCoeff() - model.mesh.V.col(1).minCoeff();
  EXPECT_NEAR(height, 1.7, 0.15);
  EXPECT_NEAR(model.mesh.V.col(1).minCoeff(), 0.0, 1e-9);
  EXPECT_GT(signedVolume(model.mesh), 0.03); // faces outward
  EXPECT_EQ(model.landmarks.size(), 40u);
  for (int i = 0; i < model.numVertices(); i += 97)
    EXPECT_NEAR(model.weights.row(i).sum(), 1.0, 1e-9);
  // Joints in anatomical order: head above neck above pelvis, left on +x.
  EXPECT_GT(model.joints(Head, 1), model.joints(Neck, 1));
  EXPECT_GT(model.joints(Neck, 1), model.joints(Pelvis, 1));
  EXPECT_GT(model.joints(LeftWrist, 0), 0.3);
  // Shape space: the first component changes the body by centimetres.
  ASSERT_GE(model.numShapeComponents(), 10);
  const double rms = std::sqrt(model.vertexBasis.col(0).squaredNorm() / model.numVertices());
  EXPECT_GT(rms, 0.005);
  // It round-trips through the model file format and poses like the built-in model.
  const std::string file = std::string(CLOTHTRACK_TEST_TMP) + "/makehuman_model.vtp";
  writeBodyModel(file, model);
  const BodyModel back = readBodyModel(file);
  BodyPose pose;
  pose.rotations.row(LeftElbow) << 0, 0, 1.0;
  EXPECT_LT(
      (back.posed(Eigen::VectorXd::Ones(3), pose).V - model.posed(Eigen::VectorXd::Ones(3), pose).V)
          .cwiseAbs()
          .maxCoeff(),
      1e-9);
}

TEST(MakeHumanImport, MissingFolderIsAClearError)
{
  try
  {
    importMakeHuman("/nonexistent/makehuman");
    FAIL() << "no error";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("base.obj: missing"), std::string::npos) << e.what();
  }
}
