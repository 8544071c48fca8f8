// Scene helpers for the tests. The random generator is the host tool's (a generator, not code
// under test); hard families are built by hand in each test.
#pragma once
#include <cstdint>
#include <vector>

#include "demo/random_scene.h"
#include "haloplot/geometry/contract.h"

namespace scenes {

using haloplot::Edge3;
using haloplot::kCoordMax;
using haloplot::host::paper_random;
using Rng = haloplot::host::Rng;

inline Edge3 edge(int32_t x1, int32_t y1, int32_t z1, int32_t x2, int32_t y2, int32_t z2) {
  return Edge3{{x1, y1, z1}, {x2, y2, z2}};
}

}  // namespace scenes
