#include <clothtrack/solver/BlockSolveKernel.h>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

using namespace clothtrack;
using namespace clothtrack::blocksolve;

namespace
{
std::uint16_t bfloat16(float x)
{
  std::uint32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return static_cast<std::uint16_t>((bits + 0x8000u) >> 16);
}

/// A dense 4n x 4n Cholesky factor cut into the kernel's blocks (every block below the
/// diagonal kept), and the solution of L L^T x = b for three right-hand sides through `kernel`.
struct DenseCase
{
  int blocks;
  Eigen::MatrixXd A, B;
  std::vector<int> columnStart, blockRow, columns;
  std::vector<std::uint16_t> value;
  std::vector<float> diagonalInverse;

  explicit DenseCase(int n) : blocks(n)
  {
    const Eigen::MatrixXd M = Eigen::MatrixXd::Random(4 * n, 4 * n);
    A = M * M.transpose() + 4.0 * n * Eigen::MatrixXd::Identity(4 * n, 4 * n);
    B = Eigen::MatrixXd::Random(4 * n, 3);
    const Eigen::MatrixXd L = A.llt().matrixL();
    columnStart.push_back(0);
    for (int J = 0; J < n; ++J)
    {
      columns.push_back(J);
      for (int I = J + 1; I < n; ++I)
      {
        blockRow.push_back(I);
        for (int k = 0; k < 4; ++k)
          for (int r = 0; r < 4; ++r)
            value.push_back(bfloat16(static_cast<float>(L(4 * I + r, 4 * J + k))));
      }
      columnStart.push_back(static_cast<int>(blockRow.size()));
      const Eigen::Matrix4d inverse = L.block<4, 4>(4 * J, 4 * J)
                                          .triangularView<Eigen::Lower>()
                                          .solve(Eigen::Matrix4d::Identity());
      for (int k = 0; k < 4; ++k)
        for (int r = 0; r < 4; ++r) diagonalInverse.push_back(static_cast<float>(inverse(r, k)));
    }
  }

  Eigen::MatrixXd solve(const Kernel& kernel) const
  {
    const Factor factor{columnStart.data(), blockRow.data(), blockRow.data(), value.data(),
                        diagonalInverse.data()};
    std::vector<Lanes> y(3 * blocks, Lanes{});
    for (int J = 0; J < blocks; ++J)
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 4; ++r) y[3 * J + c].v[r] = static_cast<float>(B(4 * J + r, c));
    kernel.forward(factor, columns.data(), blocks, y.data());
    kernel.backward(factor, columns.data(), blocks, y.data());
    Eigen::MatrixXd x(4 * blocks, 3);
    for (int J = 0; J < blocks; ++J)
      for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 4; ++r) x(4 * J + r, c) = y[3 * J + c].v[r];
    return x;
  }
};
} // namespace

TEST(BlockSolveKernel, SolvesLikeADenseFactor)
{
  const DenseCase dense(6);
  const Eigen::MatrixXd exact = dense.A.llt().solve(dense.B);
  const Kernel generic{generic::forward, generic::backward, "generic"};
  for (const Kernel* kernel : {&generic, &bestKernel()})
  {
    const Eigen::MatrixXd x = dense.solve(*kernel);
    // bfloat16 blocks: about three significant digits.
    EXPECT_LT((x - exact).norm(), 2e-2 * exact.norm()) << kernel->instructions;
    // The residual shows the factor was applied, not just its diagonal.
    EXPECT_LT((dense.A * x - dense.B).norm(), 2e-2 * dense.B.norm()) << kernel->instructions;
  }
}

TEST(BlockSolveKernel, VariantsAgree)
{
  const DenseCase dense(9);
  const Kernel generic{generic::forward, generic::backward, "generic"};
  const Eigen::MatrixXd a = dense.solve(generic), b = dense.solve(bestKernel());
  // Fused multiply-adds round differently; both read the same factor.
  EXPECT_LT((a - b).norm(), 1e-5 * a.norm()) << bestKernel().instructions;
}
