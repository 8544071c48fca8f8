#include "haloplot/view2d/polygon_view.h"

#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/wide.h"
#include "sort/in_place_sort.h"

namespace haloplot {
namespace {

// Bit budget: coordinates within 2^20, differences within 2^21, cross products within 2^43;
// parameters are ratios of two cross products; comparing two of them needs 2^86: Wide.
static_assert(int64_t{2} * kView2dLimit * 2 * kView2dLimit * 2 < (int64_t{1} << 62),
              "cross products of coordinate differences fit int64");

int sign(int64_t v) { return (v > 0) - (v < 0); }

int64_t cross(int64_t ax, int64_t ay, int64_t bx, int64_t by) { return ax * by - ay * bx; }

// orient(a, b, c): twice the signed area of the triangle, unperturbed.
int64_t orient(Point2 a, Point2 b, Point2 c) {
  return cross(int64_t{b.x} - a.x, int64_t{b.y} - a.y, int64_t{c.x} - a.x, int64_t{c.y} - a.y);
}

bool less(Ratio a, Ratio b) { return mul_i64(a.num, b.den) < mul_i64(b.num, a.den); }

Ratio make_ratio(int64_t num, int64_t den) { return den < 0 ? Ratio{-num, -den} : Ratio{num, den}; }

// The geometry as the walk sees it: vertices in walk order (oriented so visible edges turn
// counterclockwise about E) and the vantage point, perturbed symbolically.
struct Scene {
  const Point2* v;
  uint32_t n;
  Point2 e;

  uint32_t next(uint32_t i) const { return i + 1 == n ? 0 : i + 1; }
  uint32_t ahead(uint32_t from, uint32_t to) const {
    return to >= from ? to - from : to + n - from;
  }

  // Sign of cross(A - E', B - E') with E' = E + (eps, eps^2): the first non-zero of the exact
  // cross product, (A - B).y and -(A - B).x. Zero only when A = B. (Simulation of simplicity:
  // no two distinct vertices are ever on one line through E'.)
  int turn(Point2 a, Point2 b) const {
    const int64_t c =
        cross(int64_t{a.x} - e.x, int64_t{a.y} - e.y, int64_t{b.x} - e.x, int64_t{b.y} - e.y);
    if (c != 0) return sign(c);
    if (a.y != b.y) return sign(int64_t{a.y} - b.y);
    return -sign(int64_t{a.x} - b.x);
  }
  int turn(uint32_t a, uint32_t b) const { return turn(v[a], v[b]); }

