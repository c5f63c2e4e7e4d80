#include "BlockCholesky.h"

#include "BlockSolveKernel.h"
#include "Error.h"
#include "Parallel.h"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>

namespace clothtrack
{
namespace
{
using FactorMatrix = Eigen::SparseMatrix<float>;
using Permutation = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;

/// Approximate minimum degree on the graph of the 4x4 blocks of `lower`, expanded so that the
/// four unknowns of a block stay consecutive: the factor is then made of dense 4x4 blocks.
/// Returns P with P A P^T the reordered matrix.
Permutation vertexBlockOrdering(const Eigen::SparseMatrix<double>& lower)
{
  const Eigen::Index blocks = lower.rows() / 4;
  std::vector<Eigen::Triplet<float>> entries;
  entries.reserve(lower.nonZeros() / 4 + 1);
  for (Eigen::Index c = 0; c < lower.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, c); it; ++it)
      entries.emplace_back(static_cast<int>(it.row() / 4), static_cast<int>(c / 4), 1.0f);
  FactorMatrix graph(blocks, blocks);
  graph.setFromTriplets(entries.begin(), entries.end());
  Permutation blockInverse;
  // AMD orders A + A^T, so the lower triangle is enough.
  Eigen::AMDOrdering<int>()(graph, blockInverse);
  Permutation inverse(lower.rows());
  for (Eigen::Index b = 0; b < blocks; ++b)
    for (int r = 0; r < 4; ++r) inverse.indices()[4 * b + r] = 4 * blockInverse.indices()[b] + r;
  return inverse.inverse();
}

// Scalar factorisation of the reordered matrix; its factor is copied into blocks and dropped.
using Cholesky = Eigen::SimplicialLLT<FactorMatrix, Eigen::Lower, Eigen::NaturalOrdering<int>>;

// Parts of the parallel solve. A fixed number, so that the results do not depend on the number
// of threads (the parts' updates to the top of the tree are summed in a fixed order); two leave
// about 3 % of the work to the top on a body mesh.
constexpr int kParts = 2;

/// Rounds to the nearest bfloat16 (finite values).
std::uint16_t toBfloat16(float x)
{
  std::uint32_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return static_cast<std::uint16_t>((bits + 0x8000u) >> 16);
}

} // namespace

struct BlockCholesky::Impl
{
  Permutation permutation;
  std::vector<int> original; // original[permuted index] = index before the permutation
  int blocks = 0;
  // Block column J of L (permuted order): its off-diagonal blocks are slots
  // columnStart[J] .. columnStart[J+1]-1, in block rows blockRow[slot], values
  // value[16 slot + 4 k + r] = L(4 I + r, 4 J + k), as a bfloat16 (the upper half of a float):
  // the solve is limited by reading the factor, and the 8-bit mantissa costs the conjugate
  // gradients about one step in forty. The diagonal blocks are kept inverted, in float.
  std::vector<int> columnStart, blockRow;
  std::vector<std::uint16_t> value;
  std::vector<float> diagonalInverse; // 16 per block, column-major, lower triangular
  // Parallel solve. Subtrees of the elimination tree are independent until their common
  // ancestors: each part is a set of subtrees, solved on its own thread; the remaining columns
  // (the top of the tree) are solved alone. In the forward pass a part's updates to top rows go
  // to its own copy of them (block index blocks + part * topCount + position among the top
  // rows), summed before the top is solved: forwardTarget[slot] is where each slot's update goes.
  std::vector<std::vector<int>> partColumns;
  std::vector<int> topColumns, topPosition, forwardTarget;
  mutable std::vector<blocksolve::Lanes> y; // solve's scratch

