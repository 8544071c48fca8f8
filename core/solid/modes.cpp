#include "haloplot/solid/modes.h"

#include "haloplot/geometry/wide.h"

namespace haloplot {

int64_t paper_length(const Edge3& e) {
  const int64_t dx = e.b.x - e.a.x, dy = e.b.y - e.a.y;
  const int64_t l = isqrt_u64(static_cast<uint64_t>(dx * dx + dy * dy));
  return l > 0 ? l : 1;
}

}  // namespace haloplot
