#pragma once
// The inner loops of BlockCholesky::solve on plain arrays, compiled once for any x86-64 (or other)
// processor and once more for AVX2 with fused multiply-add, chosen when the program starts.
// The kernel files include no Eigen and no standard containers, so that nothing compiled with
// the wider instructions can be shared with (and run by) the rest of the library.
#include <cstdint>

namespace clothtrack
{
namespace blocksolve
{
/// Eight floats: the four unknowns of a block for one right-hand side, twice. In the forward
/// pass the value is the sum of the two halves (partial sums of even and odd factor columns);
/// once a block is solved both halves hold its solution.
struct alignas(32) Lanes
{
  float v[8];
};

/// The factor L in 4x4 blocks, as kept by BlockCholesky (permuted order).
struct Factor
{
  const int* columnStart;       ///< off-diagonal slots of block column J: [columnStart[J], [J+1])
  const int* blockRow;          ///< block row of each slot (greater than its column)
  const int* forwardTarget;     ///< where the forward pass adds each slot's update (an entry of y)
  const std::uint16_t* value;   ///< 16 bfloat16 per slot, value[16 s + 4 k + r] = L(4I + r, 4J + k)
  const float* diagonalInverse; ///< 16 per block, column-major, lower triangular
};

/// y holds 3 Lanes per entry (right-hand sides 0, 1, 2).
/// forward: solves the block columns columns[0 .. count-1] in that order (L z = y).
/// backward: solves them in reverse order (L^T x = z).
using Pass = void (*)(const Factor& factor, const int* columns, int count, Lanes* y);

struct Kernel
{
  Pass forward;
  Pass backward;
  const char* instructions; ///< "avx2+fma" or "generic"
};

/// The fastest kernel this processor runs.
const Kernel& bestKernel();

// The compiled variants (BlockSolveKernel.inc).
namespace generic
{
void forward(const Factor& factor, const int* columns, int count, Lanes* y);
void backward(const Factor& factor, const int* columns, int count, Lanes* y);
} // namespace generic
namespace avx2
{
void forward(const Factor& factor, const int* columns, int count, Lanes* y);
void backward(const Factor& factor, const int* columns, int count, Lanes* y);
} // namespace avx2
} // namespace blocksolve
} // namespace clothtrack
