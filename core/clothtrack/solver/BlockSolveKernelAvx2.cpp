// The block solve kernel for processors with AVX2 and FMA (BlockSolveKernel.inc); the build
// compiles this file alone with those instructions.
#include "BlockSolveKernel.h"

namespace clothtrack
{
namespace blocksolve
{
namespace avx2
{
#include "BlockSolveKernel.inc"
} // namespace avx2
} // namespace blocksolve
} // namespace clothtrack
