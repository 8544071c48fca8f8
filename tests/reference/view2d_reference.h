// Brute-force visibility for the 2-D hidden-line problem (host-only, __int128, independent of
// core/view2d). For each edge: its critical directions from E are the rays through its two
// ends and through every vertex strictly inside its wedge; between two neighbouring critical
// rays the nearest edge along any ray is the same one, so one exact ray cast, along the sum
// of the two direction vectors (strictly between them), decides the whole interval: visible
// when the nearest crossing is this edge. Intervals come out as exact ratios along the edge.
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

namespace reference {

struct Pt {
  int64_t x, y;
};
struct Frac {
  __int128 num, den;  // den > 0
};
inline bool frac_less(const Frac& a, const Frac& b) { return a.num * b.den < b.num * a.den; }
inline bool frac_eq(const Frac& a, const Frac& b) { return a.num * b.den == b.num * a.den; }

struct Interval {
  uint32_t edge;
  Frac s0, s1;
};

inline __int128 cr(__int128 ax, __int128 ay, __int128 bx, __int128 by) { return ax * by - ay * bx; }

// Nearest crossing of the ray E + tau d (tau > 0) with the polygon's edges: the edge index, or
// -1. No vertex lies on the ray by construction, so crossings are proper.
inline int nearest_edge(const std::vector<Pt>& p, Pt e, __int128 dx, __int128 dy) {
  const size_t n = p.size();
  int best = -1;
  Frac best_t{0, 1};
  for (size_t k = 0; k < n; ++k) {
    const Pt a = p[k], b = p[(k + 1) % n];
    const __int128 oa = cr(dx, dy, a.x - e.x, a.y - e.y), ob = cr(dx, dy, b.x - e.x, b.y - e.y);
    if (oa == 0 || ob == 0 || (oa > 0) == (ob > 0)) continue;
    // tau = cross(a - e, b - a) / cross(d, b - a)
    __int128 num = cr(a.x - e.x, a.y - e.y, b.x - a.x, b.y - a.y),
             den = cr(dx, dy, b.x - a.x, b.y - a.y);
    if (den < 0) num = -num, den = -den;
    if (num <= 0) continue;  // behind E
    const Frac t{num, den};
    if (best < 0 || frac_less(t, best_t)) best = int(k), best_t = t;
  }
  return best;
}

inline std::vector<Interval> visible_brute(const std::vector<Pt>& p, Pt e) {
  const size_t n = p.size();
  std::vector<Interval> out;
  for (size_t i = 0; i < n; ++i) {
    const Pt u = p[i], w = p[(i + 1) % n];
    const __int128 ux = u.x - e.x, uy = u.y - e.y, wx = w.x - e.x, wy = w.y - e.y;
    const __int128 wedge = cr(ux, uy, wx, wy);
    if (wedge == 0) continue;  // seen edge-on
    // Critical directions, ordered from u's ray to w's ray.
    const bool ccw = wedge > 0;
    std::vector<Pt> inner;
    for (size_t k = 0; k < n; ++k) {
      const __int128 vx = p[k].x - e.x, vy = p[k].y - e.y;
      const __int128 a = cr(ux, uy, vx, vy), b = cr(vx, vy, wx, wy);
      if (ccw ? (a > 0 && b > 0) : (a < 0 && b < 0)) inner.push_back({int64_t(vx), int64_t(vy)});
    }
    std::sort(inner.begin(), inner.end(), [&](const Pt& a, const Pt& b) {
      const __int128 c = cr(a.x, a.y, b.x, b.y);
      return ccw ? c > 0 : c < 0;
    });
    // Parameter along the edge of the point on each critical ray.
    auto s_of = [&](const Pt& r) {
      Frac f{cr(e.x - u.x, e.y - u.y, r.x, r.y), cr(w.x - u.x, w.y - u.y, r.x, r.y)};
      if (f.den < 0) f.num = -f.num, f.den = -f.den;
      return f;
    };
    std::vector<Pt> ordered = {{int64_t(ux), int64_t(uy)}};
    std::vector<Frac> cuts = {Frac{0, 1}};
    for (const Pt& r : inner) ordered.push_back(r), cuts.push_back(s_of(r));
    ordered.push_back({int64_t(wx), int64_t(wy)});
    cuts.push_back(Frac{1, 1});
    for (size_t k = 0; k + 1 < ordered.size(); ++k) {
      if (!frac_less(cuts[k], cuts[k + 1])) continue;  // two vertices on one ray
      const __int128 dx = __int128(ordered[k].x) + ordered[k + 1].x,
                     dy = __int128(ordered[k].y) + ordered[k + 1].y;
      if (nearest_edge(p, e, dx, dy) != int(i)) continue;
      if (!out.empty() && out.back().edge == i && frac_eq(out.back().s1, cuts[k]))
        out.back().s1 = cuts[k + 1];
      else
        out.push_back({uint32_t(i), cuts[k], cuts[k + 1]});
    }
  }
  return out;
}

}  // namespace reference