  // Along the ray from E through vertex r (R = v[r] - E): t of the crossing with edge i, and
  // s, the parameter of that point along the edge. Exact ratios of unperturbed cross products.
  Ratio ray_t(uint32_t r, uint32_t i) const {
    const Point2 u = v[i], w = v[next(i)];
    const int64_t dx = int64_t{w.x} - u.x, dy = int64_t{w.y} - u.y;
    return make_ratio(cross(int64_t{u.x} - e.x, int64_t{u.y} - e.y, dx, dy),
                      cross(int64_t{v[r].x} - e.x, int64_t{v[r].y} - e.y, dx, dy));
  }
  Ratio edge_s(uint32_t r, uint32_t i) const {
    const Point2 u = v[i], w = v[next(i)];
    const int64_t rx = int64_t{v[r].x} - e.x, ry = int64_t{v[r].y} - e.y;
    return make_ratio(cross(int64_t{e.x} - u.x, int64_t{e.y} - u.y, rx, ry),
                      cross(int64_t{w.x} - u.x, int64_t{w.y} - u.y, rx, ry));
  }
};

// A visible point of the walk: on edge `edge` at parameter s, on the ray from E through
// vertex `ray` at parameter t (a vertex is its own ray, t = 1).
struct WalkPoint {
  uint32_t edge;
  Ratio s;
  uint32_t ray;
  Ratio t;
};

WalkPoint at_vertex(uint32_t i) { return {i, {0, 1}, i, {1, 1}}; }

// Total angles (step 2) relative to the direction of vertex 0: whole turns, then the angle's
// place in [0, 2 pi) by half-plane and cross product.
struct Angles {
  const Scene& s;
  int rank(uint32_t x) const { return x == 0 ? 0 : (s.turn(0u, x) > 0 ? 1 : 2); }
  bool angle_less(uint32_t a, uint32_t b) const {
    const int ra = rank(a), rb = rank(b);
    if (ra != rb) return ra < rb;
    return ra != 0 && s.turn(a, b) > 0;
  }
  // Turn count change along edge i -> i+1: +1 when a counterclockwise step crosses the
  // reference direction, -1 when a clockwise one does.
  int crossing(uint32_t i) const {
    const uint32_t j = s.next(i);
    if (s.turn(i, j) > 0) return angle_less(j, i) ? 1 : 0;
    return angle_less(i, j) ? -1 : 0;
  }
  bool total_less(int32_t ta, uint32_t a, int32_t tb, uint32_t b) const {
    return ta != tb ? ta < tb : angle_less(a, b);
  }
};

struct Output {
  VisibleSink sink;
  const Scene& sc;
  bool reversed;  // walk order runs against the input order
  Status emit(uint32_t edge, Ratio s0, Ratio s1) const {
    if (!less(s0, s1)) return Status::kOk;  // an empty piece
    // Step 13: an edge exactly in line with E is seen edge-on. The walk passes along it
    // (the perturbed E sees it from one side) but it covers no direction: invisible.
    if (orient(sc.e, sc.v[edge], sc.v[sc.next(edge)]) == 0) return Status::kOk;
    const uint32_t n = sc.n;
    VisibleSpan span{edge, s0, s1};
    if (reversed) {  // internal edge i is input edge n - 2 - i, traversed backwards
      span.edge = (2 * n - 2 - edge) % n;
      span.s0 = Ratio{s1.den - s1.num, s1.den};
      span.s1 = Ratio{s0.den - s0.num, s0.den};
    }
    return sink.emit(sink.context, span);
  }
};

// Steps 7-11 and 14: the nearest crossing of the boundary with the ray from E through vertex
// r strictly beyond t_min. Returns false if there is none; *ccw tells its direction.
bool shoot(const Scene& sc, uint32_t r, Ratio t_min, uint32_t* edge, Ratio* t, bool* ccw) {
  bool found = false;
  for (uint32_t i = 0; i < sc.n; ++i) {
    const uint32_t j = sc.next(i);
    const int ou = sc.turn(r, i), ow = sc.turn(r, j);
    if (ou == 0 || ow == 0 || ou == ow) continue;  // touches at r itself, or no crossing
    const bool counter = ou < 0;
    if (sc.turn(i, j) != (counter ? 1 : -1)) continue;  // crosses the line behind E
    const Ratio ti = sc.ray_t(r, i);
    if (!less(t_min, ti)) continue;
    // A tie is the perturbed ray clipping a corner V exactly on the unperturbed ray: both of
    // V's edges cross at V's t. Seen from outside, the ray enters (counterclockwise edge)
    // before it leaves, so the entering edge wins the tie.
    const bool tie = found && !less(ti, *t) && !less(*t, ti);
    if (!found || less(ti, *t) || (tie && counter && !*ccw))
      *edge = i, *t = ti, *ccw = counter, found = true;
  }
  return found;
}

// Steps 15-17: among vertices strictly inside the triangle E, P, target (the wedge between
// the rays through P and target, on E's side of the edge's line), the most clockwise. Skips
// the vertices Proposition 3 has eliminated.
bool forward_bay(const Scene& sc, const WalkPoint& p, uint32_t target_ray, uint32_t first_skip,
                 uint32_t skip_count, uint32_t* k, View2dStats& st) {
  const Point2 u = sc.v[p.edge], w = sc.v[sc.next(p.edge)];
  const int e_side = sc.turn(p.edge, sc.next(p.edge));  // E' relative to the edge's line
  bool found = false;
  for (uint32_t x = 0; x < sc.n; ++x) {
    if (skip_count && sc.ahead(first_skip, x) < skip_count) continue;
    ++st.vertex_tests;
    if (sc.turn(p.ray, x) <= 0 || sc.turn(x, target_ray) <= 0) continue;  // outside the wedge
    if (sign(orient(u, w, sc.v[x])) != e_side) continue;                  // behind the edge
    if (!found || sc.turn(x, *k) > 0) *k = x, found = true;
  }
  return found;
}

// Segment intersection for validation: closed segments, exact.
bool on_segment(Point2 a, Point2 b, Point2 p) {
  return orient(a, b, p) == 0 && (p.x < a.x ? a.x : p.x) <= (b.x > a.x ? b.x : a.x) &&
         (p.x > a.x ? a.x : p.x) >= (b.x < a.x ? b.x : a.x) &&
         (p.y < a.y ? a.y : p.y) <= (b.y > a.y ? b.y : a.y) &&
         (p.y > a.y ? a.y : p.y) >= (b.y < a.y ? b.y : a.y);
}

bool segments_meet(Point2 a, Point2 b, Point2 c, Point2 d) {
  const int o1 = sign(orient(a, b, c)), o2 = sign(orient(a, b, d));
  const int o3 = sign(orient(c, d, a)), o4 = sign(orient(c, d, b));
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return on_segment(a, b, c) || on_segment(a, b, d) || on_segment(c, d, a) || on_segment(c, d, b);
}

// The polygon is simple: consecutive edges meet only at their shared vertex (no fold back),
// others not at all. Edges sorted by their left end; each is tested against the edges whose
// x-extent overlaps it (no heap: the caller's index buffer).
Status check_simple(const Point2* p, uint32_t n, uint32_t* order, uint32_t bad[2]) {
  auto lo_x = [&](uint32_t i) { return p[i].x < p[(i + 1) % n].x ? p[i].x : p[(i + 1) % n].x; };
  auto hi_x = [&](uint32_t i) { return p[i].x > p[(i + 1) % n].x ? p[i].x : p[(i + 1) % n].x; };
  for (uint32_t i = 0; i < n; ++i) order[i] = i;
  sort_in_place(order, n, [&](uint32_t a, uint32_t b) { return lo_x(a) < lo_x(b); });
  for (uint32_t a = 0; a < n; ++a) {
    const uint32_t i = order[a];
    for (uint32_t b = a + 1; b < n && lo_x(order[b]) <= hi_x(i); ++b) {
      const uint32_t j = order[b];
      const Point2 pi = p[i], qi = p[(i + 1) % n], pj = p[j], qj = p[(j + 1) % n];
      bool bad_pair;
      if ((i + 1) % n == j || (j + 1) % n == i) {  // neighbours share one vertex
        const bool i_first = (i + 1) % n == j;
        const Point2 shared = i_first ? qi : pi, far_i = i_first ? pi : qi,
                     far_j = i_first ? qj : pj;
        bad_pair = orient(far_i, shared, far_j) == 0 &&
                   (int64_t{far_i.x} - shared.x) * (int64_t{far_j.x} - shared.x) +
                           (int64_t{far_i.y} - shared.y) * (int64_t{far_j.y} - shared.y) >
                       0;
        if (n == 3) bad_pair = bad_pair || orient(p[0], p[1], p[2]) == 0;
      } else {
        bad_pair = segments_meet(pi, qi, pj, qj);
      }
      if (bad_pair) {
        if (bad) bad[0] = i < j ? i : j, bad[1] = i < j ? j : i;
        return Status::kSelfIntersecting;
      }
    }
  }
  return Status::kOk;
}

// The input's checks, in the order their errors take precedence: coordinates in range, no
// zero-length edge, a simple polygon with area, and E not on it. *area2: twice the signed area.
Status check_input(const Point2* poly, uint32_t n, Point2 eye, uint32_t* order,
                   uint32_t bad_edges[2], int64_t* area2) {
  auto in_range = [](Point2 q) {
    return q.x >= -kView2dLimit && q.x <= kView2dLimit && q.y >= -kView2dLimit &&
           q.y <= kView2dLimit;
  };
  if (!in_range(eye)) return Status::kCoordinateOutOfRange;
  *area2 = 0;
  for (uint32_t i = 0; i < n; ++i) {
    const Point2 a = poly[i], b = poly[(i + 1) % n];
    if (!in_range(a)) return Status::kCoordinateOutOfRange;
    if (a.x == b.x && a.y == b.y) {
      if (bad_edges) bad_edges[0] = bad_edges[1] = i;
      return Status::kSelfIntersecting;  // a zero-length edge
    }
    *area2 += cross(a.x, a.y, b.x, b.y);
  }
  const Status status = check_simple(poly, n, order, bad_edges);
  if (!ok(status)) return status;
  if (*area2 == 0) return Status::kSelfIntersecting;
  for (uint32_t i = 0; i < n; ++i)
    if (on_segment(poly[i], poly[(i + 1) % n], eye)) return Status::kBadParameter;  // E on P
  return Status::kOk;
}

// Steps 12-19: walk from visible point to visible point, handing each visible piece out.
struct Walk {
  const Scene& sc;
  const Output& out;
  View2dStats& st;
  bool free_view;
  uint32_t skip_first, skip_count;  // Proposition 3's vertices, never tested again
  uint32_t end_ahead;               // step 20: a free exterior's walk ends at Am

