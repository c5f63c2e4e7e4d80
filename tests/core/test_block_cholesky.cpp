// Block Cholesky preconditioner: solves against a dense reference, refuses bad matrices.
#include <clothtrack/base/Error.h>
#include <clothtrack/mesh/MeshTopology.h>
#include <clothtrack/mesh/Primitives.h>
#include <clothtrack/solver/BlockCholesky.h>

#include <gtest/gtest.h>

using namespace clothtrack;

namespace
{
/// The template fit's normal matrix on a sphere: a 4x4 data block per vertex plus smoothness
/// (-w I4 per edge, w times the degree on the diagonal), as its lower triangle.
Eigen::SparseMatrix<double> normalMatrix(const TriangleMesh& mesh, double smoothness)
{
  const int n = mesh.numVertices();
  const MeshTopology topology = buildTopology(mesh);
  std::vector<int> degree(n, 0);
  std::vector<Eigen::Triplet<double>> entries;
  for (const auto& e : topology.edges)
  {
    ++degree[e[0]], ++degree[e[1]];
    const int lo = std::min(e[0], e[1]), hi = std::max(e[0], e[1]);
    for (int r = 0; r < 4; ++r) entries.emplace_back(4 * hi + r, 4 * lo + r, -smoothness);
  }
  for (int i = 0; i < n; ++i)
  {
    const Eigen::Vector4d b(mesh.V(i, 0), mesh.V(i, 1), mesh.V(i, 2), 1.0);
    const Eigen::Matrix4d block = (i % 3 == 0 ? 1.0 : 0.0) * b * b.transpose() +
                                  Eigen::Matrix4d::Identity() * (smoothness * degree[i] + 1e-3);
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c <= r; ++c) entries.emplace_back(4 * i + r, 4 * i + c, block(r, c));
  }
  Eigen::SparseMatrix<double> lower(4 * n, 4 * n);
  lower.setFromTriplets(entries.begin(), entries.end());
  return lower;
}
} // namespace

TEST(BlockCholesky, SolvesLikeADenseFactorisation)
{
  const TriangleMesh sphere = icosphere(2, 0.5);
  const Eigen::SparseMatrix<double> lower = normalMatrix(sphere, 0.5);
  BlockCholesky factor(lower);
  factor.factorise(lower);
  const Eigen::MatrixXd dense = Eigen::MatrixXd(lower).selfadjointView<Eigen::Lower>();
  const BlockCholesky::RightHandSides rhs = BlockCholesky::RightHandSides::Random(lower.rows(), 3);
  BlockCholesky::RightHandSides x;
  factor.solve(rhs, x);
  const Eigen::MatrixXd reference = dense.llt().solve(Eigen::MatrixXd(rhs));
  // The factor is stored in bfloat16 (8-bit mantissa): a preconditioner, accurate to about 1 %.
  const double relative = (Eigen::MatrixXd(x) - reference).norm() / reference.norm();
  EXPECT_LT(relative, 0.02);
  EXPECT_GT(relative, 0.0);
  // Every block of the factor is accounted for: at least the diagonal and the edges.
  EXPECT_GE(factor.blockCount(), sphere.numVertices() + buildTopology(sphere).edges.size());
  // A second factorisation with other values replaces the first.
  const Eigen::SparseMatrix<double> stiffer = normalMatrix(sphere, 5.0);
  factor.factorise(stiffer);
  factor.solve(rhs, x);
  const Eigen::MatrixXd stifferReference =
      Eigen::MatrixXd(Eigen::MatrixXd(stiffer).selfadjointView<Eigen::Lower>())
          .llt()
          .solve(Eigen::MatrixXd(rhs));
  EXPECT_LT((Eigen::MatrixXd(x) - stifferReference).norm() / stifferReference.norm(), 0.02);
}

TEST(BlockCholesky, RefusesBadMatrices)
{
  EXPECT_THROW(BlockCholesky(Eigen::SparseMatrix<double>(6, 6)), Error);
  EXPECT_THROW(BlockCholesky(Eigen::SparseMatrix<double>(8, 4)), Error);
  const TriangleMesh sphere = icosphere(1, 0.5);
  Eigen::SparseMatrix<double> lower = normalMatrix(sphere, 0.5);
  BlockCholesky factor(lower);
  lower.coeffRef(5, 5) = -1.0; // no longer positive definite
  EXPECT_THROW(factor.factorise(lower), Error);
  BlockCholesky::RightHandSides x;
  EXPECT_THROW(factor.solve(BlockCholesky::RightHandSides::Zero(8, 3), x), Error);
}
