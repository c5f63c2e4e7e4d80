#include "BlockSolveKernel.h"

namespace clothtrack
{
namespace blocksolve
{
const Kernel& bestKernel()
{
  static const Kernel kernel = []
  {
#if defined(CLOTHTRACK_AVX2_KERNEL)
    __builtin_cpu_init();
    if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
      return Kernel{avx2::forward, avx2::backward, "avx2+fma"};
#endif
    return Kernel{generic::forward, generic::backward, "generic"};
  }();
  return kernel;
}
} // namespace blocksolve
} // namespace clothtrack
