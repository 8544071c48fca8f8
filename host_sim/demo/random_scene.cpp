#include "demo/random_scene.h"

#include <algorithm>

namespace haloplot::host {

std::vector<Edge3> paper_random(uint32_t n, int64_t l_millionths, uint64_t seed) {
  Rng r(seed);
  const int64_t s = kCoordMax;
  const int64_t l = l_millionths * s / 1000000;
  std::vector<Edge3> out;
  out.reserve(n);
  for (uint32_t i = 0; i < n; ++i) {
    const int64_t dx = r.uniform(-l, l), dy = r.uniform(-l, l);
    const int64_t x = r.uniform(std::max<int64_t>(0, -dx), std::min<int64_t>(s, s - dx));
    const int64_t y = r.uniform(std::max<int64_t>(0, -dy), std::min<int64_t>(s, s - dy));
    out.push_back(Edge3{{int32_t(x), int32_t(y), int32_t(r.uniform(0, s))},
                        {int32_t(x + dx), int32_t(y + dy), int32_t(r.uniform(0, s))}});
  }
  return out;
}

}  // namespace haloplot::host
