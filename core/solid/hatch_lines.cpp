#include "haloplot/solid/hatch_lines.h"

#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/quarter_turn.h"
#include "solid/cover.h"

namespace haloplot {
namespace {

// w = n . p with n in Q2.30 and coordinates below 2^20: below 2^51; the levels k S likewise. A
// side's point: a coordinate difference (2^21) times a 31-bit fraction.
static_assert(kCoordBits + kTrigFractionBits + 1 < 62, "a line's level fits in int64");
// Turned (HatchParams::turned), a level has a third such term: three below 2^51 each.
static_assert(kCoordBits + kTrigFractionBits + 3 < 63, "a turned line's level fits in int64");
static_assert(kCoordBits + 1 + 31 < 63, "a side's point fits in int64");

bool point_before(const Point3& p, const Point3& q) {
  if (p.x != q.x) return p.x < q.x;
  if (p.y != q.y) return p.y < q.y;
  return p.z < q.z;
}

// round(d * num / den) for 0 < num < den < 2^52 and |d| < 2^21: num and den are first cut to
// 31 bits, so it is one int64 product and division (the position along the side then carries a
// relative error below 2^-30: under 2^-9 units on a side below 2^21). Deterministic, so the
// host and the chip, and two triangles sharing the side, get the same point.
int32_t lerp_round(int64_t d, int64_t num, int64_t den) {
  const int shift = 64 - __builtin_clzll(uint64_t(den)) - 31;
  if (shift > 0) {
    num >>= shift;
    den >>= shift;
  }
  const int64_t p = d * num;
  return static_cast<int32_t>(p >= 0 ? (p + den / 2) / den : -((-p + den / 2) / den));
}

// Where the side from p (w_p) to q (w_q) meets the level, strictly inside it, rounded to
// units from the side's lesser end: any triangle holding the side finds the same point.
Point3 side_point(Point3 p, Point3 q, int64_t a, int64_t b) {
  if (point_before(q, p)) {
    const Point3 t = p;
    p = q;
    q = t;
    const int64_t u = a;
    a = b;
    b = u;
  }
  const int64_t den = a - b > 0 ? a - b : b - a, num = a - b > 0 ? a : -a;
  return Point3{p.x + lerp_round(int64_t{q.x} - p.x, num, den),
                p.y + lerp_round(int64_t{q.y} - p.y, num, den),
                p.z + lerp_round(int64_t{q.z} - p.z, num, den)};
}

// The lattice line at `level` clipped to the triangle with corners q (their w): false when it
// misses the triangle or touches it at one point.
bool triangle_segment(const Point3 q[3], const int64_t w[3], int64_t level, Edge3* out) {
  Point3 ends[2];
  int n = 0;
  for (int i = 0; i < 3 && n < 2; ++i) {
    const int j = (i + 1) % 3;
    const int64_t a = w[i] - level, b = w[j] - level;
    Point3 at;
    if (a == 0)
      at = q[i];
    else if ((a < 0) != (b < 0) && b != 0)
      at = side_point(q[i], q[j], a, b);
    else
      continue;
    if (n == 1 && ends[0].x == at.x && ends[0].y == at.y) continue;
    ends[n++] = at;
  }
  *out = Edge3{ends[0], ends[1]};
  return n == 2;
}

bool same_point(const Point3& p, const Point3& q) { return p.x == q.x && p.y == q.y && p.z == q.z; }

int64_t distance2(const Point3& p, const Point3& q) {
  const int64_t dx = int64_t{p.x} - q.x, dy = int64_t{p.y} - q.y;
  return dx * dx + dy * dy;
}

// Pieces of one lattice line that meet end to end (the triangles of a flat polygon meet on their
// diagonals, where both round the point alike) become one: the two ends farthest apart.
uint32_t join_pieces(Edge3* seg, uint32_t n) {
  for (bool merged = true; merged;) {
    merged = false;
    for (uint32_t i = 0; i < n && !merged; ++i)
      for (uint32_t j = i + 1; j < n && !merged; ++j) {
        const Edge3 a = seg[i], b = seg[j];
        if (!same_point(a.a, b.a) && !same_point(a.a, b.b) && !same_point(a.b, b.a) &&
            !same_point(a.b, b.b))
          continue;
        const Point3 ends[4] = {a.a, a.b, b.a, b.b};
        Edge3 best = a;
        for (int u = 0; u < 4; ++u)
          for (int v = u + 1; v < 4; ++v)
            if (distance2(ends[u], ends[v]) > distance2(best.a, best.b))
              best = Edge3{ends[u], ends[v]};
        seg[i] = best;
        seg[j] = seg[--n];
        merged = true;
      }
  }
  return n;
}

// A flat polygon of at most this many triangles, all hatched, takes its lines across it whole.
constexpr uint32_t kJoined = 8;

// Calls line(Edge3, face) for each hatch line of triangles [s, e) of one polygon: the lattice
// lines n . p = k S clipped to each triangle (those lays(t) accepts, when not joined), ends
// rounded, joined across the polygon when `joined`. Joined lines shorter than params.min_length
// on paper (both axes) are not laid: such a line crosses only the tip of a corner of the
// polygon. A triangle's piece of a line is laid however short: the line goes on into the
// triangles beyond its sides (a smooth region is hatched triangle by triangle), and a short
// piece across a corner is what joins the pieces on either side of it; left out, it left a gap
// of a step in the line every few triangles. Where it is alone, the planner's clean-up drops it
// (motion/path_plan.h: --min-stroke).
template <typename Lays, typename Line>
Status polygon_lines(const Topology& topo, uint32_t s, uint32_t e, bool joined,
                     const HatchParams& p, Lays lays, Line line) {
  const SinCos d = hatch_direction(topo.triangles, topo.n_triangles, topo.vertices, s, p);
  // The lines' normal (Q2.30) and the level of the origin: n . p - w0 is the page's level of
  // the page point p stands for. Turned, p = (y, kTurnOffset - x) for the page's (x, y), so
  // the page's normal (-sin, cos) becomes (cos, sin) and the origin's level sin kTurnOffset.
  const int64_t nx = p.turned ? d.cos : -d.sin, ny = p.turned ? d.sin : d.cos;
  const int64_t w0 = p.turned ? d.sin * kTurnOffset : 0;
  const int64_t spacing = int64_t{p.spacing} << kTrigFractionBits;
  for (uint32_t first = s; first < e; first = joined ? e : first + 1) {
    const uint32_t last = joined ? e : first + 1;
    if (!joined && !lays(first)) continue;  // a triangle of a bent polygon that is not hatched
    Point3 q[kJoined][3];
    int64_t w[kJoined][3];
    int64_t lo = 0, hi = 0;
    for (uint32_t t = first; t < last; ++t)
      for (int k = 0; k < 3; ++k) {
        q[t - first][k] = topo.vertices[topo.triangles[t].v[k]];
        const int64_t wk = nx * q[t - first][k].x + ny * q[t - first][k].y - w0;
        w[t - first][k] = wk;
        lo = (t == first && k == 0) || wk < lo ? wk : lo;
        hi = (t == first && k == 0) || wk > hi ? wk : hi;
      }
    const int64_t k0 = -floor_div(-lo, spacing), k1 = floor_div(hi, spacing);
    for (int64_t k = k0; k <= k1; ++k) {
      Edge3 seg[kJoined];
      uint32_t n = 0;
      for (uint32_t t = first; t < last; ++t)
        if (triangle_segment(q[t - first], w[t - first], k * spacing, &seg[n])) ++n;
      n = join_pieces(seg, n);
      for (uint32_t i = 0; i < n; ++i) {
        const int32_t dx = seg[i].b.x - seg[i].a.x, dy = seg[i].b.y - seg[i].a.y;
        if (joined && (dx < 0 ? -dx : dx) < p.min_length && (dy < 0 ? -dy : dy) < p.min_length)
          continue;
        const Status r = line(seg[i], first);
        if (r != Status::kOk) return r;
      }
    }
  }
  return Status::kOk;
}

}  // namespace

bool hatched_face(const Topology& topo, const uint8_t* front, uint32_t t,
                  const HatchParams& params) {
  if (front != nullptr) return front[t] != 0;
  const uint32_t* v = topo.triangles[t].v;
  const int64_t area =
      projected_area2(topo.vertices[v[0]], topo.vertices[v[1]], topo.vertices[v[2]]);
  return params.front_only ? area > 0 : area != 0;
}

Status draw_hatch_lines(const Topology& topo, const uint8_t* front, const FaceGrid& fg,
                        const HatchParams& params, uint32_t first_index, LineSink sink,
                        HatchLineStats* stats, LineRows rows) {
  if (params.spacing < 1 || params.spacing > kCoordMax) return Status::kBadParameter;
  HatchLineStats st;
  uint32_t index = first_index;
  Status s = Status::kOk;
  // Polygon by polygon (runs of triangles with one id): joined when flat, small and hatched
  // whole, triangle by triangle otherwise.
  for (uint32_t first = 0, end = 0; first < topo.n_triangles && s == Status::kOk; first = end) {
    const uint32_t polygon = topo.triangles[first].polygon;
    uint32_t hatched = 0;
    bool flat = true;
    for (end = first; end < topo.n_triangles && topo.triangles[end].polygon == polygon; ++end) {
      hatched += hatched_face(topo, front, end, params) ? 1 : 0;
      flat = flat && coplanar_faces(topo, first, end);
    }
    if (hatched == 0) continue;
    st.faces += hatched;
    const bool joined = flat && hatched == end - first && end - first <= kJoined;
    const uint32_t begin = first, stop = end;  // the polygon's triangles
    auto lays = [&](uint32_t t) { return hatched_face(topo, front, t, params); };
    s = polygon_lines(topo, first, end, joined, params, lays, [&](const Edge3& e, uint32_t t) {
      const int32_t y0 = min_i32(e.a.y, e.b.y), y1 = max_i32(e.a.y, e.b.y);
      if (rows.on && (y1 < rows.lo || y0 >= rows.hi)) return Status::kOk;  // not in the band
      ++st.lines;
      // A line across the polygon ends on its sides; one laid in triangle t ends on t's, so
      // only t's neighbours can meet its rounded ends (and a large flat region, thousands of
      // slivers, is not searched for every face asked).
      const bool small = stop - begin <= kJoined;
      const uint32_t near0 = joined || small ? begin : t, near1 = joined || small ? stop : t + 1;
      const SegmentPass pass{topo, front, fg, &st, e, {t, kNoFace}, polygon, near0, near1};
      return pass.run(index++, sink, rows);
    });
  }
  if (stats != nullptr) *stats = st;
  return s;
}

}  // namespace haloplot