  void partition(int parts)
  {
    std::vector<int> parent(blocks, -1);
    std::vector<std::vector<int>> children(blocks);
    std::vector<double> work(blocks, 0.0);
    std::vector<int> subtrees;
    double total = 0;
    for (int J = 0; J < blocks; ++J)
    {
      work[J] += 1 + columnStart[J + 1] - columnStart[J]; // parents come after their children
      total += 1 + columnStart[J + 1] - columnStart[J];
      if (columnStart[J + 1] > columnStart[J])
      {
        parent[J] = blockRow[columnStart[J]];
        work[parent[J]] += work[J];
        children[parent[J]].push_back(J);
      }
      else
        subtrees.push_back(J);
    }
    // Split the heaviest subtree until none outweighs a part's share, then deal them out
    // heaviest first to the lightest part.
    std::vector<char> top(blocks, 0);
    while (parts > 1 && !subtrees.empty())
    {
      auto heaviest = std::max_element(subtrees.begin(), subtrees.end(),
                                       [&](int a, int b) { return work[a] < work[b]; });
      if (work[*heaviest] <= total / parts) break;
      const int split = *heaviest;
      subtrees.erase(heaviest);
      top[split] = 1;
      subtrees.insert(subtrees.end(), children[split].begin(), children[split].end());
    }
    std::sort(subtrees.begin(), subtrees.end(), [&](int a, int b) { return work[a] > work[b]; });
    std::vector<double> load(parts, 0.0);
    std::vector<int> part(blocks, -1);
    for (int root : subtrees)
    {
      const int p = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
      load[p] += work[root];
      part[root] = p;
    }
    // Every column not on top belongs to the part of its subtree's root (found from the top
    // down, as parents come after their children).
    for (int J = blocks - 1; J >= 0; --J)
      if (!top[J] && part[J] < 0) part[J] = parent[J] >= 0 ? part[parent[J]] : 0;
    partColumns.assign(parts, {});
    topColumns.clear();
    topPosition.assign(blocks, -1);
    for (int J = 0; J < blocks; ++J)
      if (top[J])
      {
        topPosition[J] = static_cast<int>(topColumns.size());
        topColumns.push_back(J);
      }
      else
        partColumns[part[J]].push_back(J);
    const int topCount = static_cast<int>(topColumns.size());
    forwardTarget.resize(blockRow.size());
    for (int J = 0; J < blocks; ++J)
      for (int s = columnStart[J]; s < columnStart[J + 1]; ++s)
      {
        const int I = blockRow[s];
        forwardTarget[s] = top[J] || !top[I] ? I : blocks + part[J] * topCount + topPosition[I];
      }
  }

  void buildBlocks(const FactorMatrix& L)
  {
    const int* outer = L.outerIndexPtr();
    const int* inner = L.innerIndexPtr();
    const float* v = L.valuePtr();
    columnStart.assign(blocks + 1, 0);
    blockRow.clear();
    // The last column of a block column holds every block row below the diagonal block (each
    // column's pattern passes on to the next through the dense diagonal block).
    for (int J = 0; J < blocks; ++J)
    {
      int previous = -1;
      for (int k = outer[4 * J + 3] + 1; k < outer[4 * J + 4]; ++k)
        if (inner[k] / 4 != previous) blockRow.push_back(previous = inner[k] / 4);
      columnStart[J + 1] = static_cast<int>(blockRow.size());
    }
    value.assign(16 * blockRow.size(), 0);
    diagonalInverse.assign(16 * static_cast<size_t>(blocks), 0.0f);
    std::vector<int> slotOfRow(blocks, -1);
    for (int J = 0; J < blocks; ++J)
    {
      for (int s = columnStart[J]; s < columnStart[J + 1]; ++s) slotOfRow[blockRow[s]] = s;
      Eigen::Matrix4d diagonal = Eigen::Matrix4d::Zero();
      for (int c = 0; c < 4; ++c)
        for (int k = outer[4 * J + c]; k < outer[4 * J + c + 1]; ++k)
        {
          const int I = inner[k] / 4, r = inner[k] % 4;
          if (I == J)
            diagonal(r, c) = v[k];
          else
          {
            if (slotOfRow[I] < columnStart[J])
              throw Error("Block Cholesky: the factor is not made of 4x4 blocks.");
            value[16 * static_cast<size_t>(slotOfRow[I]) + 4 * c + r] = toBfloat16(v[k]);
          }
        }
      const Eigen::Matrix4d inverse =
          diagonal.triangularView<Eigen::Lower>().solve(Eigen::Matrix4d::Identity());
      Eigen::Map<Eigen::Matrix4f> stored(&diagonalInverse[16 * static_cast<size_t>(J)]);
      stored = inverse.cast<float>();
    }
    partition(kParts);
  }
};

