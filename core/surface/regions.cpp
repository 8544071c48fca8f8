#include "haloplot/surface/regions.h"

#include "haloplot/geometry/predicates.h"
#include "haloplot/geometry/wide.h"
#include "haloplot/solid/face_grid.h"
#include "memory/carve.h"
#include "solid/cover.h"
#include "sort/in_place_sort.h"

namespace haloplot {
namespace {

// A node as a rational point (x / d, y / d). A crossing at t = tn / den along a -> b is
// x = a.x * den + tn * (b.x - a.x), a convex combination of coordinates below 2^20 times a
// denominator below 2^41: below 2^61. Comparing two nodes multiplies by the other's d.
static_assert(kCoordBits + (kCrossBits - 1) <= 61, "a node's numerator must fit in int64_t");
static_assert(61 + (kCrossBits - 1) <= 126, "node comparisons must fit in Wide");

struct Exact {
  int64_t x, y, d;
};

Edge3 edge_of(const SolidInput& in, uint32_t e) {
  return Edge3{in.vertices[in.edge_pairs[2 * e]], in.vertices[in.edge_pairs[2 * e + 1]]};
}

bool exact_end(const SolidInput& in, uint32_t e, const PieceEnd& end, Exact* out) {
  if (end.w == PieceEnd::kNoVertex) {
    const Point3 v = in.vertices[end.u];
    *out = Exact{v.x, v.y, 1};
    return true;
  }
  const Edge3 ed = edge_of(in, e);
  const CrossingTest x = test_crossing(ed, Edge3{in.vertices[end.u], in.vertices[end.w]});
  if (!x.crosses) return false;
  *out = Exact{int64_t{ed.a.x} * x.den + x.tn * (ed.b.x - ed.a.x),
               int64_t{ed.a.y} * x.den + x.tn * (ed.b.y - ed.a.y), x.den};
  return true;
}

int compare_exact(const Exact& p, const Exact& q) {
  const int c = compare(mul_i64(p.x, q.d), mul_i64(q.x, p.d));
  return c != 0 ? c : compare(mul_i64(p.y, q.d), mul_i64(q.y, p.d));
}

struct Dir {
  int64_t x, y;
};

Dir half_edge_dir(const SolidInput& in, const RegionSegment& s, uint32_t h) {
  const Edge3 e = edge_of(in, s.edge);
  const int64_t dx = e.b.x - e.a.x, dy = e.b.y - e.a.y;
  return (h & 1) ? Dir{-dx, -dy} : Dir{dx, dy};
}

// Counter-clockwise order of directions starting from +x (exact: 42-bit cross products).
bool angle_before(const Dir& a, const Dir& b) {
  const bool ha = a.y < 0 || (a.y == 0 && a.x < 0), hb = b.y < 0 || (b.y == 0 && b.x < 0);
  if (ha != hb) return !ha;
  return a.x * b.y - a.y * b.x > 0;
}

bool same_direction(const Dir& a, const Dir& b) {
  return a.x * b.y - a.y * b.x == 0 && a.x * b.x + a.y * b.y > 0;
}

// A triangle made counter-clockwise on paper (the same plane).
struct Tri {
  Point3 a, b, c;
  int64_t area;
};

Tri ccw(const SolidInput& in, uint32_t t) {
  const uint32_t* v = in.triangles[t].v;
  Tri r{in.vertices[v[0]], in.vertices[v[1]], in.vertices[v[2]], 0};
  r.area = projected_area2(r.a, r.b, r.c);
  if (r.area < 0) {
    const Point3 s = r.b;
    r.b = r.c;
    r.c = s;
    r.area = -r.area;
  }
  return r;
}

// The plane's depth at the integer point (x, y), times the area: below 2^64 in magnitude.
Wide depth_times_area(const Tri& t, int64_t x, int64_t y) {
  const int64_t cb = int64_t{t.c.x - t.a.x} * (y - t.a.y) - int64_t{t.c.y - t.a.y} * (x - t.a.x);
  const int64_t cc = int64_t{t.b.x - t.a.x} * (y - t.a.y) - int64_t{t.b.y - t.a.y} * (x - t.a.x);
  return mul_i64(int64_t{t.a.z}, t.area) - mul_i64(int64_t{t.b.z - t.a.z}, cb) +
         mul_i64(int64_t{t.c.z - t.a.z}, cc);
}

// Arithmetic shift right by 16, and the 16 bits shifted out (floor division by 2^16).
Wide shift16(Wide w, uint64_t* rest) {
  *rest = w.lo & 0xffffu;
  Wide r;
  r.lo = (w.lo >> 16) | (w.hi << 48);
  r.hi = uint64_t(int64_t(w.hi) >> 16);
  return r;
}

int sign(Wide w) { return w.negative() ? -1 : (w.is_zero() ? 0 : 1); }

// Sign of g0 * 2^32 + dg * m for |g0|, |dg| < 2^109 and 0 <= m <= 2^32 (up to 2^142: split m
// into 16-bit halves so every partial product stays below 2^126).
int sign_linear(Wide g0, Wide dg, int64_t m) {
  const int64_t mh = m >> 16, ml = m & 0xffff;
  const Wide h = mul_wide_i64(g0, int64_t{1} << 16) + mul_wide_i64(dg, mh);
  uint64_t rest = 0;
  const Wide q = h + shift16(mul_wide_i64(dg, ml), &rest);
  const int s = sign(q);
  return s != 0 ? s : (rest != 0 ? 1 : 0);
}
static_assert(64 + (kCrossBits - 1) + 2 <= 109, "depth differences must fit sign_linear");

// Is F nearer than G (larger depth) at Q0.32 position m on edge e, nudged along `dir`?
// Both depths are linear along the edge: g(t) = zF - zG, scaled by both areas.
bool nearer(const Tri& f, const Tri& g, const Edge3& e, int64_t m, const Dir& dir) {
  const Wide ga = mul_wide_i64(depth_times_area(f, e.a.x, e.a.y), g.area) -
                  mul_wide_i64(depth_times_area(g, e.a.x, e.a.y), f.area);
  const Wide gb = mul_wide_i64(depth_times_area(f, e.b.x, e.b.y), g.area) -
                  mul_wide_i64(depth_times_area(g, e.b.x, e.b.y), f.area);
  const int s = sign_linear(ga, gb - ga, m);
  if (s != 0) return s > 0;
  // Level there (they share the edge, or cross on it): the one rising faster along the nudge.
  auto rise = [&](const Tri& t) {
    return int64_t{t.b.z - t.a.z} * (dir.x * (t.c.y - t.a.y) - dir.y * (t.c.x - t.a.x)) +
           int64_t{t.c.z - t.a.z} *
               (int64_t{t.b.x - t.a.x} * dir.y - int64_t{t.b.y - t.a.y} * dir.x);
  };
  return compare(mul_i64(rise(f), g.area), mul_i64(rise(g), f.area)) > 0;
}

template <typename C>
void carve_all(C& c, uint32_t n) {
  c.template take<Exact>(2 * size_t{n});         // ends
  c.template take<uint32_t>(2 * size_t{n});      // node of each end
  c.template take<uint32_t>(2 * size_t{n});      // scratch order (ends, then half-edges)
  c.template take<uint8_t>(n);                   // kept
  c.template take<uint64_t>(n);                  // segment keys, for duplicates
  c.template take<uint32_t>(2 * size_t{n} + 1);  // node_first
  c.template take<uint32_t>(2 * size_t{n});      // position of each half-edge in the order
  c.template take<uint32_t>(2 * size_t{n});      // cycle of each half-edge
  c.template take<uint32_t>(2 * size_t{n});      // cycle faces
  c.template take<uint8_t>(2 * size_t{n});       // cycle bounded
}

// One run's state: the segments, the arrays carved for them, and what each step found.
struct RegionRun {
  const SolidInput& in;
  const RegionSegment* seg;
  uint32_t n;
  Exact* ends;
  uint32_t* node;
  uint32_t* order;
  uint8_t* kept;
  uint64_t* keys;
  uint32_t* node_first;
  uint32_t* pos;
  uint32_t* cycle;
  uint32_t* cycle_face;
  uint8_t* cycle_bounded;
  RegionStats& st;
  uint32_t nodes = 0, nh = 0, cycles = 0;

