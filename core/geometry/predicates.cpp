#include "haloplot/geometry/predicates.h"

#include "haloplot/geometry/fraction.h"

namespace haloplot {

static_assert(kDiffBits + kCrossBits <= 63, "difference * crossing numerator must fit int64");

int32_t floor_along(int32_t a, int32_t d, int64_t n, int64_t den) {
  return a + static_cast<int32_t>(floor_div(int64_t{d} * n, den));
}

}  // namespace haloplot
