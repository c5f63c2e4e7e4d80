#include <clothtrack/mesh/Laplacian.h>
#include <clothtrack/mesh/Primitives.h>

#include <gtest/gtest.h>

#include <random>

using namespace clothtrack;

namespace
{
// A grid with jittered interior vertices: many obtuse triangles.
TriangleMesh jitteredGrid(int n, double amount, unsigned seed)
{
  TriangleMesh mesh = grid(n, 1.0);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  for (int i = 1; i < n; ++i)
    for (int j = 1; j < n; ++j)
    {
      mesh.V(i * (n + 1) + j, 0) += u(rng) / n;
      mesh.V(i * (n + 1) + j, 1) += u(rng) / n;
      mesh.V(i * (n + 1) + j, 2) += u(rng) / n;
    }
  return mesh;
}
} // namespace

TEST(VoronoiArea, SumsToSurfaceArea)
{
  for (const TriangleMesh& mesh :
       {icosphere(3), torus(1.0, 0.25, 30, 12), jitteredGrid(12, 0.45, 3)})
  {
    const Eigen::VectorXd areas = mixedVoronoiAreas(mesh);
    EXPECT_NEAR(areas.sum(), surfaceArea(mesh), 1e-10 * surfaceArea(mesh));
    EXPECT_GT(areas.minCoeff(), 0.0);
  }
}

TEST(VoronoiArea, UniformGridInteriorIsCellArea)
{
  const int n = 8;
  const Eigen::VectorXd areas = mixedVoronoiAreas(grid(n, 1.0));
  // Right triangles: an interior vertex owns exactly one grid cell.
  EXPECT_NEAR(areas[4 * (n + 1) + 4], 1.0 / (n * n), 1e-12);
}

TEST(CotanLaplacian, RowsSumToZeroAndLinearFunctionsAreHarmonic)
{
  const int n = 10;
  const TriangleMesh mesh = jitteredGrid(n, 0.3, 7);
  // Flatten the jitter so that linear functions are exactly reproduced.
  TriangleMesh flat = mesh;
  flat.V.col(2).setZero();
  const SparseMatrix L = cotanLaplacian(flat);
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(flat.numVertices());
  EXPECT_LT((L * ones).cwiseAbs().maxCoeff(), 1e-12);
  const Eigen::VectorXd f = 2.0 * flat.V.col(0) - 3.0 * flat.V.col(1);
  const Eigen::VectorXd Lf = L * f;
  for (int i = 1; i < n; ++i)
    for (int j = 1; j < n; ++j) EXPECT_NEAR(Lf[i * (n + 1) + j], 0.0, 1e-10);
  // Symmetric positive semi-definite: x^T L x >= 0.
  const Eigen::VectorXd x = Eigen::VectorXd::Random(flat.numVertices());
  EXPECT_GE(x.dot(L * x), 0.0);
  EXPECT_LT((SparseMatrix(L.transpose()) - L).norm(), 1e-12);
}
