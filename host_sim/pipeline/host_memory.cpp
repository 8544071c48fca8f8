#include "pipeline/host_memory.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace haloplot::host {

void give_back_freed_memory() {
#if defined(__GLIBC__)
  // Only a large model's freed heap is worth giving back: below this, what is free is mostly
  // main.cpp's 16 MB top pad, and the next stage's buffers (under HostMemory's 8 MB, from the
  // heap) reuse pages already there; given back, each page costs a fault again when touched
  // (about 490 of them in a 2,000-triangle torus's hidden lines, a fifth of its time).
  constexpr size_t kWorthGivingBack = size_t{32} << 20;
#if __GLIBC_PREREQ(2, 33)
  if (mallinfo2().fordblks < kWorthGivingBack) return;
#else
  if (size_t(unsigned(mallinfo().fordblks)) < kWorthGivingBack) return;
#endif
  malloc_trim(0);
#endif
}

}  // namespace haloplot::host
