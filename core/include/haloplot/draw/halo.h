// The halo gap that one front edge cuts into one behind edge, as an interval of positions
// along the behind edge in Q0.32 (paper D2.2). Two ways to size it:
//
//   kPaper: the paper's effective half-gap W / sin(theta) around the crossing point. In units
//           of t along the behind edge P that is W * |dq| / |cross(dp, dq)|, which grows without
//           bound as the edges turn parallel.
//   kExact: exactly the part of P that lies within distance W of the front segment Q: the
//           line of P clipped by the stadium (Q swept by a disc of radius W). It stays bounded
//           for near-parallel edges, ends where Q ends, and also covers near misses.
//
// Rounding: gap ends are rounded outward (start down, end up) to the Q0.32 grid, and the
// irrational lengths use integer square roots rounded up, so a gap never comes out smaller
// than the exact one; it is larger by less than 2^-11 steps plus W * 2^-10 / (|dq| sin(theta))
// steps (the Q10 length of the front edge).
#pragma once
#include <stdint.h>

#include "haloplot/draw/precision.h"
#include "haloplot/geometry/contract.h"

namespace haloplot {

enum class HaloMode : uint8_t { kPaper, kExact };

struct Gap {
  int64_t lo, hi;  // Q0.32 positions along the behind edge; empty when lo > hi
  bool empty() const { return lo > hi; }
};

// The paper's gap around a crossing at t32 (floor of the exact position). Sqrt is a square
// root policy of draw/precision.h (instantiated for the three there).
template <typename Sqrt = SqrtExact>
Gap paper_gap(const Edge3& behind, const Edge3& front, uint32_t t32, int32_t halo);

// The exact gap: positions of `behind` within distance `halo` of `front` (may be empty).
template <typename Sqrt = SqrtExact>
Gap exact_gap(const Edge3& behind, const Edge3& front, int32_t halo);

}  // namespace haloplot