  Status run(const WalkPoint& start) const {
    const uint32_t n = sc.n;
    WalkPoint p = start;
    uint32_t walked = 0;  // edges advanced since the start
    for (uint32_t guard = 0; guard < 4 * n + 8; ++guard) {
      if (free_view && walked >= end_ahead) break;
      const bool closing = !free_view && walked >= n;  // back on the start edge, a turn later
      if (closing && (walked > n || !less(p.s, start.s))) break;
      const uint32_t nxt = sc.next(p.edge);
      const uint32_t target_ray = closing ? start.ray : nxt;
      const Ratio target_s = closing ? start.s : Ratio{1, 1};
      if (sc.turn(p.ray, target_ray) > 0) {
        uint32_t k = 0;
        if (forward_bay(sc, p, target_ray, skip_first, skip_count, &k, st)) {
          // Step 19: hidden from the ray E A(k) on; A(k) is the next visible vertex.
          ++st.forward_bays;
          const Status status = out.emit(p.edge, p.s, sc.edge_s(k, p.edge));
          if (!ok(status)) return status;
          if (closing) break;
          walked += sc.ahead(p.edge, k);
          p = at_vertex(k);
        } else {
          // Step 18: Proposition 2, the piece to the target is visible.
          ++st.visible_steps;
          const Status status = out.emit(p.edge, p.s, target_s);
          if (!ok(status)) return status;
          if (closing) break;
          walked += 1;
          p = at_vertex(nxt);
        }
      } else {
        // Step 14: a backward bay. The walk resumes where the boundary next crosses the ray
        // through P beyond P, counterclockwise.
        if (closing) break;
        ++st.backward_bays;
        uint32_t edge;
        Ratio t;
        bool ccw;
        if (!shoot(sc, p.ray, p.t, &edge, &t, &ccw) || !ccw || edge == p.edge)
          return Status::kVisibilityInconsistent;
        walked += sc.ahead(p.edge, edge);
        p = WalkPoint{edge, sc.edge_s(p.ray, edge), p.ray, t};
      }
    }
    return Status::kOk;
  }
};

}  // namespace

size_t view2d_scratch_bytes(uint32_t n) { return size_t{n} * (sizeof(Point2) + sizeof(uint32_t)); }

void visible_point(Point2 a, Point2 b, Ratio s, int32_t* x, int32_t* y) {
  const int64_t t32 = s.num >= s.den ? (int64_t{1} << 32) : int64_t{frac_q32(s.num, s.den)};
  *x = lerp_round(a.x, b.x - a.x, t32);
  *y = lerp_round(a.y, b.y - a.y, t32);
}

Status view2d(const Point2* poly, uint32_t n, Point2 eye, void* scratch, size_t scratch_bytes,
              VisibleSink sink, View2dStats* stats, uint32_t bad_edges[2]) {
  View2dStats st;
  if (n < 3) return Status::kBadParameter;
  if (buffer_misaligned(scratch)) return Status::kMisalignedBuffer;
  if (scratch_bytes < view2d_scratch_bytes(n)) return Status::kWorkspaceTooSmall;
  Point2* v = static_cast<Point2*>(scratch);
  uint32_t* order = reinterpret_cast<uint32_t*>(v + n);
  int64_t area2 = 0;
  Status status = check_input(poly, n, eye, order, bad_edges, &area2);
  if (!ok(status)) return status;

  // Steps 1-3: clockwise order (interior on the right), total angles, configuration. An
  // interior E reverses the order once more, so visible edges always turn counterclockwise.
  bool reversed = area2 > 0;
  auto load = [&] {
    for (uint32_t i = 0; i < n; ++i) v[i] = reversed ? poly[n - 1 - i] : poly[i];
  };
  load();
  Scene sc{v, n, eye};
  Angles ang{sc};
  int32_t net = 0;
  for (uint32_t i = 0; i < n; ++i) net += ang.crossing(i);
  if (net != 0) {
    st.config = ViewConfig::kInterior;
    reversed = !reversed;
    load();
  }
  // Step 4: A1, the most clockwise vertex (least total angle), and Am, the most
  // counterclockwise (greatest).
  uint32_t a1 = 0, am = 0;
  int32_t turns = 0, t1 = 0, tm = 0;
  for (uint32_t i = 0; i < n; ++i) {
    if (ang.total_less(turns, i, t1, a1)) a1 = i, t1 = turns;
    if (ang.total_less(tm, am, turns, i)) am = i, tm = turns;
    turns += ang.crossing(i);
  }
  if (st.config != ViewConfig::kInterior)
    st.config = ang.total_less(tm, am, t1 + 1, a1) ? ViewConfig::kFreeExterior
                                                   : ViewConfig::kBlockedExterior;
  const bool free_view = st.config == ViewConfig::kFreeExterior;
  // Step 6, Proposition 3: from an exterior E, the edges after Am and before A1 are invisible;
  // their vertices (strictly between) are never tested again.
  uint32_t skip_first = 0, skip_count = 0;
  if (st.config != ViewConfig::kInterior) {
    st.prop3_edges = sc.ahead(am, a1);
    skip_first = sc.next(am);
    skip_count = st.prop3_edges > 0 ? st.prop3_edges - 1 : 0;
  }
  const Output out{sink, sc, reversed};

  // Steps 7-11: the first visible point. A free exterior's A1 is always visible; otherwise
  // the nearest crossing of the boundary with the ray E A1 nearer than A1, if any.
  WalkPoint p = at_vertex(a1);
  if (!free_view) {
    uint32_t edge;
    Ratio t;
    bool ccw;
    if (shoot(sc, a1, Ratio{0, 1}, &edge, &t, &ccw) && less(t, Ratio{1, 1})) {
      if (!ccw) return Status::kVisibilityInconsistent;  // a first hit always faces E
      p = WalkPoint{edge, sc.edge_s(a1, edge), a1, t};
    }
  }
  const uint32_t end_ahead = free_view ? sc.ahead(a1, am) : n;  // step 20
  status = Walk{sc, out, st, free_view, skip_first, skip_count, end_ahead}.run(p);
  if (!ok(status)) return status;
  if (stats) *stats = st;
  return Status::kOk;
}

}  // namespace haloplot
