// Independent reference for CUT: every pair of edges whose x-extents overlap (a sort by x only
// skips pairs that cannot meet), decided with the paper's line equations
// alpha*X + beta*Y + gamma = 0 in 128-bit integers. Shares no code with core/.
#pragma once
#include <algorithm>
#include <cstdint>
#include <tuple>
#include <vector>

#include "haloplot/geometry/contract.h"  // the Edge3 struct only

namespace reference {

using i128 = __int128;

struct Record {
  uint32_t behind, front;
  uint32_t t;  // floor(t * 2^32) along behind
  bool operator<(const Record& o) const {
    return std::tie(behind, t, front) < std::tie(o.behind, o.t, o.front);
  }
  bool operator==(const Record& o) const {
    return behind == o.behind && front == o.front && t == o.t;
  }
};

struct Line {
  i128 alpha, beta, gamma;  // alpha*x + beta*y + gamma: zero on the line
  i128 side(i128 x, i128 y) const { return alpha * x + beta * y + gamma; }
};

inline Line line_of(const haloplot::Edge3& e) {
  return Line{i128(e.b.y) - e.a.y, i128(e.a.x) - e.b.x, i128(e.b.x) * e.a.y - i128(e.a.x) * e.b.y};
}

inline int sgn(i128 v) { return (v > 0) - (v < 0); }

// Position along p of its proper crossing with q, as num / den (den > 0); false if none.
inline bool crossing(const haloplot::Edge3& p, const haloplot::Edge3& q, i128* num, i128* den) {
  const Line lp = line_of(p), lq = line_of(q);
  const int a = sgn(lq.side(p.a.x, p.a.y)), b = sgn(lq.side(p.b.x, p.b.y));
  const int c = sgn(lp.side(q.a.x, q.a.y)), d = sgn(lp.side(q.b.x, q.b.y));
  if (a == 0 || b == 0 || c == 0 || d == 0 || a == b || c == d) return false;
  // side of P(t) w.r.t. q is linear in t: s(t) = sa + (sb - sa) t = 0.
  const i128 sa = lq.side(p.a.x, p.a.y), sb = lq.side(p.b.x, p.b.y);
  *num = sa;
  *den = sa - sb;
  if (*den < 0) {
    *num = -*num;
    *den = -*den;
  }
  return true;
}

struct Result {
  std::vector<Record> records;
  uint64_t equal_depth = 0;
};

inline Result brute_cut(const std::vector<haloplot::Edge3>& edges) {
  Result r;
  const size_t n = edges.size();
  std::vector<uint32_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = uint32_t(i);
  auto xmin = [&](uint32_t i) { return std::min(edges[i].a.x, edges[i].b.x); };
  auto xmax = [&](uint32_t i) { return std::max(edges[i].a.x, edges[i].b.x); };
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return xmin(a) < xmin(b); });
  for (size_t oi = 0; oi < n; ++oi) {
    const uint32_t i = order[oi];
    for (size_t oj = oi + 1; oj < n && xmin(order[oj]) <= xmax(i); ++oj) {
      const uint32_t j = order[oj];
      const haloplot::Edge3 &p = edges[i], &q = edges[j];
      i128 tn, td, un, ud;
      if (!crossing(p, q, &tn, &td) || !crossing(q, p, &un, &ud)) continue;
      // depth of p at t: z = za + (zb - za) tn / td; compare p and q by cross-multiplying.
      const i128 zp = i128(p.a.z) * td + i128(p.b.z - p.a.z) * tn;  // over td
      const i128 zq = i128(q.a.z) * ud + i128(q.b.z - q.a.z) * un;  // over ud
      const i128 lhs = zp * ud, rhs = zq * td;                      // < 2^62 * 2^42: fits 128 bits
      if (lhs == rhs) {
        ++r.equal_depth;
        continue;
      }
      if (lhs < rhs)
        r.records.push_back({i, j, uint32_t((tn << 32) / td)});
      else
        r.records.push_back({j, i, uint32_t((un << 32) / ud)});
    }
  }
  std::sort(r.records.begin(), r.records.end());
  return r;
}

}  // namespace reference
