// Near misses (the HALO paper's Figure 5): two projected edges that do not cross but pass
// within `reach` steps of each other. The exact-halo DRAW mode cuts the farther one there too.
#pragma once
#include <stdint.h>

#include "haloplot/geometry/contract.h"

namespace haloplot {

struct NearMiss {
  bool found = false;
  bool p_behind = false;   // true: P is the farther edge at the closest approach
  int32_t ex = 0, ey = 0;  // the endpoint that realises the closest approach (owns the pair)
  uint32_t t_behind = 0;   // closest-approach position along the behind edge, Q0.32 (saturated)
};

// Exact test, for two edges that do not properly cross: is their distance <= reach, and if
// so which is behind at the closest approach? Squared distances are compared as exact
// rationals with 128-bit products. Equal depths there mean the edges meet in space: no record.
NearMiss test_near_miss(const Edge3& p, const Edge3& q, int32_t reach);

}  // namespace haloplot
