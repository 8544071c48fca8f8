// The numeric contract every stage relies on. Read this before touching a predicate.
//
// Projected edges carry integer x, y in [0, 2^20) units (plotter steps, or 2^-s steps: see
// kMaxSubstepBits) and an integer depth z in [0, 2^20). The viewer sits at z = +infinity: a
// larger z is nearer.
//
// Bit budget (all signed, two's complement):
//   coordinate               20 bits unsigned   [0, 2^20)
//   difference dx, dy, dz    21 bits signed     |d| <= 2^20 - 1
//   product of differences   41 bits signed     |dx*dy| < 2^40
//   2-D cross / dot product  42 bits signed     |cross| < 2^41
//   coordinate * cross       62 bits signed     used for exact depths and crossing points
// Everything that decides topology (does it cross, which cell owns the crossing, which edge
// is in front) therefore fits in int64_t and needs no 128-bit type. Only the exact-halo
// roots square a cross product; they use geometry/wide.h, written with 32-bit limbs so the
// same code runs on a Cortex-M4, which has no __int128.
#pragma once
#include <stddef.h>
#include <stdint.h>

namespace haloplot {

inline constexpr int kCoordBits = 20;
// Units: a projected scene may be fitted in units of 2^-s plot steps (View::substep_bits), the
// plot area times 2^s still inside [0, 2^20): the budget above is the same in any unit, and the
// unused high bits of a plot area far smaller than 2^20 steps become sub-step resolution.
// Emitted positions are rounded to whole steps once, at the path (geometry/units.h).
inline constexpr int kMaxSubstepBits = 8;
inline constexpr int32_t kCoordLimit = int32_t{1} << kCoordBits;  // exclusive upper bound
inline constexpr int32_t kCoordMax = kCoordLimit - 1;

inline constexpr int kDiffBits = kCoordBits + 1;       // signed differences
inline constexpr int kCrossBits = 2 * kCoordBits + 2;  // signed 2-D cross and dot products
inline constexpr int kCoordTimesCrossBits = kCoordBits + kCrossBits;  // exact depth / position

static_assert(int64_t{kCoordMax} * kCoordMax * 2 < (int64_t{1} << (kCrossBits - 1)),
              "cross product of two differences must fit kCrossBits");
static_assert(kCoordTimesCrossBits <= 63, "coordinate * cross must fit in int64_t");

// A projected 3-D edge. int32_t rather than packed bit fields: the hot loops read it directly.
struct Point3 {
  int32_t x, y, z;
};

struct Edge3 {
  Point3 a, b;
};

// A run of edges with its count: the count travels with its pointer, so an entry that also
// takes a capacity cannot have the two swapped (both would be uint32_t). From an array the
// count is the array's own.
struct Edges {
  const Edge3* data = nullptr;
  uint32_t count = 0;

  constexpr Edges() = default;
  constexpr Edges(const Edge3* edges, uint32_t n) : data(edges), count(n) {}
  template <size_t N>
  constexpr Edges(const Edge3 (&edges)[N]) : data(edges), count(uint32_t(N)) {  // NOLINT
    static_assert(N <= 0xffffffffu, "an edge count is 32 bits");
  }
};

inline bool in_range(int32_t v) { return v >= 0 && v <= kCoordMax; }
inline bool in_range(const Point3& p) { return in_range(p.x) && in_range(p.y) && in_range(p.z); }
inline bool in_range(const Edge3& e) { return in_range(e.a) && in_range(e.b); }

}  // namespace haloplot
