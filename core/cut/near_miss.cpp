#include "cut/near_miss.h"

#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/predicates.h"
#include "haloplot/geometry/wide.h"

namespace haloplot {
namespace {

// Squared distance from endpoint v to segment s, as the exact rational num / den, plus the
// foot's position k / den along s (clamped to [0, den]).
struct PointToSegment {
  Wide num;
  uint64_t den = 1;  // |ds|^2 (< 2^41) when the foot is interior, else 1
  int64_t k = 0;     // foot position numerator, over |ds|^2
  int64_t len2 = 0;  // |ds|^2
};

PointToSegment point_to_segment(const Point3& v, const Edge3& s) {
  PointToSegment r;
  const int64_t dx = s.b.x - s.a.x, dy = s.b.y - s.a.y;
  const int64_t wx = v.x - s.a.x, wy = v.y - s.a.y;
  r.len2 = dx * dx + dy * dy;
  const int64_t k = dot(wx, wy, dx, dy);
  if (r.len2 == 0 || k <= 0) {
    r.num = Wide::from_i64(wx * wx + wy * wy);
    r.k = 0;
    return r;
  }
  if (k >= r.len2) {
    const int64_t ux = v.x - s.b.x, uy = v.y - s.b.y;
    r.num = Wide::from_i64(ux * ux + uy * uy);
    r.k = r.len2;
    return r;
  }
  const int64_t c = cross(dx, dy, wx, wy);  // |c| < 2^42: c^2 < 2^84
  r.num = mul_i64(c, c);
  r.den = static_cast<uint64_t>(r.len2);
  r.k = k;
  return r;
}

// a.num / a.den < b.num / b.den, exactly: products below 2^84 * 2^41 = 2^125.
bool less_distance(const PointToSegment& a, const PointToSegment& b) {
  return mul_wide_u64(a.num, b.den) < mul_wide_u64(b.num, a.den);
}

}  // namespace

NearMiss test_near_miss(const Edge3& p, const Edge3& q, int32_t reach) {
  NearMiss r;
  // The four endpoint-to-segment distances; for segments that do not properly cross, the
  // smallest is the distance between them. Ties keep the first in this fixed order, so the
  // owning endpoint is the same whichever cell asks.
  const Point3* ends[4] = {&p.a, &p.b, &q.a, &q.b};
  const Edge3* others[4] = {&q, &q, &p, &p};
  PointToSegment best = point_to_segment(*ends[0], *others[0]);
  int best_i = 0;
  for (int i = 1; i < 4; ++i) {
    const PointToSegment c = point_to_segment(*ends[i], *others[i]);
    if (less_distance(c, best)) {
      best = c;
      best_i = i;
    }
  }
  const Wide limit = mul_u64(static_cast<uint64_t>(reach) * static_cast<uint64_t>(reach), best.den);
  if (limit < best.num) return r;

  // Depth at the endpoint against depth at its foot on the other edge, both times |ds|^2:
  // z * 2^41 and dz * k stay below 2^62.
  const Point3& v = *ends[best_i];
  const Edge3& s = *others[best_i];
  const int64_t len2 = best.len2 == 0 ? 1 : best.len2;
  const int64_t k = best.len2 == 0 ? 0 : best.k;
  const int64_t z_end = int64_t{v.z} * len2;
  const int64_t z_foot = int64_t{s.a.z} * len2 + int64_t{s.b.z - s.a.z} * k;
  if (z_end == z_foot) return r;  // the edges meet in space: neither is cut

  const bool end_is_on_p = best_i < 2;
  const bool end_behind = z_end < z_foot;
  r.found = true;
  r.p_behind = end_is_on_p ? end_behind : !end_behind;
  r.ex = v.x;
  r.ey = v.y;
  if (end_behind) {
    // The behind edge owns the endpoint: t is 0 or 1 (saturated to the largest Q0.32).
    r.t_behind = (best_i % 2 == 0) ? 0u : 0xffffffffu;
  } else {
    r.t_behind = k >= len2 ? 0xffffffffu : frac_q32_small(k, len2);
  }
  return r;
}

}  // namespace haloplot
