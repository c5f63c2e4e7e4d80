#include "MemoryReuse.h"

#include <cstdlib> // defines __GLIBC__ where the C library is glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace clothtrack
{
void keepFreedMemoryForReuse()
{
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
#endif
}

void releaseFreedMemory()
{
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}
} // namespace clothtrack
