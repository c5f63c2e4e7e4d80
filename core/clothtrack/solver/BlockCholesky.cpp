#include "BlockCholesky.h"

#include "BlockSolveKernel.h"
#include <clothtrack/base/Error.h>
#include <clothtrack/base/Parallel.h>

#include <Eigen/Cholesky>
#include <Eigen/OrderingMethods>

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

  // Row J of L: the columns K < J with a block L_JK (ascending), and that block's slot.
  std::vector<int> rowStart, rowColumn, rowSlot;

  /// The block pattern of L from the block graph of the permuted matrix (lowerNeighbours[I]: the
  /// blocks J < I coupled to I), by walking the elimination tree from each coupling (Liu).
  void analyse(const std::vector<std::vector<int>>& lowerNeighbours)
  {
    std::vector<int> parent(blocks, -1), mark(blocks, -1);
    std::vector<std::vector<int>> columnRows(blocks);
    for (int I = 0; I < blocks; ++I)
    {
      mark[I] = I;
      for (int J : lowerNeighbours[I])
        for (int K = J; mark[K] != I; K = parent[K])
        {
          if (parent[K] < 0) parent[K] = I;
          columnRows[K].push_back(I); // rows arrive in increasing order
          mark[K] = I;
        }
    }
    columnStart.assign(blocks + 1, 0);
    for (int J = 0; J < blocks; ++J)
      columnStart[J + 1] = columnStart[J] + static_cast<int>(columnRows[J].size());
    blockRow.resize(columnStart[blocks]);
    for (int J = 0; J < blocks; ++J)
      std::copy(columnRows[J].begin(), columnRows[J].end(), blockRow.begin() + columnStart[J]);
    rowStart.assign(blocks + 1, 0);
    for (int I : blockRow) ++rowStart[I + 1];
    for (int J = 0; J < blocks; ++J) rowStart[J + 1] += rowStart[J];
    rowColumn.resize(blockRow.size());
    rowSlot.resize(blockRow.size());
    std::vector<int> fill(rowStart.begin(), rowStart.end() - 1);
    for (int K = 0; K < blocks; ++K)
      for (int slot = columnStart[K]; slot < columnStart[K + 1]; ++slot)
      {
        const int at = fill[blockRow[slot]]++;
        rowColumn[at] = K;
        rowSlot[at] = slot;
      }
    value.assign(16 * blockRow.size(), 0);
    diagonalInverse.assign(16 * static_cast<size_t>(blocks), 0.0f);
    partition(kParts);
  }

  /// Left-looking Cholesky on the 4x4 blocks, in float: column J gathers the updates of the
  /// columns K of row J, then is scaled by the inverse of its diagonal block's factor. `work`
  /// holds the matrix's blocks in the slots of L (layout as `value`), `diagonal` its diagonal
  /// blocks; both are overwritten.
  void factoriseBlocks(std::vector<float>& work, std::vector<float>& diagonal)
  {
    using Block = Eigen::Map<Eigen::Matrix4f>;
    // Columns only receive updates from their descendants in the elimination tree: the parts of
    // the solve (BlockSolveKernel.h) are factorised side by side, then the top of the tree.
    auto factoriseColumn = [&](int J, std::vector<int>& slotOfRow)
    {
      for (int s = columnStart[J]; s < columnStart[J + 1]; ++s) slotOfRow[blockRow[s]] = s;
      Block D(&diagonal[16 * static_cast<size_t>(J)]);
      for (int at = rowStart[J]; at < rowStart[J + 1]; ++at)
      {
        const int K = rowColumn[at], slotJK = rowSlot[at];
        const Eigen::Matrix4f LJK = Block(&work[16 * static_cast<size_t>(slotJK)]);
        D.noalias() -= LJK * LJK.transpose();
        // Every row below J in column K is also in column J.
        for (int t = slotJK + 1; t < columnStart[K + 1]; ++t)
          Block(&work[16 * static_cast<size_t>(slotOfRow[blockRow[t]])]).noalias() -=
              Block(&work[16 * static_cast<size_t>(t)]) * LJK.transpose();
      }
      const Eigen::LLT<Eigen::Matrix4f> llt(D);
      const Eigen::Matrix4f inverse =
          llt.matrixL().solve(Eigen::Matrix4f::Identity()); // lower triangular
      if (llt.info() != Eigen::Success || !inverse.allFinite())
        throw Error("Block Cholesky: the matrix is not positive definite.");
      Block stored(&diagonalInverse[16 * static_cast<size_t>(J)]);
      stored = inverse;
      for (int s = columnStart[J]; s < columnStart[J + 1]; ++s)
      {
        Block L(&work[16 * static_cast<size_t>(s)]);
        L = (L * inverse.transpose()).eval();
        for (int k = 0; k < 16; ++k)
          value[16 * static_cast<size_t>(s) + k] = toBfloat16(L.data()[k]);
      }
    };
    const int parts = static_cast<int>(partColumns.size());
    std::vector<std::vector<int>> slotOfRow(parts + 1, std::vector<int>(blocks, -1));
    parallelFor(
        0, parts,
        [&](int p)
        {
          for (int J : partColumns[p]) factoriseColumn(J, slotOfRow[p]);
        },
        1);
    for (int J : topColumns) factoriseColumn(J, slotOfRow[parts]);
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
  const int* permuted = impl_->permutation.indices().data();
  std::vector<std::vector<int>> lowerNeighbours(impl_->blocks);
  for (Eigen::Index c = 0; c < lower.outerSize(); ++c)
    for (Matrix::InnerIterator it(lower, c); it; ++it)
    {
      const int I = permuted[it.row()] / 4, J = permuted[c] / 4;
      if (I != J) lowerNeighbours[std::max(I, J)].push_back(std::min(I, J));
    }
  for (auto& neighbours : lowerNeighbours)
  {
    std::sort(neighbours.begin(), neighbours.end());
    neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
  }
  impl_->analyse(lowerNeighbours);
}

