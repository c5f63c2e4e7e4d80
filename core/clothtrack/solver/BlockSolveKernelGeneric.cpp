// The block solve kernel for any processor (BlockSolveKernel.inc).
#include "BlockSolveKernel.h"

namespace clothtrack
{
namespace blocksolve
{
namespace generic
{
#include "BlockSolveKernel.inc"
} // namespace generic
} // namespace blocksolve
} // namespace clothtrack
