// Random scenes in the HALO paper's EDGE distribution, freestanding so the chip can build
// the same scenes as the host from the same seed: each edge's dx and dy uniform in [-L, L]
// on a 1 x 1 screen (scaled to [0, 2^20) steps), placed uniformly where it fits, with
// independent uniform depths at both ends.
#pragma once
#include <stdint.h>

#include "haloplot/geometry/contract.h"

namespace haloplot {

// splitmix64: tiny, fast, and the same sequence on every target.
struct SplitMix64 {
  uint64_t s;
  explicit SplitMix64(uint64_t seed) : s(seed) {}
  uint64_t next() {
    uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  int64_t uniform(int64_t lo, int64_t hi) { return lo + int64_t(next() % uint64_t(hi - lo + 1)); }
};

// n edges into out; L in millionths of the screen side (the paper's L = 0.01 is 10000).
void random_edges(uint32_t n, int64_t l_millionths, uint64_t seed, Edge3* out);

}  // namespace haloplot
