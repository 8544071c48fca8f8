#include "haloplot/draw/halo.h"

#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/predicates.h"
#include "haloplot/geometry/wide.h"

namespace haloplot {
namespace {

constexpr Gap kEmpty{1, 0};
constexpr Gap kWhole{0, kFracOne};

Gap intersect(Gap a, Gap b) { return Gap{a.lo > b.lo ? a.lo : b.lo, a.hi < b.hi ? a.hi : b.hi}; }

Gap hull(Gap a, Gap b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  return Gap{a.lo < b.lo ? a.lo : b.lo, a.hi > b.hi ? a.hi : b.hi};
}

// { t : lo_num <= k0 + k1 * t <= hi_num } for a linear function, outward-rounded.
// |k0|, |k1|, |lo_num|, |hi_num| < 2^59.
Gap linear_band(int64_t k0, int64_t k1, int64_t lo_num, int64_t hi_num) {
  if (k1 == 0) return (k0 >= lo_num && k0 <= hi_num) ? Gap{-kFracOne, 2 * kFracOne} : kEmpty;
  int64_t a = lo_num - k0, b = hi_num - k0;  // k1 * t in [a, b]
  if (k1 < 0) {
    const int64_t t = -a;
    a = -b;
    b = t;
    k1 = -k1;
  }
  return Gap{q32_floor_clamped(a, k1), q32_ceil_clamped(b, k1)};
}

// { t : |P(t) - c| <= r } where P(t) = p + t * dp: roots of a t^2 + 2 b t + cc = 0.
Gap disc_gap(const Edge3& behind, int64_t cx, int64_t cy, int32_t r) {
  const int64_t dx = behind.b.x - behind.a.x, dy = behind.b.y - behind.a.y;
  const int64_t wx = behind.a.x - cx, wy = behind.a.y - cy;
  const int64_t a = dx * dx + dy * dy;                    // < 2^41
  const int64_t b = dot(dx, dy, wx, wy);                  // < 2^42
  const int64_t cc = wx * wx + wy * wy - int64_t{r} * r;  // < 2^42
  if (a == 0) return cc <= 0 ? kWhole : kEmpty;           // P is a single point
  const Wide disc = mul_i64(b, b) - mul_i64(a, cc);       // < 2^85
  if (disc.negative()) return kEmpty;
  uint64_t s = isqrt(disc);
  if (mul_u64(s, s) < disc) ++s;  // round the root up: the gap only grows
  const int64_t root = static_cast<int64_t>(s);
  return Gap{q32_floor_clamped(-b - root, a), q32_ceil_clamped(-b + root, a)};
}

}  // namespace

template <typename Sqrt>
Gap paper_gap(const Edge3& behind, const Edge3& front, uint32_t t32, int32_t halo) {
  // Differences of in-range coordinates (|.| < 2^kDiffBits): 32 x 32 -> 64 products.
  const int32_t pdx = behind.b.x - behind.a.x, pdy = behind.b.y - behind.a.y;
  const int32_t qdx = front.b.x - front.a.x, qdy = front.b.y - front.a.y;
  int64_t d = cross_diffs(pdx, pdy, qdx, qdy);  // nonzero: the edges cross properly
  if (d < 0) d = -d;
  if (d == 0) return kWhole;  // cannot happen for a CUT crossing; stay safe for bad input
  // half-gap in t = W * |dq| / |d|; numerator < 2^20 * 2^31.5, denominator < 2^51.
  const int64_t num = mul_32x64(halo, static_cast<int64_t>(Sqrt::length_q10_ceil(qdx, qdy)));
  const int64_t h = q32_ceil_clamped(num, d << 10);  // d > 0 here
  // The exact crossing lies in [t32, t32 + 1) / 2^32.
  return Gap{int64_t{t32} - h, int64_t{t32} + 1 + h};
}

template <typename Sqrt>
Gap exact_gap(const Edge3& behind, const Edge3& front, int32_t halo) {
  const int64_t pdx = behind.b.x - behind.a.x, pdy = behind.b.y - behind.a.y;
  const int64_t qdx = front.b.x - front.a.x, qdy = front.b.y - front.a.y;
  const int64_t wx = behind.a.x - front.a.x, wy = behind.a.y - front.a.y;
  Gap g = disc_gap(behind, front.a.x, front.a.y, halo);
  g = hull(g, disc_gap(behind, front.b.x, front.b.y, halo));
  const int64_t q2 = qdx * qdx + qdy * qdy;
  if (q2 != 0) {
    // The rectangle part of the stadium: within W of Q's line, and between the normals
    // through Q's endpoints. Distances to the line are cross / |dq|, so compare
    // cross * 2^10 with W * |dq| * 2^10 (|dq| rounded up).
    const int64_t width = int64_t{halo} * static_cast<int64_t>(Sqrt::length_q10_ceil(qdx, qdy));
    // Scale by multiplying: a left shift of a negative value is undefined in C++17.
    constexpr int64_t kQ10 = int64_t{1} << 10;
    const Gap strip = linear_band(cross(qdx, qdy, wx, wy) * kQ10, cross(qdx, qdy, pdx, pdy) * kQ10,
                                  -width, width);
    const Gap slab = linear_band(dot(qdx, qdy, wx, wy), dot(qdx, qdy, pdx, pdy), 0, q2);
    g = hull(g, intersect(strip, slab));
  }
  return g;
}

template Gap paper_gap<SqrtExact>(const Edge3&, const Edge3&, uint32_t, int32_t);
template Gap paper_gap<SqrtNewton>(const Edge3&, const Edge3&, uint32_t, int32_t);
template Gap paper_gap<SqrtTable>(const Edge3&, const Edge3&, uint32_t, int32_t);
template Gap exact_gap<SqrtExact>(const Edge3&, const Edge3&, int32_t);
template Gap exact_gap<SqrtNewton>(const Edge3&, const Edge3&, int32_t);
template Gap exact_gap<SqrtTable>(const Edge3&, const Edge3&, int32_t);

}  // namespace haloplot
