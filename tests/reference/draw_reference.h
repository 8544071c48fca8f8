// Independent reference for DRAW in long double (host-only test code): the paper's
// sign-counting sweep (D2.2-D2.5) over gaps computed without any of the core's integer tricks.
// Paper mode: t +/- W |dq| / |cross(dp, dq)|. Exact mode: the interval where the distance
// from P(t) to segment Q is at most W, found by ternary search for the closest point and
// bisection for the two ends: a different method from the core's closed-form stadium.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "haloplot/geometry/contract.h"

namespace reference {

using ld = long double;

struct RefSpan {
  uint32_t edge;
  ld x0, y0, x1, y1;
};

inline ld dist_point_segment(ld px, ld py, const haloplot::Edge3& q) {
  const ld dx = ld(q.b.x) - q.a.x, dy = ld(q.b.y) - q.a.y, l2 = dx * dx + dy * dy;
  ld u = l2 == 0 ? 0 : ((px - q.a.x) * dx + (py - q.a.y) * dy) / l2;
  u = std::clamp<ld>(u, 0, 1);
  return std::hypot(px - (q.a.x + u * dx), py - (q.a.y + u * dy));
}

// t-interval of P within distance w of Q (lo > hi if none), from scratch.
inline void exact_gap_ref(const haloplot::Edge3& p, const haloplot::Edge3& q, ld w, ld* lo,
                          ld* hi) {
  const ld dx = ld(p.b.x) - p.a.x, dy = ld(p.b.y) - p.a.y;
  auto f = [&](ld t) { return dist_point_segment(p.a.x + t * dx, p.a.y + t * dy, q); };
  ld a = -1, b = 2;  // gaps beyond [0, 1] are clipped anyway
  for (int i = 0; i < 300; ++i) {
    const ld m1 = a + (b - a) / 3, m2 = b - (b - a) / 3;
    if (f(m1) < f(m2))
      b = m2;
    else
      a = m1;
  }
  const ld tmin = (a + b) / 2;
  if (f(tmin) > w) {
    *lo = 1;
    *hi = 0;
    return;
  }
  ld l = -1, r = tmin;  // f(l) > w or l is beyond the clip, f(r) <= w
  for (int i = 0; i < 200; ++i) {
    const ld m = (l + r) / 2;
    (f(m) <= w ? r : l) = m;
  }
  *lo = r;
  l = tmin, r = 2;
  for (int i = 0; i < 200; ++i) {
    const ld m = (l + r) / 2;
    (f(m) <= w ? l : r) = m;
  }
  *hi = l;
}

struct RefGapInput {
  uint32_t behind, front;
  ld t;  // exact crossing position (unused in exact mode)
};

inline std::vector<RefSpan> draw_ref(const std::vector<haloplot::Edge3>& edges,
                                     const std::vector<RefGapInput>& cuts, ld w, bool exact_mode) {
  std::vector<std::vector<std::pair<ld, int>>> signs(edges.size());
  for (const RefGapInput& c : cuts) {
    const haloplot::Edge3 &p = edges[c.behind], &q = edges[c.front];
    ld lo, hi;
    if (exact_mode) {
      exact_gap_ref(p, q, w, &lo, &hi);
      if (lo > hi) continue;
    } else {
      const ld pdx = ld(p.b.x) - p.a.x, pdy = ld(p.b.y) - p.a.y;
      const ld qdx = ld(q.b.x) - q.a.x, qdy = ld(q.b.y) - q.a.y;
      const ld h = w * std::hypot(qdx, qdy) / std::fabs(pdx * qdy - pdy * qdx);
      lo = c.t - h;
      hi = c.t + h;
    }
    signs[c.behind].push_back({lo, -1});  // D2.2: halo starts
    signs[c.behind].push_back({hi, +1});  //       halo stops
  }
  std::vector<RefSpan> out;
  for (uint32_t e = 0; e < edges.size(); ++e) {
    auto& s = signs[e];
    s.push_back({0, +1});  // D2.3: the endpoints
    s.push_back({1, -1});
    std::sort(s.begin(), s.end(), [](auto a, auto b) {
      return a.first != b.first ? a.first < b.first : a.second > b.second;
    });
    int excess = 0;  // D2.5: + count minus - count
    ld start = 0;
    const haloplot::Edge3& p = edges[e];
    for (const auto& [t, sign] : s) {
      const int before = excess;
      excess += sign;
      if (before < 1 && excess == 1) start = t;
      if (before == 1 && excess < 1) {
        const ld a = std::clamp<ld>(start, 0, 1), b = std::clamp<ld>(t, 0, 1);
        if (b > a || (a == 0 && b == 0 && t == 1))
          out.push_back({e, p.a.x + a * (ld(p.b.x) - p.a.x), p.a.y + a * (ld(p.b.y) - p.a.y),
                         p.a.x + b * (ld(p.b.x) - p.a.x), p.a.y + b * (ld(p.b.y) - p.a.y)});
      }
    }
  }
  return out;
}

}  // namespace reference
