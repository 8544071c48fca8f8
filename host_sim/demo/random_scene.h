// Random scenes in the HALO paper's EDGE distribution on the host: the core's freestanding
// generator (core/include/haloplot/scene/random_edges.h) into a vector, so the chip and the host
// build the same scene from the same seed.
#pragma once
#include <cstdint>
#include <vector>

#include "haloplot/scene/random_edges.h"

namespace haloplot::host {

using Rng = haloplot::SplitMix64;

// L in millionths of the screen side (the paper's L = 0.01 is 10000).
inline std::vector<Edge3> paper_random(uint32_t n, int64_t l_millionths, uint64_t seed) {
  std::vector<Edge3> out(n);
  haloplot::random_edges(n, l_millionths, seed, out.data());
  return out;
}

}  // namespace haloplot::host
