#include "haloplot/curve/curve_draw.h"

#include "haloplot/sort/lower_bound.h"
#include "memory/carve.h"
#include "sort/in_place_sort.h"

namespace haloplot {

namespace {

// Bit budget (units: the contract's coordinates, below 2^20):
//   a point or a tangent in Q.32           |.| < 3 * 2^20 * 2^32 < 2^54
//   a tangent, normalised                  components below 2^30 after `shift` halvings
//   cross of two normalised tangents       < 2^61 (int64_t)
//   a half-gap's arc W |a| |b| 2^32        < 2^20 * 2^31 * 2^31 * 2^32 = 2^114 (Wide)
//   a chord or a leg of a walk's step       Q.32, below 2^57; halved below 2^31 for its length
//   chord count factor 3 * 64 * D_c        D_c < 2^22: < 2^30
inline constexpr int kQ = 32;
inline constexpr int64_t kOne = int64_t{1} << kQ;
inline constexpr int64_t kNormLimit = int64_t{1} << 30;
inline constexpr uint32_t kNoLink = 0xffffffffu;
static_assert(kCoordBits + 2 + kQ < 63, "a tangent in Q.32 fits int64_t");
static_assert(2 * 30 + 1 < 63, "a cross of normalised tangents fits int64_t");

// An edge's control points in units; a segment keeps its ends (p0 = p1, p2 = p3) and is
// evaluated linearly, as run_curve_cross() parameterises it.
struct Ctl {
  int64_t x[4], y[4], z[4];
  bool straight;
};

Ctl ctl_of(const BezierEdge3* curves, uint32_t nc, const Edge3* segments, uint32_t k) {
  Ctl c;
  Point3 p[4];
  if (k < nc) {
    for (int i = 0; i < 4; ++i) p[i] = curves[k].p[i];
  } else {
    const Edge3& e = segments[k - nc];
    p[0] = p[1] = e.a;
    p[2] = p[3] = e.b;
  }
  for (int i = 0; i < 4; ++i) c.x[i] = p[i].x, c.y[i] = p[i].y, c.z[i] = p[i].z;
  c.straight = k >= nc;
  return c;
}

// v + floor(d * t / 2^32), |d| < 2^62, t <= 2^32 (the result fits: the callers' budgets).
int64_t lerp32(int64_t v, int64_t d, uint64_t t) {
  const Wide p = mul_i64(d, static_cast<int64_t>(t));
  return v + static_cast<int64_t>((p.hi << 32) | (p.lo >> 32));
}

// The point at t (Q0.32) in Q.32 units: de Casteljau, each level a floor of 2^-32 units.
void point_at(const Ctl& c, uint64_t t, int64_t* x, int64_t* y) {
  if (c.straight) {
    *x = c.x[0] * kOne + (c.x[3] - c.x[0]) * static_cast<int64_t>(t);
    *y = c.y[0] * kOne + (c.y[3] - c.y[0]) * static_cast<int64_t>(t);
    return;
  }
  int64_t px[4], py[4];
  for (int i = 0; i < 4; ++i) px[i] = c.x[i] * kOne, py[i] = c.y[i] * kOne;
  for (int level = 3; level > 0; --level)
    for (int i = 0; i < level; ++i) {
      px[i] = lerp32(px[i], px[i + 1] - px[i], t);
      py[i] = lerp32(py[i], py[i + 1] - py[i], t);
    }
  *x = px[0];
  *y = py[0];
}

int32_t round_unit(int64_t v) { return static_cast<int32_t>((v + (kOne >> 1)) >> kQ); }

// The tangent B'(t) in Q.32 units per unit of t: 3 times the quadratic de Casteljau of the
// control points' differences.
void tangent_at(const Ctl& c, uint64_t t, int64_t* dx, int64_t* dy) {
  if (c.straight) {
    *dx = (c.x[3] - c.x[0]) * kOne;
    *dy = (c.y[3] - c.y[0]) * kOne;
    return;
  }
  int64_t qx[3], qy[3];
  for (int i = 0; i < 3; ++i)
    qx[i] = (c.x[i + 1] - c.x[i]) * kOne, qy[i] = (c.y[i + 1] - c.y[i]) * kOne;
  for (int level = 2; level > 0; --level)
    for (int i = 0; i < level; ++i) {
      qx[i] = lerp32(qx[i], qx[i + 1] - qx[i], t);
      qy[i] = lerp32(qy[i], qy[i + 1] - qy[i], t);
    }
  *dx = 3 * qx[0];
  *dy = 3 * qy[0];
}

// A tangent as (x, y) * 2^(shift - 32), components below 2^30: halved (floor) until they are.
struct Dir {
  int64_t x = 0, y = 0;
  int shift = 0;
};
int64_t abs64(int64_t v) { return v < 0 ? -v : v; }
Dir normalized(int64_t x, int64_t y) {
  Dir d{x, y, 0};
  while (abs64(d.x) >= kNormLimit || abs64(d.y) >= kNormLimit) {
    d.x >>= 1;
    d.y >>= 1;
    ++d.shift;
  }
  return d;
}
Dir tangent_dir(const Ctl& c, uint64_t t) {
  int64_t x, y;
  tangent_at(c, t, &x, &y);
  return normalized(x, y);
}
uint64_t length_ceil(const Dir& d) {
  const uint64_t v = static_cast<uint64_t>(d.x * d.x + d.y * d.y);
  const uint64_t s = isqrt_u64(v);
  return s * s < v ? s + 1 : s;
}

// ---- arc length ----
//
// A half-gap is W / sin(theta) of arc, walked along the curve (docs/curves.md, "The gap").
// Lengths are Q.32 units in int64_t. A step [t, t + h] of the walk is the sub-cubic with
// control points B(t), B(t) + h/3 B'(t), B(t + h) - h/3 B'(t + h), B(t + h) (exact Bézier
// subdivision), so its arc lies between its chord c and its control polygon p, and the step
// counts (2c + p) / 3 (Gravesen's estimate), within 2 (p - c) / 3 of the arc. A step is halved
// until p - c <= c 2^-14 + 2^-20 units, so the walk's count is within 2^-14.5 of the arc it
// covers plus 2^-20.6 units a step; a flat step lets the next one double, up to 2^-6 of the
// edge. The walk ends by bisection: a step that would pass the arc left is halved until it
// does not, or until its estimate is below kArcEndTol (1/64 unit), which is then taken whole.
inline constexpr int64_t kArcHuge = int64_t{1} << 62;     // no end: a gap along the chain
inline constexpr int64_t kArcStepMax = int64_t{1} << 26;  // 2^-6 of an edge's parameter
inline constexpr int64_t kArcStepMin = int64_t{1} << 8;   // 2^-24
inline constexpr int64_t kArcAbsTol = int64_t{1} << 12;   // 2^-20 units
inline constexpr int64_t kArcEndTol = int64_t{1} << 26;   // 1/64 unit
inline constexpr int kArcRelBits = 14;
static_assert(kCoordBits + 3 + kQ < 63, "a chord or a control leg in Q.32 fits int64_t");

// |(dx, dy)| in Q.32 for Q.32 components below 2^56: halved until they are below 2^31, so the
// squares' sum fits uint64_t (relative error below 2^-29, never above the length).
int64_t length32(int64_t dx, int64_t dy) {
  int shift = 0;
  while (abs64(dx) >= (int64_t{1} << 31) || abs64(dy) >= (int64_t{1} << 31)) {
    dx /= 2;
    dy /= 2;
    ++shift;
  }
  return static_cast<int64_t>(uint64_t{isqrt_u64(static_cast<uint64_t>(dx * dx + dy * dy))}
                              << shift);
}

// A third of h (Q0.32) times a Q.32 tangent: a control leg of the step's sub-cubic.
int64_t leg(int64_t d, int64_t h) { return lerp32(0, d, static_cast<uint64_t>(h)) / 3; }

// Walks the arc *left (Q.32 units; kArcHuge: no end) along edge c from t in direction dir (+1
// or -1). Returns the parameter where the arc runs out (*left then 0) or the edge's end.
int64_t walk_arc(const Ctl& c, int64_t t, int dir, int64_t* left) {
  const int64_t end = dir > 0 ? kOne : 0;
  const bool endless = *left >= kArcHuge;
  int64_t h = kArcStepMax, px, py, tx, ty;
  bool closing = false;
  point_at(c, static_cast<uint64_t>(t), &px, &py);
  tangent_at(c, static_cast<uint64_t>(t), &tx, &ty);
  while (t != end && *left > 0) {
    if (h > dir * (end - t)) h = dir * (end - t);
    const int64_t q = t + dir * h;
    int64_t qx, qy, ux, uy;
    point_at(c, static_cast<uint64_t>(q), &qx, &qy);
    tangent_at(c, static_cast<uint64_t>(q), &ux, &uy);
    const int64_t ax = dir * leg(tx, h), ay = dir * leg(ty, h);
    const int64_t bx = dir * leg(ux, h), by = dir * leg(uy, h);
    const int64_t chord = length32(qx - px, qy - py);
    const int64_t poly =
        length32(ax, ay) + length32(qx - px - ax - bx, qy - py - ay - by) + length32(bx, by);
    const int64_t excess = poly > chord ? poly - chord : 0;
    if (excess > (chord >> kArcRelBits) + kArcAbsTol && h > kArcStepMin) {
      h /= 2;
      continue;
    }
    const int64_t est = (2 * chord + poly) / 3;
    if (!endless && est > *left) {
      closing = true;
      if (est > kArcEndTol && h > 1) {
        h /= 2;
        continue;
      }
      *left = 0;
      return q;
    }
    if (!endless) *left -= est;
    t = q, px = qx, py = qy, tx = ux, ty = uy;
    if (!closing && excess <= (chord >> (kArcRelBits + 3)) + kArcAbsTol / 8 && h < kArcStepMax)
      h *= 2;
  }
  return t;
}

// W / sin(theta) of arc for tangents a and b: W |a| |b| / |cross(a, b)|, Q.32 units, rounded
// up; kArcHuge when the tangents are parallel as rounded.
static_assert(kCoordBits + 31 + 31 + kQ < 126, "a half-gap's arc numerator fits Wide");
int64_t half_arc(const Dir& a, const Dir& b, int32_t halo) {
  const int64_t cr = abs64(a.x * b.y - a.y * b.x);
  if (cr == 0) return kArcHuge;
  Wide num = mul_wide_u64(mul_u64(length_ceil(a), length_ceil(b)), static_cast<uint64_t>(halo));
  num.hi = (num.hi << kQ) | (num.lo >> (64 - kQ));
  num.lo <<= kQ;
  bool over = false;
  const uint64_t q = divide_round(num, static_cast<uint64_t>(cr), &over);
  return over || q >= static_cast<uint64_t>(kArcHuge) ? kArcHuge : static_cast<int64_t>(q) + 1;
}

// The exact halo's front strand (run_curve_draw_exact): up to kFrontRuns polylines of chords
// within 1/64 unit of their piece of curve, in Q.8 units, in scratch (`cap` points a run).
inline constexpr int kFrontRuns = 3;
inline constexpr int kFrontQ = 8;
struct Scene;
struct ExactFront {
  int64_t (*pts)[2];
  uint32_t cap;
  uint32_t len[kFrontRuns];
  int64_t w2;  // W^2 in Q.8 (below 2^56)
  // Its functions, set by run_curve_draw_exact only, so run_curve_draw (the controller's)
  // does not link them.
  int64_t (*walk)(const Scene& s, const Ctl& c, int64_t t, int dir, int64_t* left);
  void (*around)(const Scene& s, uint32_t k, int64_t u, int64_t L);
  void (*vertex)(const Scene& s, const uint32_t f[2], int64_t L);
};

struct Scene {
  const BezierEdge3* curves;
  uint32_t nc, n;
  const Edge3* segments;
  const CurveHit* hits;
  uint32_t n_hits;
  int32_t halo;
  const uint32_t* link;  // link_joints()'s
  int64_t* end_gap;      // per end: how far from it gaps arriving over a joint reach
  CurveDrawStats* st;
  ExactFront* front;  // the exact halo's front strand; null: the paper's gap
  Ctl edge(uint32_t k) const { return ctl_of(curves, nc, segments, k); }
  // The first hit on edge k (hits are sorted by curve).
  uint32_t first_hit(uint32_t k) const {
    return lower_bound_index(0, n_hits, [&](uint32_t i) { return hits[i].curve < k; });
  }
};

bool smooth(const Scene& s, uint32_t id);

// One side of a gap from t on edge c: L of arc (walk_arc), or with the exact halo until the
// edge leaves the front strand's W (walk_exact; *left stays above 0 while it has not).
int64_t walk_side(const Scene& s, const Ctl& c, int64_t t, int dir, int64_t* left) {
  return s.front != nullptr ? s.front->walk(s, c, t, dir, left) : walk_arc(c, t, dir, left);
}

// A gap side that ran past an edge's end with arc `left` to go, entering the next edge at
// its end e: along the chain across every joint, each edge it enters marked in end_gap (how far
// from that end it is covered), until the arc runs out, the chain ends or every edge is walked.
void walk_chain(const Scene& s, uint32_t e, int64_t left) {
  for (uint32_t hops = 0; hops < s.n && left > 0; ++hops) {
    const int64_t stop = walk_side(s, s.edge(e / 2), (e & 1) ? kOne : 0, (e & 1) ? -1 : 1, &left);
    const int64_t cover = (e & 1) ? kOne - stop : stop;
    if (cover > s.end_gap[e]) s.end_gap[e] = cover;
    if (s.link[e ^ 1] == kNoLink || !smooth(s, e ^ 1)) return;
    e = s.link[e ^ 1];
  }
}

// True when the arc from t to parameter `end` of c is surely longer than L: the chord between
// them is (an arc is never shorter than its chord), so a walk of L from t cannot reach `end`.
bool short_of_end(const Ctl& c, int64_t t, int64_t end, int64_t L) {
  int64_t x0, y0, x1, y1;
  point_at(c, static_cast<uint64_t>(t), &x0, &y0);
  point_at(c, static_cast<uint64_t>(end), &x1, &y1);
  return length32(x1 - x0, y1 - y0) > L;
}

// How far the gap of arc L on each side of [lo, hi] of c reaches from the crossing inside
// [lo, hi], as a bound in units (CurveDrawStats::reach): the arc between, at most the speed
// bound 3 max |leg| (|dx| + |dy| a leg) times hi - lo, plus L and the walk's excess over L
// (below 2^-14 L + 1/64 unit, and a unit for the floors).
// A gap walked from an exact point (a joint) has nothing between: `across` 0.
void note_reach(const Scene& s, int64_t L, int64_t across) {
  uint64_t reach = kCurveReachUnbounded;
  if (L < kArcHuge) {
    const int64_t q32 = L + (L >> 12) + across + 2 * kOne;
    reach = static_cast<uint64_t>((q32 + kOne - 1) >> kQ);
  }
  if (reach > s.st->reach) s.st->reach = reach;
}
void note_reach(const Scene& s, const Ctl& c, int64_t lo, int64_t hi, int64_t L) {
  int64_t leg = 0;
  for (int i = 0; i < 3; ++i) {
    const int64_t d = abs64(c.x[i + 1] - c.x[i]) + abs64(c.y[i + 1] - c.y[i]);
    leg = d > leg ? d : leg;
  }
  note_reach(s, L, 3 * leg * (hi - lo));  // below 3 * 2^22 * 2^32 < 2^56
}

// The gap of arc L on each side of [lo, hi] on edge k. With `carry` (the first pass, which
// only carries), the sides that run past one of k's ends go on along the chain (walk_chain:
// end_gap) and are counted as carried; a side whose chord to the end is longer than L cannot
// reach it and is not walked.
Gap arc_gap(const Scene& s, uint32_t k, int64_t lo, int64_t hi, int64_t L, bool carry) {
  const Ctl c = s.edge(k);
  lo = lo < 0 ? 0 : lo;
  hi = hi > kOne ? kOne : hi;
  note_reach(s, c, lo, hi, L);
  Gap g{lo, hi};
  for (int side = 0; side < 2; ++side) {
    const uint32_t end = 2 * k + static_cast<uint32_t>(side);
    const bool joined = s.link[end] != kNoLink && smooth(s, end);
    const int64_t from = side ? hi : lo;
    if (carry && (!joined || short_of_end(c, from, side ? kOne : 0, L))) continue;
    int64_t left = L;
    const int64_t to = walk_side(s, c, from, side ? 1 : -1, &left);
    (side ? g.hi : g.lo) = to;
    if (carry && left > 0) {
      ++s.st->carried;
      walk_chain(s, s.link[end], left);
    }
  }
  return g;
}

// The gap a crossing hit cuts: W / sin(theta) of arc beyond its parameter bound on each side;
// with the exact halo, what lies within W of the front edge around the crossing.
Gap hit_gap(const Scene& s, const CurveHit& h, bool carry) {
  const Dir a = tangent_dir(s.edge(h.curve), h.t);
  const Dir b = tangent_dir(s.edge(h.other), h.other_t);
  const int64_t t = static_cast<int64_t>(h.t), e = static_cast<int64_t>(h.t_err);
  int64_t L = half_arc(a, b, s.halo);
  if (s.front != nullptr) {
    s.front->around(s, h.other, static_cast<int64_t>(h.other_t), L);
    L = kArcHuge;
  }
  return arc_gap(s, h.curve, t - e, t + e, L, carry);
}

bool cuts_gap(const CurveHit& h) { return h.kind == CurveHitKind::kCrossing && h.front < 0; }

// ---- joints ----

// The point of end `id` (edge id / 2, its start for an even id) and the direction leaving the
// joint into the edge.
void end_of(const Scene& s, uint32_t id, int64_t p[3], int64_t d[2]) {
  const Ctl c = s.edge(id / 2);
  const int i = (id & 1) ? 3 : 0, j = (id & 1) ? 2 : 1;
  const int jj = c.straight ? 3 - i : j;  // a segment's repeated point: its other end
  p[0] = c.x[i], p[1] = c.y[i], p[2] = c.z[i];
  d[0] = c.x[jj] - c.x[i], d[1] = c.y[jj] - c.y[i];
}

bool end_less(const Scene& s, uint32_t a, uint32_t b) {
  int64_t pa[3], pb[3], d[2];
  end_of(s, a, pa, d);
  end_of(s, b, pb, d);
  for (int i = 0; i < 3; ++i)
    if (pa[i] != pb[i]) return pa[i] < pb[i];
  return a < b;
}

// True when the chain goes on smoothly at end id's vertex (link[id] set): the two ends leave it
// in opposite directions within 45 degrees (|cross| < -dot), a joint, where gaps carry on.
bool smooth(const Scene& s, uint32_t id) {
  int64_t p[3], u[2], v[2];
  end_of(s, id, p, u);
  end_of(s, s.link[id], p, v);
  const int64_t dot = u[0] * v[0] + u[1] * v[1], cr = abs64(u[0] * v[1] - u[1] * v[0]);
  return dot < 0 && cr < -dot;
}

// link[id]: the end joined to end id, or kNoLink. Exactly two ends at one 3-D point make a
// vertex of a chain: a joint where it goes on smoothly (smooth()), else a corner. Returns the
// number of joints.
uint32_t link_joints(const Scene& s, uint32_t* order, uint32_t* link) {
  const uint32_t ends = 2 * s.n;
  for (uint32_t i = 0; i < ends; ++i) order[i] = i, link[i] = kNoLink;
  sort_in_place(order, ends, [&s](uint32_t a, uint32_t b) { return end_less(s, a, b); });
  uint32_t joints = 0;
  for (uint32_t i = 0; i < ends;) {
    uint32_t j = i + 1;
    int64_t pa[3], pb[3], d[2];
    end_of(s, order[i], pa, d);
    for (; j < ends; ++j) {
      end_of(s, order[j], pb, d);
      if (pa[0] != pb[0] || pa[1] != pb[1] || pa[2] != pb[2]) break;
    }
    if (j - i == 2) {
      link[order[i]] = order[i + 1];
      link[order[i + 1]] = order[i];
      if (smooth(s, order[i])) ++joints;
    }
    i = j;
  }
  return joints;
}

// ---- crossings at joints ----

// Two chains that pass through one projected point at different depths, each with a joint
// there, may cross at it; run_curve_cross() sees only edge ends meeting there (never a
// crossing). The chains cross when their directions alternate around the point: the two
// directions of one chain lie strictly on opposite sides of the other chain's path through
// it. Directions are control-point differences (below 2^21 a coordinate): their cross
// products are below 2^43.
static_assert(2 * (kCoordBits + 1) + 1 < 63, "a cross of two end directions fits int64_t");

int64_t cross2(const int64_t u[2], const int64_t v[2]) { return u[0] * v[1] - u[1] * v[0]; }

// +1 when w is strictly inside the counter-clockwise turn from u to v, -1 inside the turn from
// v to u, 0 on either ray (a tangency: no side).
int side_of_path(const int64_t u[2], const int64_t v[2], const int64_t w[2]) {
  const int64_t uw = cross2(u, w), wv = cross2(w, v), uv = cross2(u, v);
  const bool on_u = uw == 0 && u[0] * w[0] + u[1] * w[1] > 0;
  const bool on_v = wv == 0 && v[0] * w[0] + v[1] * w[1] > 0;
  if (on_u || on_v) return 0;
  // The turn from u to v is convex (uv > 0), a half-plane (uv = 0) or reflex (uv < 0).
  const bool inside = uv > 0 ? (uw > 0 && wv > 0) : uv == 0 ? uw > 0 : (uw >= 0 || wv >= 0);
  return inside ? 1 : -1;
}

// The tangent of end e's edge at that end.
Dir end_dir(const Scene& s, uint32_t e) {
  return tangent_dir(s.edge(e / 2), (e & 1) ? kCurveParamOne : 0);
}

// The half-gap's arc on the edge of end `e` (its tangent at the joint) against the front
// chain's two ends f[0], f[1]: the larger of the two, so the gap covers either side's angle.
int64_t joint_half_arc(const Scene& s, uint32_t e, const uint32_t f[2]) {
  const Dir a = end_dir(s, e);
  int64_t most = 0;
  for (int i = 0; i < 2; ++i) {
    const int64_t L = half_arc(a, end_dir(s, f[i]), s.halo);
    most = L > most ? L : most;
  }
  return most;
}

// Joints j (ends j[0], j[1]) and k at one projected point: when they cross at different
// depths, the gap on both edges of the joint behind, walked from the joint (walk_chain).
void joint_pair(const Scene& s, const uint32_t j[2], const uint32_t k[2]) {
  int64_t pj[3], pk[3], uj[2], vj[2], uk[2], vk[2];
  end_of(s, j[0], pj, uj);
  end_of(s, j[1], pj, vj);
  end_of(s, k[0], pk, uk);
  end_of(s, k[1], pk, vk);
  if (pj[2] == pk[2]) return;  // one 3-D point: a meeting
  if (side_of_path(uj, vj, uk) * side_of_path(uj, vj, vk) != -1) return;  // a touch
  const uint32_t* back = pj[2] < pk[2] ? j : k;                           // larger z is nearer
  const uint32_t* front = pj[2] < pk[2] ? k : j;
  for (int i = 0; i < 2; ++i) {
    int64_t L = joint_half_arc(s, back[i], front);
    if (s.front != nullptr) {
      s.front->vertex(s, front, L);
      L = kArcHuge;
    }
    note_reach(s, L, 0);
    walk_chain(s, back[i], L);
  }
  ++s.st->gaps;
  ++s.st->joint_crossings;
}

// Over the ends sorted by (x, y, z) (link_joints' order): the joints at each projected point,
// taken in pairs.
void joint_crossings(const Scene& s, const uint32_t* order) {
  const uint32_t* link = s.link;
  const uint32_t ends = 2 * s.n;
  for (uint32_t i = 0; i < ends;) {
    int64_t pa[3], pb[3], d[2];
    end_of(s, order[i], pa, d);
    uint32_t j = i + 1;
    for (; j < ends; ++j) {
      end_of(s, order[j], pb, d);
      if (pa[0] != pb[0] || pa[1] != pb[1]) break;
    }
    // A joint is named by its lower end; each pair of joints once.
    for (uint32_t x = i; x < j; ++x) {
      const uint32_t ex = order[x];
      if (link[ex] == kNoLink || link[ex] < ex) continue;
      for (uint32_t y = x + 1; y < j; ++y) {
        const uint32_t ey = order[y];
        if (link[ey] == kNoLink || link[ey] < ey) continue;
        const uint32_t jx[2] = {ex, link[ex]}, jy[2] = {ey, link[ey]};
        joint_pair(s, jx, jy);
      }
    }
    i = j;
  }
}

// ---- a chain through another's joint ----

// Edge k passing, in its interior, exactly through the projected point of a joint of another
// chain: found where it does so at a piece end of its exact halving (a dyadic parameter, as a
// symmetric scene has it), by descending into the pieces whose box holds the point, to
// kCurveMaxDepth (on a stack of kCurveMaxDepth + 2 pieces in scratch). A pass through the point
// between piece ends is left to run_curve_cross(): an end-point meeting there.
static_assert(kCurvePointBits + 1 + kCoordBits + 1 + 1 < 126, "a side of a pass fits Wide");
struct Through {
  uint64_t t = 0;
  int64_t z = 0;      // depth, Q20.42
  int64_t z_err = 0;  // its error bound (0: exact)
  int64_t d[2] = {};  // direction along k there, Q20.42 or Q.32 (below 2^62)
};
bool passes_through(const Scene& s, uint32_t k, const int64_t p[2], CurvePiece* stack,
                    Through* out) {
  const Ctl c = s.edge(k);
  const int64_t px = p[0], py = p[1];
  if (px < c.x[0] && px < c.x[1] && px < c.x[2] && px < c.x[3]) return false;
  if (px > c.x[0] && px > c.x[1] && px > c.x[2] && px > c.x[3]) return false;
  if (py < c.y[0] && py < c.y[1] && py < c.y[2] && py < c.y[3]) return false;
  if (py > c.y[0] && py > c.y[1] && py > c.y[2] && py > c.y[3]) return false;
  const int64_t fx = px * (int64_t{1} << kCurveFracBits), fy = py * (int64_t{1} << kCurveFracBits);
  uint32_t top = 0;
  stack[top++] = k < s.nc ? whole_piece(s.curves[k], k) : segment_piece(s.segments[k - s.nc], k);
  while (top > 0) {
    const CurvePiece q = stack[--top];
    const FixBox b = box_of(q);
    if (fx < b.x0 || fx > b.x1 || fy < b.y0 || fy > b.y1) continue;
    const FixPoint3& a = q.p[0];
    const FixPoint3& next = q.straight ? q.p[3] : q.p[1];
    if (q.t_lo() != 0 && a.x == fx && a.y == fy && (next.x != a.x || next.y != a.y)) {
      out->t = q.t_lo();
      out->z = a.z;
      out->d[0] = next.x - a.x;
      out->d[1] = next.y - a.y;
      return true;
    }
    if (q.level >= kCurveMaxDepth) continue;
    CurvePiece l, r;
    halve(q, &l, &r);
    stack[top++] = r;
    stack[top++] = l;
  }
  return false;
}

// Joint j (ends j[0], j[1], at point p) and edge k through it (found by passes_through): a
// crossing when j's two directions lie strictly on opposite sides of k's tangent line there
// (exact: Q20.42 direction times a unit difference, below 2^84, in Wide). Returns -1 when the
// joint is behind, +1 when k is, 0 for no crossing (a touch, or one depth).
int through_front(const Scene& s, const uint32_t j[2], const Through& th) {
  int64_t p[3], u[2], v[2];
  end_of(s, j[0], p, u);
  end_of(s, j[1], p, v);
  const int64_t z = p[2] * (int64_t{1} << kCurveFracBits);
  if (abs64(z - th.z) <= th.z_err) return 0;
  const Wide su = mul_i64(th.d[0], u[1]) - mul_i64(th.d[1], u[0]);
  const Wide sv = mul_i64(th.d[0], v[1]) - mul_i64(th.d[1], v[0]);
  if (su.is_zero() || sv.is_zero() || su.negative() == sv.negative()) return 0;
  return z < th.z ? -1 : 1;
}

// The half-gap's arc on edge k at the pass (or, on_joint, on the joint's end e) against the
// other.
int64_t through_half_arc(const Scene& s, uint32_t k, uint64_t t, uint32_t e, bool on_joint) {
  const Dir dk = tangent_dir(s.edge(k), t), de = end_dir(s, e);
  return on_joint ? half_arc(de, dk, s.halo) : half_arc(dk, de, s.halo);
}

// Edge k passes through joint (or corner) j at th (its parameter within t_err), crossing it
// (through_front() is f, not 0). With `gaps` null (the first pass): counted, the joint's edges
// walked from it when it is behind, k's gap carried past its ends when k is; else k's gap
// into `gaps` when k is behind. Returns the gaps stored.
uint32_t cut_pass(const Scene& s, uint32_t k, const uint32_t j[2], const Through& th, int f,
                  int64_t t_err, Gap* gaps) {
  const bool first_pass = gaps == nullptr;
  if (first_pass) {
    ++s.st->gaps;
    ++s.st->joint_crossings;
  }
  int64_t most = 0;
  const int64_t t = static_cast<int64_t>(th.t);
  for (int m = 0; m < 2; ++m) {
    int64_t L = through_half_arc(s, k, th.t, j[m], f < 0);
    if (f < 0 && first_pass && s.front != nullptr) {
      s.front->around(s, k, t, L);
      L = kArcHuge;
    }
    if (f < 0 && first_pass) {
      note_reach(s, L, 0);
      walk_chain(s, j[m], L);
    }
    most = L > most ? L : most;
  }
  if (f < 0) return 0;
  if (s.front != nullptr) {
    s.front->vertex(s, j, most);
    most = kArcHuge;
  }
  const Gap g = arc_gap(s, k, t - t_err, t + t_err, most, first_pass);
  if (first_pass) return 0;
  gaps[0] = g;
  return 1;
}

// The first end in `order` (sorted by x, then y, z) whose x is not below x.
uint32_t first_end_at(const Scene& s, const uint32_t* order, int64_t x) {
  return lower_bound_index(0, 2 * s.n, [&](uint32_t i) {
    int64_t p[3], d[2];
    end_of(s, order[i], p, d);
    return p[0] < x;
  });
}

// Edges k in [from, to) through the joints of other chains: the joints whose x lies within
// k's box are found by a binary search in the ends sorted by x. With `gaps` null (the first
// pass): counted, and joints behind walked from (walk_chain), edges behind carried past their
// ends; else the gaps of edges behind into `gaps`.
uint32_t through_joints(const Scene& s, const uint32_t* order, uint32_t from, uint32_t to,
                        CurvePiece* stack, Gap* gaps) {
  const uint32_t* link = s.link;
  uint32_t n = 0;
  for (uint32_t k = from; k < to; ++k) {
    const Ctl c = s.edge(k);
    int64_t x0 = c.x[0], x1 = c.x[0];
    for (int i = 1; i < 4; ++i) x0 = c.x[i] < x0 ? c.x[i] : x0, x1 = c.x[i] > x1 ? c.x[i] : x1;
    for (uint32_t i = first_end_at(s, order, x0); i < 2 * s.n; ++i) {
      const uint32_t e = order[i];
      int64_t p[3], d[2];
      end_of(s, e, p, d);
      if (p[0] > x1) break;
      if (link[e] == kNoLink || link[e] < e) continue;
      const uint32_t j[2] = {e, link[e]};
      Through th;
      if (k == j[0] / 2 || k == j[1] / 2 || !passes_through(s, k, p, stack, &th)) continue;
      const int f = through_front(s, j, th);
      if (f == 0) continue;
      n += cut_pass(s, k, j, th, f, 0, gaps == nullptr ? nullptr : gaps + n);
    }
  }
  return n;
}

// ---- a chain through another's joint, between piece ends ----

// The depth at t (Q0.32) in Q.32 units, de Casteljau as point_at, and a bound on how much it
// changes over t_err of the parameter (3 times the largest control-point depth difference).
int64_t depth_at(const Ctl& c, uint64_t t) {
  int64_t z[4] = {c.z[0] * kOne, c.z[1] * kOne, c.z[2] * kOne, c.z[3] * kOne};
  if (c.straight) return lerp32(z[0], z[3] - z[0], t);
  for (int level = 3; level > 0; --level)
    for (int i = 0; i < level; ++i) z[i] = lerp32(z[i], z[i + 1] - z[i], t);
  return z[0];
}
static_assert(kCoordBits + 2 + kQ + 1 < 62, "a depth bound over a parameter bound fits");
int64_t depth_slack(const Ctl& c, uint64_t t_err) {
  int64_t most = 0;
  for (int i = 0; i < 3; ++i) {
    const int64_t d = abs64(c.z[i + 1] - c.z[i]);
    most = d > most ? d : most;
  }
  const uint64_t e = t_err < kCurveParamOne ? t_err : kCurveParamOne;
  return 3 * most * static_cast<int64_t>(e) + 2;  // Q.32 units
}

// A chain through another's joint (or corner) at a parameter of its own that is not a piece
// end of its halving: run_curve_cross() reports it as a touch (an end-point meeting) of the
// edge with an edge of the joint, at that edge's end. Hit i on edge k is such a pass when it is
// a touch inside k whose other side reaches an end of its edge that is a vertex of two edges
// other than k, and the same pass was not seen from the vertex's other edge earlier on k. The
// vertex's ends go to j, the pass (k's parameter, depth with its bound, tangent) to th.
bool touch_pass(const Scene& s, uint32_t i, uint32_t j[2], Through* th) {
  const CurveHit& h = s.hits[i];
  if (h.kind != CurveHitKind::kTouch || h.t <= h.t_err || h.t + h.t_err >= kCurveParamOne)
    return false;
  const bool at_start = h.other_t <= h.other_err;
  if (!at_start && h.other_t + h.other_err < kCurveParamOne) return false;
  const uint32_t e = 2 * h.other + (at_start ? 0 : 1);
  if (s.link[e] == kNoLink) return false;
  j[0] = e < s.link[e] ? e : s.link[e];
  j[1] = e < s.link[e] ? s.link[e] : e;
  if (h.curve == j[0] / 2 || h.curve == j[1] / 2) return false;
  for (uint32_t b = s.first_hit(h.curve); b < i; ++b) {  // seen from the other edge already
    const CurveHit& g = s.hits[b];
    const uint64_t d = g.t > h.t ? g.t - h.t : h.t - g.t;
    if (g.kind == CurveHitKind::kTouch && (g.other == j[0] / 2 || g.other == j[1] / 2) &&
        g.other != h.other && d <= g.t_err + h.t_err)
      return false;
  }
  const Ctl c = s.edge(h.curve);
  th->t = h.t;
  tangent_at(c, h.t, &th->d[0], &th->d[1]);
  const int64_t shift = int64_t{1} << (kCurveFracBits - kQ);  // Q.32 to Q20.42
  th->z = depth_at(c, h.t) * shift;
  const int64_t slack = depth_slack(c, h.t_err);
  th->z_err = slack < (int64_t{1} << 51) ? slack * shift : int64_t{1} << 61;
  return true;
}

// Hit i as a pass through a joint (touch_pass), decided and cut as through_joints() does, unless
// the pass is at a piece end (passes_through(): through_joints() has it).
uint32_t touch_gap(const Scene& s, uint32_t i, CurvePiece* stack, Gap* gaps) {
  uint32_t j[2];
  Through th, exact;
  if (!touch_pass(s, i, j, &th)) return 0;
  int64_t p[3], d[2];
  end_of(s, j[0], p, d);
  const uint32_t k = s.hits[i].curve;
  if (passes_through(s, k, p, stack, &exact)) return 0;
  const int f = through_front(s, j, th);
  if (f == 0) return 0;
  return cut_pass(s, k, j, th, f, static_cast<int64_t>(s.hits[i].t_err), gaps);
}

// ---- one edge ----

// The gaps of the crossings behind on edge k, walked along it. With `gaps` null (the first
// pass), sides that run past k's ends are carried on along the chain (end_gap) and nothing is
// stored; else the gaps go into `gaps`, with the undecided crossings and the gaps counted.
uint32_t hit_gaps(const Scene& s, uint32_t k, CurvePiece* stack, Gap* gaps) {
  uint32_t n = 0;
  for (uint32_t i = s.first_hit(k); i < s.n_hits && s.hits[i].curve == k; ++i) {
    const CurveHit& h = s.hits[i];
    if (h.kind == CurveHitKind::kTouch) {
      n += touch_gap(s, i, stack, gaps == nullptr ? nullptr : gaps + n);
      continue;
    }
    if (gaps == nullptr) {
      if (cuts_gap(h)) hit_gap(s, h, true);
      continue;
    }
    // Each crossing is seen from both edges: count it from one side.
    const bool first_side = h.curve < h.other || (h.curve == h.other && h.t < h.other_t);
    if (h.kind == CurveHitKind::kCrossing && h.front == 0 && first_side) ++s.st->undecided;
    if (!cuts_gap(h)) continue;
    gaps[n++] = hit_gap(s, h, false);
    ++s.st->gaps;
  }
  return n;
}

// The gaps on edge k: its own crossings behind, what gaps from along its chain reach over its
// ends (end_gap: carried gaps, crossings at its joints) and its passes through other chains'
// joints. Returns the count (at most 3 * most_hits + 2 + edges).
uint32_t collect_gaps(const Scene& s, uint32_t k, const uint32_t* order, CurvePiece* stack,
                      Gap* gaps) {
  uint32_t n = through_joints(s, order, k, k + 1, stack, gaps);
  if (s.end_gap[2 * k] > 0) gaps[n++] = Gap{0, s.end_gap[2 * k]};
  if (s.end_gap[2 * k + 1] > 0) gaps[n++] = Gap{kOne - s.end_gap[2 * k + 1], kOne};
  return n + hit_gaps(s, k, stack, gaps + n);
}

// The largest second-difference coordinate of a curve's control points (0 for a segment).
int64_t second_difference(const Ctl& c) {
  if (c.straight) return 0;
  int64_t most = 0;
  for (int i = 0; i < 2; ++i) {
    const int64_t dx = abs64(c.x[i] - 2 * c.x[i + 1] + c.x[i + 2]);
    const int64_t dy = abs64(c.y[i] - 2 * c.y[i + 1] + c.y[i + 2]);
    most = dx > most ? dx : most;
    most = dy > most ? dy : most;
  }
  return most;
}

// ---- the exact halo (run_curve_draw_exact) ----
//
// The gap removes what lies within W of the front strand, found by walking the edge behind
// from the crossing in arc steps of W / 4 until a point lies W or more from it, then bisecting
// that step to 1/64 unit. The front strand is taken around the crossing only (else a curve's
// own loop would be its own front everywhere): 2 (L + W) of arc each way along the front edge
// (L = W / sin(theta), its paper half-gap), on over smooth joints into its neighbours, or
// from a vertex into its two edges; as chords within 1/64 unit (Q.8 points). A point is inside
// when its squared distance to a chord is below W^2, exactly in Q.8 (below 2^114 in Wide).
static_assert(2 * (kCoordBits + kFrontQ + 1) + 1 < 126, "a chord's distance test fits Wide");

// The chords' count over all of edge c at 1/64 unit: the chord formula with tol 4/256.
uint64_t front_root(const Ctl& c) {
  return c.straight ? 1 : uint64_t{isqrt_u64(static_cast<uint64_t>(48 * second_difference(c)))} + 1;
}

int64_t to_q8(int64_t v) { return (v + (int64_t{1} << (kQ - kFrontQ - 1))) >> (kQ - kFrontQ); }

// Run r of the front strand: edge k's chords over [a, b] (Q0.32, a <= b).
void front_run(const Scene& s, int r, uint32_t k, int64_t a, int64_t b) {
  ExactFront& f = *s.front;
  const Ctl c = s.edge(k);
  uint64_t n = (static_cast<uint64_t>(b - a) * front_root(c) + kOne - 1) >> kQ;
  n = n == 0 ? 1 : (n + 1 > f.cap ? f.cap - 1 : n);
  int64_t(*p)[2] = f.pts + static_cast<size_t>(r) * f.cap;
  for (uint64_t j = 0; j <= n; ++j) {
    int64_t x, y;
    point_at(c, static_cast<uint64_t>(a) + static_cast<uint64_t>(b - a) * j / n, &x, &y);
    p[j][0] = to_q8(x);
    p[j][1] = to_q8(y);
  }
  f.len[r] = static_cast<uint32_t>(n + 1);
}

int64_t front_reach(const Scene& s, int64_t L) {
  const int64_t w = int64_t{s.halo} << kQ;
  return L >= kArcHuge / 4 ? kArcHuge : 2 * (L + w);
}

// Run r: from end e into its edge, R of arc.
void front_from_end(const Scene& s, int r, uint32_t e, int64_t R) {
  int64_t left = R;
  const int64_t stop = walk_arc(s.edge(e / 2), (e & 1) ? kOne : 0, (e & 1) ? -1 : 1, &left);
  front_run(s, r, e / 2, (e & 1) ? stop : 0, (e & 1) ? kOne : stop);
}

// The front strand around parameter u of edge k (L: the paper's half-gap there).
void front_around(const Scene& s, uint32_t k, int64_t u, int64_t L) {
  const Ctl c = s.edge(k);
  const int64_t R = front_reach(s, L);
  s.front->len[1] = s.front->len[2] = 0;
  int64_t left = R;
  const int64_t a = walk_arc(c, u, -1, &left);
  if (left > 0 && s.link[2 * k] != kNoLink && smooth(s, 2 * k))
    front_from_end(s, 1, s.link[2 * k], left);
  left = R;
  const int64_t b = walk_arc(c, u, 1, &left);
  if (left > 0 && s.link[2 * k + 1] != kNoLink && smooth(s, 2 * k + 1))
    front_from_end(s, 2, s.link[2 * k + 1], left);
  front_run(s, 0, k, a, b);
}

// The front strand at a vertex: its two edges from it.
void front_from_vertex(const Scene& s, const uint32_t f[2], int64_t L) {
  const int64_t R = front_reach(s, L);
  front_from_end(s, 0, f[0], R);
  front_from_end(s, 1, f[1], R);
  s.front->len[2] = 0;
}

// True when (px, py) (Q.8) is closer than W to a chord of the front strand.
bool near_front(const ExactFront& f, int64_t px, int64_t py) {
  for (int r = 0; r < kFrontRuns; ++r) {
    const int64_t(*p)[2] = f.pts + static_cast<size_t>(r) * f.cap;
    for (uint32_t j = 0; j + 1 < f.len[r]; ++j) {
      const int64_t ax = p[j][0], ay = p[j][1], dx = p[j + 1][0] - ax, dy = p[j + 1][1] - ay;
      const int64_t vx = px - ax, vy = py - ay;
      const int64_t dot = vx * dx + vy * dy, dd = dx * dx + dy * dy;
      int64_t ex = vx, ey = vy;
      if (dot > 0 && dot >= dd) {
        ex = px - p[j + 1][0];
        ey = py - p[j + 1][1];
      } else if (dot > 0) {
        const int64_t cr = vx * dy - vy * dx;
        if (mul_i64(cr, cr) < mul_u64(static_cast<uint64_t>(f.w2), static_cast<uint64_t>(dd)))
          return true;
        continue;
      }
      if (ex * ex + ey * ey < f.w2) return true;
    }
  }
  return false;
}

bool inside_at(const Scene& s, const Ctl& c, int64_t t) {
  int64_t x, y;
  point_at(c, static_cast<uint64_t>(t), &x, &y);
  return near_front(*s.front, to_q8(x), to_q8(y));
}

// From t (inside) along c in direction dir: steps of W / 4 of arc while inside; the step that
// leaves is bisected until its chord is below 1/64 unit, and its outer end returned (*left 0).
// Reaching the edge's end still inside returns it with *left untouched.
int64_t walk_exact(const Scene& s, const Ctl& c, int64_t t, int dir, int64_t* left) {
  const int64_t end = dir > 0 ? kOne : 0;
  while (t != end) {
    int64_t step = (int64_t{s.halo} << kQ) / 4 + 1;
    const int64_t q = walk_arc(c, t, dir, &step);
    if (inside_at(s, c, q)) {
      t = q;
      continue;
    }
    int64_t a = t, b = q;
    while (dir * (b - a) > 1) {
      int64_t ax, ay, bx, by;
      point_at(c, static_cast<uint64_t>(a), &ax, &ay);
      point_at(c, static_cast<uint64_t>(b), &bx, &by);
      if (length32(bx - ax, by - ay) < kArcEndTol) break;
      const int64_t mid = a + (b - a) / 2;
      (inside_at(s, c, mid) ? a : b) = mid;
    }
    *left = 0;
    return b;
  }
  return end;
}

// One visible interval: to the interval sink, then as n equal chords (curve_draw.h).
Status emit_visible(const Ctl& c, uint32_t k, uint64_t t0, uint64_t t1, uint64_t root,
                    SpanSink chords, const CurveIntervalSink* intervals, CurveDrawStats& st) {
  ++st.intervals;
  if (intervals != nullptr) {
    const Status s =
        intervals->emit(intervals->context, CurveInterval{k, int64_t(t0), int64_t(t1)});
    if (!ok(s)) return s;
  }
  const uint64_t w = t1 - t0;
  uint64_t n = (w * root + static_cast<uint64_t>(kOne) - 1) >> kQ;
  if (n == 0) n = 1;
  int64_t x, y;
  point_at(c, t0, &x, &y);
  Span span{{k, static_cast<int64_t>(t0), 0}, round_unit(x), round_unit(y), 0, 0};
  for (uint64_t j = 1; j <= n; ++j) {
    const uint64_t t = t0 + w * j / n;
    point_at(c, t, &x, &y);
    span.t1 = static_cast<int64_t>(t);
    span.x1 = round_unit(x);
    span.y1 = round_unit(y);
    ++st.chords;
    const Status s = chords.emit(chords.context, span);
    if (!ok(s)) return s;
    span.t0 = span.t1;
    span.x0 = span.x1;
    span.y0 = span.y1;
  }
  return Status::kOk;
}

// D2.4-D2.5 on one edge: the gaps sorted along it, the uncovered parts emitted.
Status draw_edge(const Scene& s, uint32_t k, Gap* gaps, uint32_t n, const CurveDrawParams& params,
                 SpanSink chords, const CurveIntervalSink* intervals, CurveDrawStats& st) {
  const Ctl c = s.edge(k);
  const uint64_t k3 = static_cast<uint64_t>(3 * 64 * second_difference(c)) / params.chord_tol_q8;
  const uint64_t root = c.straight ? 0 : uint64_t{isqrt_u64(k3)} + 1;
  for (uint32_t i = 0; i < n; ++i) {
    if (gaps[i].lo < 0) gaps[i].lo = 0;
    if (gaps[i].hi > kOne) gaps[i].hi = kOne;
  }
  sort_in_place(gaps, n, [](const Gap& a, const Gap& b) { return a.lo < b.lo; });
  int64_t cursor = 0;
  bool drew = false;
  for (uint32_t i = 0; i <= n; ++i) {
    const int64_t until = i < n ? gaps[i].lo : kOne;
    if (until > cursor) {
      const Status r = emit_visible(c, k, static_cast<uint64_t>(cursor),
                                    static_cast<uint64_t>(until), root, chords, intervals, st);
      if (!ok(r)) return r;
      drew = true;
    }
    if (i < n && gaps[i].hi > cursor) cursor = gaps[i].hi;
  }
  if (!drew) ++st.hidden;
  return Status::kOk;
}

template <typename Carve>
void carve(Carve& c, uint32_t edges, uint32_t most_hits, uint32_t** order, uint32_t** link,
           int64_t** end_gap, CurvePiece** stack, Gap** gaps) {
  *order = c.template take<uint32_t>(size_t{2} * edges);
  *link = c.template take<uint32_t>(size_t{2} * edges);
  *end_gap = c.template take<int64_t>(size_t{2} * edges);
  *stack = c.template take<CurvePiece>(kCurveMaxDepth + 2);
  *gaps = c.template take<Gap>(size_t{3} * most_hits + 2 + edges);
}

}  // namespace

Status plan_curve_draw(const BezierEdge3* curves, uint32_t n_curves, const Edge3* segments,
                       uint32_t n_segments, const CurveHit* hits, uint32_t n_hits,
                       const CurveDrawParams& params, CurveDrawPlan* plan) {
  *plan = CurveDrawPlan();
  if (params.halo < 0 || params.halo > kCoordMax || params.chord_tol_q8 == 0 ||
      params.chord_tol_q8 > (uint32_t{1} << 16))
    return Status::kBadParameter;
  if (uint64_t{n_curves} + n_segments > kMaxCurveCount) return Status::kTooManyEdges;
  for (uint32_t i = 0; i < n_curves; ++i)
    if (!in_range(curves[i])) return Status::kCoordinateOutOfRange;
  for (uint32_t i = 0; i < n_segments; ++i)
    if (!in_range(segments[i])) return Status::kCoordinateOutOfRange;
  const uint32_t n = n_curves + n_segments;
  uint32_t run = 0;
  for (uint32_t i = 0; i < n_hits; ++i) {
    const CurveHit& h = hits[i];
    // Hits must be run_curve_cross()'s: on these edges, sorted by curve.
    if (h.curve >= n || h.other >= n || h.t > kCurveParamOne || h.other_t > kCurveParamOne ||
        h.t_err > kCurveParamOne || (i > 0 && hits[i - 1].curve > h.curve))
      return Status::kBadParameter;
    run = (i > 0 && hits[i - 1].curve == h.curve) ? run + 1 : 1;
    if (run > plan->most_hits) plan->most_hits = run;
  }
  plan->n_curves = n_curves;
  plan->n_segments = n_segments;
  plan->n_hits = n_hits;
  plan->params = params;
  ByteCounter bytes;
  uint32_t *order, *link;
  int64_t* end_gap;
  CurvePiece* stack;
  Gap* gaps;
  carve(bytes, n, plan->most_hits, &order, &link, &end_gap, &stack, &gaps);
  plan->scratch_bytes = bytes.total;
  return Status::kOk;
}

namespace {

Status draw_run(const CurveDrawPlan& plan, const BezierEdge3* curves, const Edge3* segments,
                const CurveHit* hits, uint32_t n_hits, void* scratch, size_t scratch_bytes,
                SpanSink chords, const CurveIntervalSink* intervals, CurveDrawStats* stats,
                ExactFront* exact) {
  CurveDrawStats st;
  if (buffer_misaligned(scratch)) return Status::kMisalignedBuffer;
  if (n_hits != plan.n_hits) return Status::kBadParameter;  // not the hits the plan checked
  const uint32_t n = plan.n_curves + plan.n_segments;
  Carver carver(scratch, scratch_bytes);
  uint32_t *order, *link;
  int64_t* end_gap;
  CurvePiece* stack;
  Gap* gaps;
  carve(carver, n, plan.most_hits, &order, &link, &end_gap, &stack, &gaps);
  if (carver.short_) return Status::kWorkspaceTooSmall;
  const Scene s{curves,           plan.n_curves, n,       segments, hits, n_hits,
                plan.params.halo, link,          end_gap, &st,      exact};
  st.joints = link_joints(s, order, link);
  for (uint32_t i = 0; i < 2 * n; ++i) end_gap[i] = 0;
  const bool haloed = plan.params.halo > 0;
  if (haloed) {  // the first pass: what reaches each edge over its ends
    joint_crossings(s, order);
    through_joints(s, order, 0, n, stack, nullptr);
    for (uint32_t k = 0; k < n; ++k) hit_gaps(s, k, stack, nullptr);
  }
  for (uint32_t k = 0; k < n; ++k) {
    const uint32_t g = haloed ? collect_gaps(s, k, order, stack, gaps) : 0;
    const Status r = draw_edge(s, k, gaps, g, plan.params, chords, intervals, st);
    if (!ok(r)) return r;
  }
  if (stats != nullptr) *stats = st;
  return Status::kOk;
}

}  // namespace

Status run_curve_draw(const CurveDrawPlan& plan, const BezierEdge3* curves, const Edge3* segments,
                      const CurveHit* hits, uint32_t n_hits, void* scratch, size_t scratch_bytes,
                      SpanSink chords, const CurveIntervalSink* intervals, CurveDrawStats* stats) {
  return draw_run(plan, curves, segments, hits, n_hits, scratch, scratch_bytes, chords, intervals,
                  stats, nullptr);
}

Status plan_curve_draw_exact(const BezierEdge3* curves, uint32_t n_curves, const Edge3* segments,
                             uint32_t n_segments, const CurveHit* hits, uint32_t n_hits,
                             const CurveDrawParams& params, CurveDrawPlan* plan) {
  const Status st =
      plan_curve_draw(curves, n_curves, segments, n_segments, hits, n_hits, params, plan);
  if (!ok(st)) return st;
  uint64_t most = 1;
  for (uint32_t k = 0; k < n_curves; ++k) {
    const uint64_t r = front_root(ctl_of(curves, n_curves, segments, k));
    most = r > most ? r : most;
  }
  plan->front_points = static_cast<uint32_t>(most + 2);
  plan->scratch_bytes += carve_round(size_t{kFrontRuns} * plan->front_points * 16);
  return Status::kOk;
}

Status run_curve_draw_exact(const CurveDrawPlan& plan, const BezierEdge3* curves,
                            const Edge3* segments, const CurveHit* hits, uint32_t n_hits,
                            void* scratch, size_t scratch_bytes, SpanSink chords,
                            const CurveIntervalSink* intervals, CurveDrawStats* stats) {
  if (plan.front_points == 0) return Status::kBadParameter;  // plan_curve_draw_exact's plan
  // The front strand at the scratch's end (plan_curve_draw_exact added its bytes).
  const size_t front_bytes = size_t{kFrontRuns} * plan.front_points * sizeof(int64_t[2]);
  if (buffer_misaligned(scratch)) return Status::kMisalignedBuffer;
  if (scratch_bytes < front_bytes) return Status::kWorkspaceTooSmall;
  const size_t rest = (scratch_bytes - front_bytes) & ~size_t{7};
  ExactFront front{};
  front.pts = reinterpret_cast<int64_t(*)[2]>(static_cast<unsigned char*>(scratch) + rest);
  front.cap = plan.front_points;
  const int64_t w8 = int64_t{plan.params.halo} << kFrontQ;
  front.w2 = w8 * w8;
  front.walk = &walk_exact;
  front.around = &front_around;
  front.vertex = &front_from_vertex;
  return draw_run(plan, curves, segments, hits, n_hits, scratch, rest, chords, intervals, stats,
                  &front);
}

}  // namespace haloplot