  uint32_t origin(uint32_t h) const { return node[h]; }  // half-edge 2s leaves end 2s's node
  Dir dir(uint32_t h) const { return half_edge_dir(in, seg[h / 2], h); }
  // next(h): the half-edge just clockwise of h's twin around h's far node.
  uint32_t next(uint32_t h) const {
    const uint32_t t = h ^ 1u, v = origin(t), i = pos[t];
    return order[i == node_first[v] ? node_first[v + 1] - 1 : i - 1];
  }

  Status merge_nodes();
  void drop_segments();
  void order_half_edges();
  bool opens_left(uint32_t start, uint32_t low) const;
  Status find_cycles();
  uint32_t face_left_of(const FaceGrid& fg, uint32_t h);
  void name_faces(const FaceGrid& fg);
};

// Step 10, nodes: every end as an exact point, sorted, equal points merged, so segments that
// meet share a node however their ends were computed.
Status RegionRun::merge_nodes() {
  for (uint32_t s = 0; s < n; ++s) {
    if (!exact_end(in, seg[s].edge, seg[s].from, &ends[2 * s]) ||
        !exact_end(in, seg[s].edge, seg[s].to, &ends[2 * s + 1]))
      return Status::kVisibilityInconsistent;
    order[2 * s] = 2 * s;
    order[2 * s + 1] = 2 * s + 1;
  }
  const Exact* at = ends;
  heap_sort(order, 2 * size_t{n},
            [&](uint32_t a, uint32_t b) { return compare_exact(at[a], at[b]) < 0; });
  for (uint32_t i = 0; i < 2 * n; ++i) {
    if (i > 0 && compare_exact(ends[order[i - 1]], ends[order[i]]) != 0) ++nodes;
    node[order[i]] = nodes;
  }
  if (n > 0) ++nodes;
  st.nodes = nodes;
  return Status::kOk;
}

// Segments: drop those of zero length and the second of two with the same nodes, which would
// otherwise make empty cycles.
void RegionRun::drop_segments() {
  for (uint32_t s = 0; s < n; ++s) {
    const uint32_t a = node[2 * s], b = node[2 * s + 1];
    kept[s] = a != b;
    st.zero_length += a == b;
    keys[s] = (uint64_t{a < b ? a : b} << 32) | (a < b ? b : a);
    order[s] = s;
  }
  const uint64_t* k = keys;
  heap_sort(order, n,
            [&](uint32_t a, uint32_t b) { return k[a] < k[b] || (k[a] == k[b] && a < b); });
  for (uint32_t i = 1; i < n; ++i)
    if (kept[order[i]] && keys[order[i]] == keys[order[i - 1]] && kept[order[i - 1]]) {
      kept[order[i]] = 0;
      ++st.duplicates;
    }
}

// Half-edges around each node in counter-clockwise order: what next() walks the cycles by.
void RegionRun::order_half_edges() {
  nh = 0;
  for (uint32_t h = 0; h < 2 * n; ++h)
    if (kept[h / 2]) order[nh++] = h;
  heap_sort(order, nh, [&](uint32_t a, uint32_t b) {
    if (origin(a) != origin(b)) return origin(a) < origin(b);
    return angle_before(dir(a), dir(b));
  });
  for (uint32_t v = 0; v <= nodes; ++v) node_first[v] = 0;
  for (uint32_t i = 0; i < nh; ++i) {
    ++node_first[origin(order[i]) + 1];
    pos[order[i]] = i;
    if (i > 0 && origin(order[i]) == origin(order[i - 1]) &&
        same_direction(dir(order[i]), dir(order[i - 1])))
      ++st.overlaps;
  }
  for (uint32_t v = 0; v < nodes; ++v) node_first[v + 1] += node_first[v];
}

// At its lowest node every half-edge points right (or straight up), so only one corner there
// opens to the left: the cycle whose corner it is bounds the outside of its piece (a hole
// boundary). A corner runs counter-clockwise from the way out to the way back; it opens to the
// left when that is the long way round, or all the way round (a spike).
bool RegionRun::opens_left(uint32_t start, uint32_t low) const {
  bool left = false;
  uint32_t h = start;
  do {
    const uint32_t nx = next(h);
    if (origin(nx) == low) {
      const Dir out_d = dir(nx);
      const Dir in_d = dir(h);
      const Dir back{-in_d.x, -in_d.y};
      const int64_t turn = out_d.x * back.y - out_d.y * back.x;
      left = left || turn < 0 || (turn == 0 && same_direction(out_d, back));
    }
    h = nx;
  } while (h != start);
  return left;
}

// Cycles, each classified at its lowest node (the smallest id: nodes are in (x, y) order).
Status RegionRun::find_cycles() {
  for (uint32_t h = 0; h < 2 * n; ++h) cycle[h] = kRegionBackground;
  cycles = 0;
  for (uint32_t i = 0; i < nh; ++i) {
    const uint32_t start = order[i];
    if (cycle[start] != kRegionBackground) continue;
    uint32_t h = start, low = origin(start), guard = 0;
    do {
      cycle[h] = cycles;
      low = origin(h) < low ? origin(h) : low;
      h = next(h);
      if (++guard > nh) return Status::kVisibilityInconsistent;
    } while (h != start);
    cycle_bounded[cycles] = !opens_left(start, low);
    st.bounded += cycle_bounded[cycles];
    ++cycles;
  }
  st.cycles = cycles;
  st.holes = cycles - st.bounded;
  return Status::kOk;
}

// The nearest face covering the middle of half-edge h's segment, nudged to its left (the
// cycle's inside), or kRegionBackground.
uint32_t RegionRun::face_left_of(const FaceGrid& fg, uint32_t h) {
  const RegionSegment& g = seg[h / 2];
  const Edge3 e = edge_of(in, g.edge);
  const int64_t m = g.t0 + (g.t1 - g.t0) / 2;
  CoverPoint pt = edge_point(e, m);
  const Dir d = half_edge_dir(in, g, h);
  const Dir left{-d.y, d.x};
  pt.dir_x = static_cast<int32_t>(left.x);
  pt.dir_y = static_cast<int32_t>(left.y);
  pt.dir_z = 0;
  uint32_t best = kRegionBackground;
  Tri best_tri{};
  for (const uint32_t* f = fg.begin(cell_x(pt), cell_y(pt)); f != fg.end(cell_x(pt), cell_y(pt));
       ++f) {
    ++st.face_tests;
    const Tri t = ccw(in, *f);
    if (t.area == 0 || projection_cover_halves(t.a, t.b, t.c, pt) != 2) continue;
    if (best == kRegionBackground || nearer(t, best_tri, e, m, left)) {
      best = *f;
      best_tri = t;
    }
  }
  return best;
}

// Step 11: each cycle's face, asked beside its longest segment (the one whose middle is
// surest to be away from the cycle's corners).
void RegionRun::name_faces(const FaceGrid& fg) {
  uint32_t* longest = cycle_face;  // reused: the half-edge, then the face
  for (uint32_t c = 0; c < cycles; ++c) longest[c] = kRegionUnnamed;
  for (uint32_t i = 0; i < nh; ++i) {
    const uint32_t h = order[i], c = cycle[h];
    const int64_t len = seg[h / 2].t1 - seg[h / 2].t0;
    if (len < 2) continue;
    if (longest[c] == kRegionUnnamed || len > seg[longest[c] / 2].t1 - seg[longest[c] / 2].t0)
      longest[c] = h;
  }
  for (uint32_t c = 0; c < cycles; ++c) {
    if (longest[c] == kRegionUnnamed) {
      ++st.unnamed;
      continue;
    }
    longest[c] = face_left_of(fg, longest[c]);
    st.background += longest[c] == kRegionBackground;
  }
}

}  // namespace

size_t regions_bytes(const SolidInput& in, uint32_t n_segments) {
  ByteCounter c;
  carve_all(c, n_segments);
  return c.total + face_grid_bytes(faces_only(in)) + 16;
}

Status build_regions(const SolidInput& in, const RegionSegment* seg, uint32_t n, void* buffer,
                     size_t bytes, Regions* out, RegionStats* stats) {
  RegionStats st;
  st.segments = n;
  if (uint64_t{n} * 2 + 1 > 0xffffffffu) return Status::kTooManyEdges;
  for (uint32_t s = 0; s < n; ++s)
    if (seg[s].edge >= in.n_edges) return Status::kBadParameter;
  Carver carve(buffer, bytes);
  RegionRun run{in,
                seg,
                n,
                carve.take<Exact>(2 * size_t{n}),
                carve.take<uint32_t>(2 * size_t{n}),
                carve.take<uint32_t>(2 * size_t{n}),
                carve.take<uint8_t>(n),
                carve.take<uint64_t>(n),
                carve.take<uint32_t>(2 * size_t{n} + 1),
                carve.take<uint32_t>(2 * size_t{n}),
                carve.take<uint32_t>(2 * size_t{n}),
                carve.take<uint32_t>(2 * size_t{n}),
                carve.take<uint8_t>(2 * size_t{n}),
                st};
  const Topology topo = faces_only(in);
  const size_t fg_bytes = face_grid_bytes(topo);
  uint8_t* fg_mem = carve.take<uint8_t>(fg_bytes);
  if (carve.short_) return Status::kWorkspaceTooSmall;

  Status s = run.merge_nodes();
  if (s != Status::kOk) return s;
  run.drop_segments();
  run.order_half_edges();
  s = run.find_cycles();
  if (s != Status::kOk) return s;
  FaceGrid fg;
  s = build_face_grid(topo, fg_mem, fg_bytes, &fg);
  if (s != Status::kOk) return s;
  run.name_faces(fg);

  out->n_segments = n;
  out->n_nodes = run.nodes;
  out->n_cycles = run.cycles;
  out->segments = seg;
  out->node = run.node;
  out->kept = run.kept;
  out->cycle = run.cycle;
  out->cycle_face = run.cycle_face;
  out->cycle_bounded = run.cycle_bounded;
  if (stats) *stats = st;
  return Status::kOk;
}

}  // namespace haloplot