BlockCholesky::BlockCholesky(const Matrix& lower) : impl_(std::make_unique<Impl>())
{
  if (lower.rows() != lower.cols() || lower.rows() % 4 != 0)
    throw Error("Block Cholesky: the matrix is " + std::to_string(lower.rows()) + " x " +
                std::to_string(lower.cols()) + ", not square with a size divisible by 4.");
  impl_->blocks = static_cast<int>(lower.rows() / 4);
  impl_->permutation = vertexBlockOrdering(lower);
  impl_->original.resize(lower.rows());
  for (Eigen::Index i = 0; i < lower.rows(); ++i)
    impl_->original[impl_->permutation.indices()[i]] = static_cast<int>(i);
}

BlockCholesky::~BlockCholesky() = default;

void BlockCholesky::factorise(const Matrix& lower)
{
  if (lower.rows() != 4 * impl_->blocks || lower.cols() != lower.rows())
    throw Error("Block Cholesky: the matrix does not have the analysed size.");
  FactorMatrix reordered(lower.rows(), lower.cols());
  reordered.selfadjointView<Eigen::Lower>() =
      lower.cast<float>().selfadjointView<Eigen::Lower>().twistedBy(impl_->permutation);
  Cholesky cholesky(reordered);
  if (cholesky.info() != Eigen::Success)
    throw Error("Block Cholesky: the matrix is not positive definite.");
  impl_->buildBlocks(cholesky.matrixL().nestedExpression());
}

Eigen::Index BlockCholesky::blockCount() const
{
  return static_cast<Eigen::Index>(impl_->blockRow.size()) + impl_->blocks;
}

void BlockCholesky::solve(const RightHandSides& rhs, RightHandSides& x) const
{
  const Impl& m = *impl_;
  const int n = 4 * m.blocks;
  if (rhs.rows() != n) throw Error("Block Cholesky: the right-hand sides do not match the matrix.");
  const int parts = static_cast<int>(m.partColumns.size());
  const size_t topCount = m.topColumns.size();
  // Entry J of y (three Lanes, one per right-hand side) holds the four unknowns of block J in
  // permuted order (BlockSolveKernel.h); the parts' copies of the top rows follow, zeroed.
  std::vector<blocksolve::Lanes>& y = m.y;
  y.resize(3 * (static_cast<size_t>(m.blocks) + parts * topCount));
  const int* original = m.original.data();
  parallelFor(
      0, m.blocks,
      [&](int J)
      {
        for (int c = 0; c < 3; ++c)
        {
          float* lanes = y[3 * static_cast<size_t>(J) + c].v;
          for (int r = 0; r < 4; ++r)
            lanes[r] = float(rhs(original[4 * J + r], c)), lanes[r + 4] = 0;
        }
      },
      1024);
  std::fill(y.begin() + 3 * static_cast<size_t>(m.blocks), y.end(), blocksolve::Lanes{});
  const blocksolve::Factor factor{m.columnStart.data(), m.blockRow.data(), m.forwardTarget.data(),
                                  m.value.data(), m.diagonalInverse.data()};
  const blocksolve::Kernel& kernel = blocksolve::bestKernel();
  auto run = [&](blocksolve::Pass pass, const std::vector<int>& columns)
  { pass(factor, columns.data(), static_cast<int>(columns.size()), y.data()); };
  parallelFor(
      0, parts, [&](int p) { run(kernel.forward, m.partColumns[p]); }, 1);
  for (size_t t = 0; t < topCount; ++t)
    for (int p = 0; p < parts; ++p)
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 8; ++k)
          y[3 * m.topColumns[t] + c].v[k] += y[3 * (m.blocks + p * topCount + t) + c].v[k];
  run(kernel.forward, m.topColumns);
  run(kernel.backward, m.topColumns);
  parallelFor(
      0, parts, [&](int p) { run(kernel.backward, m.partColumns[p]); }, 1);
  x.resize(n, 3);
  parallelFor(
      0, m.blocks,
      [&](int J)
      {
        for (int c = 0; c < 3; ++c)
          for (int r = 0; r < 4; ++r)
            x(original[4 * J + r], c) = y[3 * static_cast<size_t>(J) + c].v[r];
      },
      1024);
}
} // namespace clothtrack
