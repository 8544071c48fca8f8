// The core's one binary search. below(i) must be true on a prefix of [lo, hi) and false after
// it (a sorted array asked "is element i before the key?"); the answer is the first index where
// it is false, hi if none. Each caller says what "below" means, so one loop serves arrays of
// keys, of indices into another array and of computed values alike.
#pragma once
#include <stdint.h>

namespace haloplot {

template <typename Below>
inline uint32_t lower_bound_index(uint32_t lo, uint32_t hi, Below below) {
  while (lo < hi) {
    const uint32_t mid = lo + (hi - lo) / 2;
    if (below(mid))
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo;
}

}  // namespace haloplot
