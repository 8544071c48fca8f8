#include "platform/c_runtime.h"

// Stack bytes never touched since boot: painted words still intact, from the bottom up.
extern "C" uint32_t stack_unused_bytes() {
  uint32_t n = 0;
  for (const uint32_t* p = &__stack_limit; p < &__stack_top && *p == haloplot::fw::kStackPaint; ++p)
    n += 4;
  return n;
}