BlockCholesky::~BlockCholesky() = default;

void BlockCholesky::factorise(const Matrix& lower)
{
  if (lower.rows() != 4 * impl_->blocks || lower.cols() != lower.rows())
    throw Error("Block Cholesky: the matrix does not have the analysed size.");
  Impl& m = *impl_;
  // Float copies, needed only while factorising (13 MB for a 10k-vertex template).
  std::vector<float> work(16 * m.blockRow.size(), 0.0f);
  std::vector<float> diagonal(16 * static_cast<size_t>(m.blocks), 0.0f);
  // The permuted lower triangle into the blocks of L's pattern (entries above the diagonal of a
  // block are mirrored: the diagonal blocks are kept whole).
  const int* permuted = m.permutation.indices().data();
  for (Eigen::Index c = 0; c < lower.outerSize(); ++c)
    for (Matrix::InnerIterator it(lower, c); it; ++it)
    {
      int row = permuted[it.row()], column = permuted[c];
      if (row < column) std::swap(row, column);
      const int I = row / 4, J = column / 4, r = row % 4, k = column % 4;
      const float v = static_cast<float>(it.value());
      if (I == J)
      {
        diagonal[16 * static_cast<size_t>(J) + 4 * k + r] = v;
        diagonal[16 * static_cast<size_t>(J) + 4 * r + k] = v;
        continue;
      }
      const int* begin = m.blockRow.data() + m.columnStart[J];
      const int* end = m.blockRow.data() + m.columnStart[J + 1];
      const int* slot = std::lower_bound(begin, end, I);
      if (slot == end || *slot != I)
        throw Error("Block Cholesky: the matrix has an entry outside the analysed pattern.");
      work[16 * static_cast<size_t>(slot - m.blockRow.data()) + 4 * k + r] = v;
    }
  m.factoriseBlocks(work, diagonal);
}

Eigen::Index BlockCholesky::blockCount() const
{
  return static_cast<Eigen::Index>(impl_->blockRow.size()) + impl_->blocks;
}

void BlockCholesky::solve(const RightHandSides& rhs, RightHandSides& x) const
{
  solveDot(rhs, x);
}

double BlockCholesky::solveDot(const RightHandSides& rhs, RightHandSides& x) const
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
  // The scatter back to the original order gives rhs . x on the way.
  return parallelSum(m.blocks,
                     [&](long from, long to)
                     {
                       double dot = 0;
                       for (long J = from; J < to; ++J)
                         for (int r = 0; r < 4; ++r)
                         {
                           const int row = original[4 * J + r];
                           for (int c = 0; c < 3; ++c)
                           {
                             const double value = y[3 * J + c].v[r];
                             x(row, c) = value;
                             dot += rhs(row, c) * value;
                           }
                         }
                       return dot;
                     });
}
} // namespace clothtrack
