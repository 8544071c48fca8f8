// Exact 2-D predicates on projected edges. Every function here decides topology, so every
// one is exact integer arithmetic inside the budget of geometry/contract.h.
#pragma once
#include <stdint.h>

#include "haloplot/geometry/contract.h"
#include "haloplot/geometry/product.h"

namespace haloplot {

// cross(u, v) = u.x * v.y - u.y * v.x for differences of in-range coordinates: |.| < 2^41.
inline int64_t cross(int64_t ux, int64_t uy, int64_t vx, int64_t vy) { return ux * vy - uy * vx; }
inline int64_t dot(int64_t ux, int64_t uy, int64_t vx, int64_t vy) { return ux * vx + uy * vy; }

// The same for differences held in int32_t (|.| < 2^kDiffBits): 32 x 32 -> 64 products, which
// the Cortex-M0+ builds from 16-bit halves rather than calling a 64 x 64 multiply.
static_assert(kDiffBits <= 23, "a cross product of differences from 16-bit halves (product.h)");
inline int64_t cross_diffs(int32_t ux, int32_t uy, int32_t vx, int32_t vy) {
  return mul_narrow<kDiffBits, kDiffBits>(ux, vy) - mul_narrow<kDiffBits, kDiffBits>(uy, vx);
}

inline int sign(int64_t v) { return (v > 0) - (v < 0); }

// The outcome of testing two projected edges P and Q.
struct CrossingTest {
  bool crosses = false;  // the projections meet at one point interior to both
  // Valid only when crosses: the point is P.a + (P.b - P.a) * tn / den
  //                                   = Q.a + (Q.b - Q.a) * un / den, with 0 < tn, un < den.
  int64_t tn = 0, un = 0, den = 0;  // den > 0, den < 2^41
};

// Proper crossing test: the endpoints of each edge lie strictly on opposite sides of the
// other's line. A zero side value means an endpoint touches the other line (endpoint touch,
// T-junction, shared vertex, collinear overlap, or a zero-length edge), and none of those is
// a crossing under the contract, so strict signs are exactly the rule.
// E is any edge-like type with a.x, a.y, b.x, b.y: Edge3, or CUT's compact cell entries.
// Always inlined: its callers read `crosses` first, and out of line the Cortex-M0+ build (whose
// products are inline MULS sequences, geometry/product.h) zero-fills the whole result through
// memset on every test.
template <typename E>
__attribute__((always_inline)) inline CrossingTest test_crossing(const E& p, const E& q) {
  CrossingTest r;
  // Differences of in-range coordinates: |.| < 2^kDiffBits, int32_t.
  const int32_t pdx = p.b.x - p.a.x, pdy = p.b.y - p.a.y;
  const int32_t qdx = q.b.x - q.a.x, qdy = q.b.y - q.a.y;
  // Sides of Q's endpoints relative to P's line, and of P's endpoints relative to Q's line.
  const int64_t s1 = cross_diffs(pdx, pdy, q.a.x - p.a.x, q.a.y - p.a.y);
  const int64_t s2 = cross_diffs(pdx, pdy, q.b.x - p.a.x, q.b.y - p.a.y);
  if (sign(s1) * sign(s2) >= 0) return r;
  const int64_t s3 = cross_diffs(qdx, qdy, p.a.x - q.a.x, p.a.y - q.a.y);
  const int64_t s4 = cross_diffs(qdx, qdy, p.b.x - q.a.x, p.b.y - q.a.y);
  if (sign(s3) * sign(s4) >= 0) return r;
  // t along P = s3 / (s3 - s4); u along Q = s1 / (s1 - s2). Both denominators equal
  // +/- cross(dp, dq); using the side values keeps both numerators positive.
  int64_t den = s3 - s4;  // = cross(dp, dq), |.| < 2^41
  int64_t tn = s3, un = s1;
  if (den < 0) {
    den = -den;
    tn = -tn;
  }
  // s1 - s2 = -cross(dp, dq) = -(s3 - s4); fix the sign of un to the same positive den.
  if (s1 - s2 < 0) un = -un;
  r.crosses = true;
  r.tn = tn;
  r.un = un;
  r.den = den;
  return r;
}

// floor of a coordinate of the crossing point: a + floor(d * n / den). |d * n| < 2^62.
int32_t floor_along(int32_t a, int32_t d, int64_t n, int64_t den);

// Depth comparison at the crossing: sign of (depth of P) - (depth of Q), exactly. Each depth
// times den is a coordinate * den plus a difference * numerator: below 2^62 in magnitude.
// (Plain 64-bit products: on the Cortex-M0+ product.h's mul_32x64 measured no faster here.)
inline int compare_depth_at_crossing(const Edge3& p, const Edge3& q, const CrossingTest& c) {
  const int64_t zp = int64_t{p.a.z} * c.den + int64_t{p.b.z - p.a.z} * c.tn;
  const int64_t zq = int64_t{q.a.z} * c.den + int64_t{q.b.z - q.a.z} * c.un;
  return sign(zp - zq);
}

}  // namespace haloplot
