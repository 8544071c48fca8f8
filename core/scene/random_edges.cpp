#include "haloplot/scene/random_edges.h"

namespace haloplot {

void random_edges(uint32_t n, int64_t l_millionths, uint64_t seed, Edge3* out) {
  SplitMix64 r(seed);
  const int64_t s = kCoordMax;
  const int64_t l = l_millionths * s / 1000000;
  for (uint32_t i = 0; i < n; ++i) {
    const int64_t dx = r.uniform(-l, l), dy = r.uniform(-l, l);
    const int64_t x = r.uniform(dx < 0 ? -dx : 0, dx > 0 ? s - dx : s);
    const int64_t y = r.uniform(dy < 0 ? -dy : 0, dy > 0 ? s - dy : s);
    const int32_t z0 = int32_t(r.uniform(0, s));
    const int32_t z1 = int32_t(r.uniform(0, s));
    out[i] = Edge3{{int32_t(x), int32_t(y), z0}, {int32_t(x + dx), int32_t(y + dy), z1}};
  }
}

}  // namespace haloplot
