#include "drivers/realtime/heap_policy.h"

#include <cstdlib>  // defines __GLIBC__ on glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace deepnav {

bool fixHeapPolicy() {
#if defined(__GLIBC__) && !defined(__SANITIZE_ADDRESS__) && !defined(__SANITIZE_THREAD__)
  // Setting M_MMAP_THRESHOLD explicitly also turns off glibc's dynamic adjustment of it and of
  // M_TRIM_THRESHOLD (mallopt(3)), which is the point: the threshold must not follow freed blocks upwards.
  if (::mallopt(M_MMAP_THRESHOLD, kMmapThresholdBytes) != 1) return false;
  // A heap top grown before the call (static initialisers, a test framework) would still serve image-sized
  // requests from the arena: give it back so the next one is mapped.
  ::malloc_trim(0);
  return true;
#else
  return false;
#endif
}

}  // namespace deepnav
