// Scene generators for the tests: the HALO paper's random distribution and the hard families
// (lattices on cell corners, stars, T-junctions, overlaps, near-parallel edges, range ends).
#pragma once
#include <cstdint>
#include <vector>

#include "geometry/contract.h"

namespace scenes {

using haloplot::Edge3;
using haloplot::kCoordMax;

// splitmix64: small, deterministic on every platform.
struct Rng {
  uint64_t s;
  explicit Rng(uint64_t seed) : s(seed) {}
  uint64_t next() {
    uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  int64_t uniform(int64_t lo, int64_t hi) {  // inclusive
    return lo + int64_t(next() % uint64_t(hi - lo + 1));
  }
};

// The paper's EDGE distribution: dx, dy uniform in [-L, L] on a 1 x 1 screen, the edge placed
// uniformly where it fits; depths uniform. L is given in millionths of the screen.
inline std::vector<Edge3> paper_random(uint32_t n, int64_t l_millionths, uint64_t seed) {
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

inline Edge3 edge(int32_t x1, int32_t y1, int32_t z1, int32_t x2, int32_t y2, int32_t z2) {
  return Edge3{{x1, y1, z1}, {x2, y2, z2}};
}

}  // namespace scenes
