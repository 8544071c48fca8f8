#include "haloplot/surface/franklin.h"

#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/predicates.h"
#include "haloplot/geometry/wide.h"
#include "haloplot/solid/incidence.h"
#include "haloplot/sort/lower_bound.h"
#include "memory/carve.h"
#include "solid/cover.h"
#include "sort/in_place_sort.h"

namespace haloplot {
namespace {

constexpr uint32_t kNone = 0xffffffffu;
constexpr int64_t kOne = int64_t{1} << 32;

Edge3 edge_of(const SolidInput& in, uint32_t e) {
  return Edge3{in.vertices[in.edge_pairs[2 * e]], in.vertices[in.edge_pairs[2 * e + 1]]};
}

// Step 2: B = floor(c * min(sqrt(N), 1 / L)) cells a side, L the average projected length over
// the scene's extent; at most 4N + 64 cells so the grid stays O(N) bytes.
Grid make_grid(const SolidInput& in, const FranklinParams& p) {
  const Grid whole = grid_over(in.vertices, in.n_vertices, 1);
  const uint64_t extent = uint64_t(whole.cell);  // one cell: the longer side, plus one
  // Average length over a fixed-stride sample of at most 4096 edges (an estimate suffices).
  const uint32_t stride = in.n_edges > 4096 ? in.n_edges / 4096 : 1;
  uint64_t sum = 0, count = 0;
  for (uint32_t e = 0; e < in.n_edges; e += stride, ++count) {
    const Edge3 g = edge_of(in, e);
    const int64_t dx = g.b.x - g.a.x, dy = g.b.y - g.a.y;
    sum += isqrt_u64(uint64_t(dx * dx + dy * dy));
  }
  const uint64_t avg = count > 0 && sum >= count ? sum / count : 1;
  const uint64_t inv_l = extent / avg;
  const uint64_t root = isqrt_u64(in.n_edges);
  uint64_t b = (uint64_t{p.c_q8} * (root < inv_l ? root : inv_l)) >> 8;
  const uint64_t cap = isqrt_u64(4ull * in.n_edges + 64);
  if (b > cap) b = cap;
  return grid_over(in.vertices, in.n_vertices, static_cast<uint32_t>(b < 1 ? 1 : b));
}

Edge3 face_box(const SolidInput& in, uint32_t t) {
  const uint32_t* v = in.triangles[t].v;
  const Point3 a = in.vertices[v[0]], b = in.vertices[v[1]], c = in.vertices[v[2]];
  return Edge3{{min_i32(a.x, min_i32(b.x, c.x)), min_i32(a.y, min_i32(b.y, c.y)), 0},
               {max_i32(a.x, max_i32(b.x, c.x)), max_i32(a.y, max_i32(b.y, c.y)), 0}};
}

// A face's plane at an integer point, times its doubled area: the depth is value / area.
struct Plane {
  Point3 a, b, c;
  int64_t area;
  Wide value(int64_t x, int64_t y) const {
    const int64_t cb =
        int64_t{c.x - a.x} * (y - a.y) - int64_t{c.y - a.y} * (x - a.x);  // -cross(P-a, c-a)
    const int64_t cc = int64_t{b.x - a.x} * (y - a.y) - int64_t{b.y - a.y} * (x - a.x);
    return mul_i64(int64_t{a.z}, area) - mul_i64(int64_t{b.z - a.z}, cb) +
           mul_i64(int64_t{c.z - a.z}, cc);
  }
  // Sign of (this depth - other depth) at (x, y), exactly.
  int compare(const Plane& o, int64_t x, int64_t y) const {
    const int s = compare(mul_wide_i64(value(x, y), o.area), mul_wide_i64(o.value(x, y), area));
    return ((area > 0) == (o.area > 0)) ? s : -s;
  }
  // Inside or on the projection of the face (strictly: inside, not on a side).
  bool holds(int64_t x, int64_t y, bool strictly = false) const {
    auto side = [&](const Point3& u, const Point3& v) {
      const int64_t s = int64_t{v.x - u.x} * (y - u.y) - int64_t{v.y - u.y} * (x - u.x);
      return area > 0 ? s : -s;
    };
    const int64_t s0 = side(a, b), s1 = side(b, c), s2 = side(c, a);
    return strictly ? (s0 > 0 && s1 > 0 && s2 > 0) : (s0 >= 0 && s1 >= 0 && s2 >= 0);
  }
  static int compare(Wide l, Wide r) { return haloplot::compare(l, r); }
};

Plane plane_of(const SolidInput& in, uint32_t t) {
  const uint32_t* v = in.triangles[t].v;
  Plane p{in.vertices[v[0]], in.vertices[v[1]], in.vertices[v[2]], 0};
  p.area = projected_area2(p.a, p.b, p.c);
  return p;
}

struct Cell {
  int64_t x0, y0, x1, y1;  // closed extent for the corner tests
};

Cell cell_box(const Grid& g, uint32_t c) {
  const int64_t x0 = g.ox + int64_t(c % g.nx) * g.cell, y0 = g.oy + int64_t(c / g.nx) * g.cell;
  return Cell{x0, y0, x0 + g.cell, y0 + g.cell};
}

// Step 5b(i): F behind Fb at the cell's four corners, hence throughout the cell.
bool face_behind(const Plane& f, const Plane& fb, const Cell& c) {
  return f.compare(fb, c.x0, c.y0) < 0 && f.compare(fb, c.x1, c.y0) < 0 &&
         f.compare(fb, c.x0, c.y1) < 0 && f.compare(fb, c.x1, c.y1) < 0;
}

// Step 5b(ii): the face's projection holds all four corners, strictly inside. Strictly, because
// the cell's edges behind the face are then dropped from it (step 7), crossings on the cell's
// border included: that is safe only where the face hides a neighbourhood of the whole closed
// cell. A face side along the cell's border would otherwise lose the cut where an edge leaves
// the face there (found by fuzz_solid: a prism top's side on a grid line, corpus kept).
bool blocks(const Plane& f, const Cell& c) {
  return f.area != 0 && f.holds(c.x0, c.y0, true) && f.holds(c.x1, c.y0, true) &&
         f.holds(c.x0, c.y1, true) && f.holds(c.x1, c.y1, true);
}

// A segment's parameter range [lo, hi] (positions n / d, |n|, d < 2^21) clipped exactly to a
// closed cell, one axis at a time: p + t d within [c0, c1].
struct CellClip {
  int64_t lo_n = 0, lo_d = 1, hi_n = 1, hi_d = 1;
  bool axis(int64_t p, int64_t d, int64_t c0, int64_t c1) {
    if (d == 0) return p >= c0 && p <= c1;
    int64_t n0 = c0 - p, n1 = c1 - p;
    if (d < 0) {
      d = -d;
      const int64_t t = -n0;
      n0 = -n1;
      n1 = t;
    }
    if (n0 * lo_d > lo_n * d) lo_n = n0, lo_d = d;  // later entry
    if (n1 * hi_d < hi_n * d) hi_n = n1, hi_d = d;  // earlier exit
    return true;
  }
  // The part of segment ab in the cell; false when there is none.
  bool segment(const Point3& a, const Point3& b, const Cell& c) {
    return axis(a.x, int64_t{b.x} - a.x, c.x0, c.x1) && axis(a.y, int64_t{b.y} - a.y, c.y0, c.y1) &&
           lo_n * hi_d <= hi_n * lo_d;
  }
};

// Step 7a(i): the edge's part inside the cell (clipped exactly) is behind the blocking face at
// both of its ends, hence all along it.
bool edge_behind(const Edge3& e, const Plane& fb, const Cell& c) {
  CellClip k;
  if (!k.segment(e.a, e.b, c)) return false;  // no part in the cell
  // g(t) = (edge depth - plane depth) * area, linear in t: g(n/d) * d = ga (d - n) + gb n.
  const Wide ga = mul_i64(int64_t{e.a.z}, fb.area) - fb.value(e.a.x, e.a.y);
  const Wide gb = mul_i64(int64_t{e.b.z}, fb.area) - fb.value(e.b.x, e.b.y);
  auto sign_at = [&](int64_t n, int64_t d) {
    const Wide v = mul_wide_i64(ga, d - n) + mul_wide_i64(gb, n);
    const int s = v.negative() ? -1 : (v.is_zero() ? 0 : 1);
    return fb.area > 0 ? s : -s;
  };
  return sign_at(k.lo_n, k.lo_d) < 0 && sign_at(k.hi_n, k.hi_d) < 0;
}

// A polygon is the run of consecutive triangles with its id (the host splits each polygon into
// one such run). A flat polygon blocks a cell as a whole: Franklin's faces are polygons, and a
// square split along its diagonal would rarely cover a cell with either half alone.
uint32_t group_end(const SolidInput& in, uint32_t start) {
  uint32_t e = start + 1;
  while (e < in.n_triangles && in.triangles[e].polygon == in.triangles[start].polygon) ++e;
  return e;
}

// Every corner of the group's triangles on the first one's plane (exact: a 3-D orientation).
bool flat_group(const SolidInput& in, uint32_t start, uint32_t end) {
  const Plane f = plane_of(in, start);
  const int64_t ux = f.b.x - f.a.x, uy = f.b.y - f.a.y, uz = f.b.z - f.a.z;
  const int64_t vx = f.c.x - f.a.x, vy = f.c.y - f.a.y, vz = f.c.z - f.a.z;
  const int64_t nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  for (uint32_t t = start + 1; t < end; ++t)
    for (int k = 0; k < 3; ++k) {
      const Point3 q = in.vertices[in.triangles[t].v[k]];
      const Wide d = mul_i64(nx, q.x - f.a.x) + mul_i64(ny, q.y - f.a.y) + mul_i64(nz, q.z - f.a.z);
      if (!d.is_zero()) return false;
    }
  return true;
}

// Does a side of the group that no other triangle of it shares (the polygon's own boundary,
// not a diagonal) meet the closed cell?
bool boundary_meets_cell(const SolidInput& in, uint32_t start, uint32_t end, const Cell& c) {
  for (uint32_t t = start; t < end; ++t)
    for (int k = 0; k < 3; ++k) {
      const uint32_t u = in.triangles[t].v[k], w = in.triangles[t].v[(k + 1) % 3];
      bool shared = false;
      for (uint32_t o = start; o < end && !shared; ++o)
        for (int j = 0; j < 3 && o != t; ++j) {
          const uint32_t p = in.triangles[o].v[j], q = in.triangles[o].v[(j + 1) % 3];
          shared = shared || (p == w && q == u) || (p == u && q == w);
        }
      if (!shared && CellClip{}.segment(in.vertices[u], in.vertices[w], c)) return true;
    }
  return false;
}

// The group's projection covers the closed cell with a neighbourhood (see blocks()): each
// corner lies in one of its triangles, and no side of the polygon's own boundary meets the
// cell. For a convex polygon the corners alone would do; a concave one can hold all four
// corners while a notch or a slot narrower than the cell cuts into it, and what is seen
// through the slot must not be dropped (test solid_cases, "slot narrower than a cell"). A
// corner on the boundary is a side meeting the cell, so strictness comes with it.
bool group_blocks(const SolidInput& in, uint32_t start, uint32_t end, const Cell& c) {
  const int64_t xs[4] = {c.x0, c.x1, c.x0, c.x1}, ys[4] = {c.y0, c.y0, c.y1, c.y1};
  for (int k = 0; k < 4; ++k) {
    bool in_one = false;
    for (uint32_t t = start; t < end && !in_one; ++t) {
      const Plane f = plane_of(in, t);
      in_one = f.area != 0 && f.holds(xs[k], ys[k]);
    }
    if (!in_one) return false;
  }
  return !boundary_meets_cell(in, start, end, c);
}

struct Cut {
  uint32_t edge, t;
  uint32_t u, w;  // the other edge's vertices: the exact cut (see PieceEnd)
};

// Exact order of two cuts on one edge (the Q0.32 floors tie for points closer than 2^-32).
bool before(const SolidInput& in, uint32_t e, const PieceEnd& p, const PieceEnd& q) {
  const PiecePosition a = piece_end_position(in, e, p), b = piece_end_position(in, e, q);
  return compare(mul_i64(a.num, b.den), mul_i64(b.num, a.den)) < 0;
}

template <typename C>
void count_arrays(C& carve, const SolidInput& in, const Grid& g, uint64_t face_pairs,
                  uint64_t edge_pairs, uint32_t crossing_capacity) {
  carve.template take<SolidEdge>(in.n_edges);
  carve.template take<uint32_t>(g.cells());  // blocking face
  carve.template take<uint32_t>(size_t{g.cells()} + 1);
  carve.template take<uint32_t>(size_t(face_pairs));
  carve.template take<uint32_t>(size_t{g.cells()} + 1);
  carve.template take<uint32_t>(size_t(edge_pairs));
  carve.template take<uint8_t>(in.n_edges);  // edge kept somewhere
  carve.template take<Cut>(size_t{crossing_capacity} * 2);
}

void bounds(const SolidInput& in, const Grid& g, uint64_t* face_pairs, uint64_t* edge_pairs) {
  uint64_t f = 0, e = 0;
  for (uint32_t t = 0; t < in.n_triangles; ++t)
    for_each_cell(g, face_box(in, t), CellCover::kBoundingBox, 0, [&](uint32_t) { ++f; });
  for (uint32_t i = 0; i < in.n_edges; ++i)
    for_each_cell(g, edge_of(in, i), CellCover::kExact, 0, [&](uint32_t) { ++e; });
  *face_pairs = f;
  *edge_pairs = e;
}

Topology lite_topology(const SolidInput& in, SolidEdge* edges) {
  Topology t;
  t.vertices = in.vertices;
  t.n_vertices = in.n_vertices;
  t.edges = edges;
  t.n_edges = in.n_edges;
  t.n_drawn = in.n_edges;
  for (uint32_t e = 0; e < in.n_edges; ++e)
    edges[e] = SolidEdge{in.edge_pairs[2 * e],
                         in.edge_pairs[2 * e + 1],
                         {kNoFace, kNoFace},
                         EdgeClass::kLoose,
                         true,
                         false};
  return t;
}

// The triangle sides that are not drawn edges (the diagonals of split polygons): coverage
// changes across them too (the two triangles of a bent quad differ in depth, or fold), so they
// cut edges like any other side. Appended after the drawn edges, sorted and unique.
uint32_t append_diagonals(const SolidInput& in, uint32_t* pairs, uint64_t* keys) {
  auto key = [](uint32_t a, uint32_t b) {
    return a < b ? (uint64_t{a} << 32) | b : (uint64_t{b} << 32) | a;
  };
  for (uint32_t e = 0; e < 2 * in.n_edges; ++e) pairs[e] = in.edge_pairs[e];
  for (uint32_t e = 0; e < in.n_edges; ++e)
    keys[e] = key(in.edge_pairs[2 * e], in.edge_pairs[2 * e + 1]);
  heap_sort(keys, in.n_edges, [](uint64_t a, uint64_t b) { return a < b; });
  uint64_t* sides = keys + in.n_edges;
  uint32_t n = 0;
  for (uint32_t t = 0; t < in.n_triangles; ++t)
    for (int k = 0; k < 3; ++k) {
      const uint64_t s = key(in.triangles[t].v[k], in.triangles[t].v[(k + 1) % 3]);
      const uint32_t lo = lower_bound_index(0, in.n_edges, [&](uint32_t i) { return keys[i] < s; });
      if ((lo < in.n_edges && keys[lo] == s) || (s >> 32) == (s & 0xffffffffu)) continue;
      sides[n++] = s;
    }
  heap_sort(sides, n, [](uint64_t a, uint64_t b) { return a < b; });
  uint32_t out = in.n_edges;
  for (uint32_t i = 0; i < n; ++i) {
    if (i > 0 && sides[i] == sides[i - 1]) continue;
    pairs[2 * out] = uint32_t(sides[i] >> 32);
    pairs[2 * out + 1] = uint32_t(sides[i] & 0xffffffffu);
    ++out;
  }
  return out;
}

// One run's state, shared by its steps: the edges that cut (the drawn ones, then the
// diagonals), the grid, and the per-cell lists carved from the caller's buffer.
struct FranklinRun {
  SolidInput in;
  uint32_t n_drawn = 0;  // the drawn edges come first in `in` and are the only ones drawn
  Grid g;
  uint32_t cells = 0;
  uint32_t* blocking = nullptr;  // the first triangle of each cell's blocking polygon, or kNone
  uint32_t* face_first = nullptr;
  uint32_t* face_list = nullptr;
  uint32_t* edge_first = nullptr;
  uint32_t* edge_list = nullptr;
  uint8_t* edge_kept = nullptr;
  Cut* cuts = nullptr;
  uint64_t n_cuts = 0;
  FranklinStats st;

  void choose_blocking();
  void list_faces();
  void list_edges();
  void cut_pairs(uint32_t crossing_capacity);
  void sort_cuts();
  bool covers(uint32_t t, const CoverPoint& pt);
  bool hidden_at(const Edge3& ed, int64_t m);
  Status edge_pieces(uint32_t e, uint64_t k, const Incidences& inc, bool every_piece,
                     FranklinSink sink);
};

// Steps 5-6, first half: a face becomes a cell's Fb unless the current one is in front of it.
void FranklinRun::choose_blocking() {
  for (uint32_t c = 0; c < cells; ++c) blocking[c] = kNone;
  for (uint32_t t = 0; t < in.n_triangles;) {
    const uint32_t end = group_end(in, t);
    const bool flat = flat_group(in, t, end);
    for (uint32_t f = t; f < end; ++f) {
      // A flat polygon is tried whole, once, over the union of its triangles' boxes (each
      // triangle's box is visited; a cell already blocked by this polygon is skipped).
      const Plane pf = plane_of(in, f);
      if (pf.area == 0) continue;  // edge-on: covers no cell, hides nothing
      for_each_cell(g, face_box(in, f), CellCover::kBoundingBox, 0, [&](uint32_t c) {
        if (blocking[c] == t) return;
        const Cell box = cell_box(g, c);
        if (!(flat ? group_blocks(in, t, end, box) : blocks(pf, box))) return;
        if (blocking[c] != kNone && face_behind(pf, plane_of(in, blocking[c]), box)) return;
        blocking[c] = flat ? t : f;
      });
    }
    t = end;
  }
}

// Steps 5-6, second half: each cell lists its faces not behind its final Fb (counted, then
// filled), so a midpoint is tested against only the faces that can hide it there.
void FranklinRun::list_faces() {
  for (uint32_t c = 0; c <= cells; ++c) face_first[c] = 0;
  for (int pass = 0; pass < 2; ++pass) {
    for (uint32_t t = 0; t < in.n_triangles; ++t) {
      const Plane f = plane_of(in, t);
      if (f.area == 0) continue;
      bool kept = false;
      for_each_cell(g, face_box(in, t), CellCover::kBoundingBox, 0, [&](uint32_t c) {
        if (blocking[c] != kNone && blocking[c] <= t && t < group_end(in, blocking[c]) &&
            (blocking[c] == t || flat_group(in, blocking[c], group_end(in, blocking[c])))) {
          kept = true;  // the blocking polygon itself is kept apart from the list
          return;
        }
        if (blocking[c] != kNone && face_behind(f, plane_of(in, blocking[c]), cell_box(g, c))) {
          if (pass == 0) ++st.face_cells_culled;
          return;
        }
        kept = true;
        if (pass == 0)
          ++face_first[c + 1];
        else
          face_list[face_first[c]++] = t;
      });
      if (pass == 0 && !kept) ++st.faces_deleted;
    }
    if (pass == 0)
      for (uint32_t c = 0; c < cells; ++c) face_first[c + 1] += face_first[c];
  }
  for (uint32_t c = cells; c > 0; --c) face_first[c] = face_first[c - 1];
  face_first[0] = 0;
  st.face_cells = face_first[cells];
  for (uint32_t c = 0; c < cells; ++c) st.blocking_cells += blocking[c] != kNone;
}

// Step 7: edges into cells, unless behind the blocking face there: a cell's pairs are then
// tested only among the edges that can show in it.
void FranklinRun::list_edges() {
  for (uint32_t c = 0; c <= cells; ++c) edge_first[c] = 0;
  for (uint32_t e = 0; e < in.n_edges; ++e) edge_kept[e] = 0;
  for (int pass = 0; pass < 2; ++pass) {
    for (uint32_t e = 0; e < in.n_edges; ++e) {
      const Edge3 ed = edge_of(in, e);
      for_each_cell(g, ed, CellCover::kExact, 0, [&](uint32_t c) {
        if (blocking[c] != kNone && edge_behind(ed, plane_of(in, blocking[c]), cell_box(g, c))) {
          if (pass == 0) ++st.edge_cells_culled;
          return;
        }
        edge_kept[e] = 1;
        if (pass == 0)
          ++edge_first[c + 1];
        else
          edge_list[edge_first[c]++] = e;
      });
    }
    if (pass == 0)
      for (uint32_t c = 0; c < cells; ++c) edge_first[c + 1] += edge_first[c];
  }
  for (uint32_t c = cells; c > 0; --c) edge_first[c] = edge_first[c - 1];
  edge_first[0] = 0;
  st.edge_cells = edge_first[cells];
  for (uint32_t e = 0; e < n_drawn; ++e) st.edges_deleted += edge_kept[e] == 0;
}

// Step 8: pairs in each cell; a crossing counts in the cell that holds it, so a pair sharing
// several cells is cut once; both edges are cut. Cuts past the capacity are counted, not kept.
void FranklinRun::cut_pairs(uint32_t crossing_capacity) {
  for (uint32_t c = 0; c < cells; ++c) {
    const Cell box = cell_box(g, c);
    for (uint32_t i = edge_first[c]; i < edge_first[c + 1]; ++i)
      for (uint32_t j = i + 1; j < edge_first[c + 1]; ++j) {
        const Edge3 p1 = edge_of(in, edge_list[i]), p2 = edge_of(in, edge_list[j]);
        ++st.pairs_tested;
        const CrossingTest x = test_crossing(p1, p2);
        if (!x.crosses) continue;
        const int64_t px = int64_t{p1.b.x - p1.a.x} * x.tn, py = int64_t{p1.b.y - p1.a.y} * x.tn;
        if (!((box.x0 - p1.a.x) * x.den <= px && px < (box.x1 - p1.a.x) * x.den &&
              (box.y0 - p1.a.y) * x.den <= py && py < (box.y1 - p1.a.y) * x.den))
          continue;
        ++st.crossings;
        if (n_cuts + 2 <= uint64_t{crossing_capacity} * 2) {
          const uint32_t* pi = in.edge_pairs + 2 * edge_list[i];
          const uint32_t* pj = in.edge_pairs + 2 * edge_list[j];
          cuts[n_cuts] = Cut{edge_list[i], frac_q32_small(x.tn, x.den), pj[0], pj[1]};
          cuts[n_cuts + 1] = Cut{edge_list[j], frac_q32_small(x.un, x.den), pi[0], pi[1]};
        }
        n_cuts += 2;
      }
  }
}

// Each edge's cuts together and in exact order along it, for step 9's walk.
void FranklinRun::sort_cuts() {
  const SolidInput& edges = in;
  heap_sort(cuts, size_t(n_cuts), [&](const Cut& a, const Cut& b) {
    if (a.edge != b.edge) return a.edge < b.edge;
    if (a.t != b.t) return a.t < b.t;
    return before(edges, a.edge, PieceEnd{a.u, a.w}, PieceEnd{b.u, b.w});
  });
}

bool FranklinRun::covers(uint32_t t, const CoverPoint& pt) {
  const uint32_t* v = in.triangles[t].v;
  const Point3 &a = in.vertices[v[0]], &b = in.vertices[v[1]], &cc = in.vertices[v[2]];
  ++st.face_tests;
  return (projected_area2(a, b, cc) >= 0 ? cover_halves(a, b, cc, pt)
                                         : cover_halves(a, cc, b, pt)) != 0;
}

// Step 9's test: a piece is hidden when a face of its midpoint's cell covers the midpoint;
// the cell's blocking polygon is kept apart from its list, so it is asked first.
bool FranklinRun::hidden_at(const Edge3& ed, int64_t m) {
  const CoverPoint pt = edge_point(ed, m);
  const uint32_t c = g.cell_of(cell_x(pt), cell_y(pt));
  ++st.midpoint_tests;
  bool hidden = false;
  if (blocking[c] != kNone) {
    const uint32_t b0 = blocking[c];
    const uint32_t b1 = flat_group(in, b0, group_end(in, b0)) ? group_end(in, b0) : b0 + 1;
    for (uint32_t t = b0; !hidden && t < b1; ++t) hidden = covers(t, pt);
  }
  for (uint32_t i = face_first[c]; !hidden && i < face_first[c + 1]; ++i)
    hidden = covers(face_list[i], pt);
  return hidden;
}

// Step 9 for one edge: its pieces between cuts, runs of equal visibility joined (unless
// every piece is wanted) and handed to the sink one behind, when the next one differs.
struct EdgePieces {
  FranklinRun& run;
  uint32_t e;
  Edge3 ed;
  bool every_piece;
  FranklinSink sink;
  FranklinPiece pending{{e, 0, 0}, false, {}, {}};
  bool have = false;
  bool last_hidden = false;

  Status piece(int64_t t0, int64_t t1, PieceEnd from, PieceEnd to) {
    if (t1 < t0 || (t1 == t0 && !every_piece)) return Status::kOk;
    ++run.st.pieces;
    bool hidden = true;
    if (!run.edge_kept[e]) {
      hidden = true;
    } else if (t1 - t0 < 2) {
      hidden = last_hidden;
    } else {
      hidden = run.hidden_at(ed, t0 + (t1 - t0) / 2);
    }
    last_hidden = hidden;
    if (have && !every_piece && pending.hidden == hidden && pending.t1 == t0) {
      pending.t1 = t1;
      pending.to = to;
      return Status::kOk;
    }
    Status r = Status::kOk;
    if (have) r = sink.emit(sink.context, pending);
    pending = FranklinPiece{{e, t0, t1}, hidden, from, to};
    have = true;
    return r;
  }
};

// Walks edge e's cuts (from cuts[k]) and the vertices on it in order along the edge: visibility
// can change at either (solid/incidence.h).
Status FranklinRun::edge_pieces(uint32_t e, uint64_t k, const Incidences& inc, bool every_piece,
                                FranklinSink sink) {
  EdgePieces ps{*this, e, edge_of(in, e), every_piece, sink};
  uint64_t kc = k;
  uint32_t ki = inc.edge_first[e];
  Status s = Status::kOk;
  int64_t at = 0;
  PieceEnd at_end{in.edge_pairs[2 * e], PieceEnd::kNoVertex};
  while (s == Status::kOk && ((kc < n_cuts && cuts[kc].edge == e) || ki < inc.edge_first[e + 1])) {
    int64_t t;
    PieceEnd end;
    bool take_cut = ki >= inc.edge_first[e + 1];
    if (!take_cut && kc < n_cuts && cuts[kc].edge == e) {
      const Incidence& v = inc.by_edge[ki];
      take_cut = cuts[kc].t < v.t ||
                 (cuts[kc].t == v.t && !before(in, e, PieceEnd{v.vertex, PieceEnd::kNoVertex},
                                               PieceEnd{cuts[kc].u, cuts[kc].w}));
    }
    if (take_cut) {
      end = PieceEnd{cuts[kc].u, cuts[kc].w};
      t = cuts[kc++].t;
    } else {
      end = PieceEnd{inc.by_edge[ki].vertex, PieceEnd::kNoVertex};
      t = inc.by_edge[ki++].t;
    }
    s = ps.piece(at, t, at_end, end);
    at = t;
    at_end = end;
  }
  if (s == Status::kOk)
    s = ps.piece(at, kOne, at_end, PieceEnd{in.edge_pairs[2 * e + 1], PieceEnd::kNoVertex});
  if (s == Status::kOk && ps.have) s = sink.emit(sink.context, ps.pending);
  return s;
}

// Every vertex in range, every index in its array, and room for the diagonals' indices.
Status check_input(const SolidInput& drawn) {
  for (uint32_t v = 0; v < drawn.n_vertices; ++v)
    if (!in_range(drawn.vertices[v])) return Status::kCoordinateOutOfRange;
  for (uint32_t e = 0; e < 2 * drawn.n_edges; ++e)
    if (drawn.edge_pairs[e] >= drawn.n_vertices) return Status::kBadParameter;
  for (uint32_t t = 0; t < drawn.n_triangles; ++t)
    for (int k = 0; k < 3; ++k)
      if (drawn.triangles[t].v[k] >= drawn.n_vertices) return Status::kBadParameter;
  if (uint64_t{drawn.n_edges} + 3ull * drawn.n_triangles > 0x3fffffffu)
    return Status::kTooManyEdges;
  return Status::kOk;
}

}  // namespace

PiecePosition piece_end_position(const SolidInput& in, uint32_t e, const PieceEnd& at) {
  const Edge3 ed = edge_of(in, e);
  if (at.w == PieceEnd::kNoVertex) {
    // A vertex on the edge: its projection is a + (b - a) * num / den along the longer axis.
    const Point3 v = in.vertices[at.u];
    const int64_t dx = ed.b.x - ed.a.x, dy = ed.b.y - ed.a.y;
    const bool by_x = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
    int64_t n = by_x ? v.x - ed.a.x : v.y - ed.a.y, d = by_x ? dx : dy;
    if (d < 0) n = -n, d = -d;
    return PiecePosition{n, d};
  }
  const CrossingTest x = test_crossing(ed, Edge3{in.vertices[at.u], in.vertices[at.w]});
  return PiecePosition{x.tn, x.den};
}

size_t franklin_bytes(const SolidInput& drawn, const FranklinParams& p, uint32_t crossing_capacity,
                      uint32_t incidence_capacity) {
  // Sized as if every triangle side were a diagonal (the bound; a run uses what it finds).
  const size_t most = size_t{drawn.n_edges} + 3 * size_t{drawn.n_triangles};
  ByteCounter c;
  c.take<uint32_t>(2 * most);
  c.take<uint64_t>(most);
  const Grid g = make_grid(drawn, p);
  uint64_t fp = 0, ep = 0;
  bounds(drawn, g, &fp, &ep);
  for (uint32_t t = 0; t < drawn.n_triangles; ++t)
    for (int k = 0; k < 3; ++k) {
      const Edge3 side{drawn.vertices[drawn.triangles[t].v[k]],
                       drawn.vertices[drawn.triangles[t].v[(k + 1) % 3]]};
      for_each_cell(g, side, CellCover::kExact, 0, [&](uint32_t) { ++ep; });
    }
  SolidInput in = drawn;
  in.n_edges = static_cast<uint32_t>(most);
  count_arrays(c, in, g, fp, ep, crossing_capacity);
  Topology t;
  t.n_vertices = in.n_vertices;
  t.n_edges = in.n_edges;
  return c.total + incidence_bytes(t, incidence_capacity) + 24;
}

Status franklin_hidden_lines(const SolidInput& drawn, const FranklinParams& p,
                             uint32_t crossing_capacity, uint32_t incidence_capacity, void* buffer,
                             size_t bytes, FranklinSink sink, FranklinStats* stats) {
  const Status checked = check_input(drawn);
  if (checked != Status::kOk) return checked;
  FranklinRun run;
  Carver carve(buffer, bytes);
  const size_t most = size_t{drawn.n_edges} + 3 * size_t{drawn.n_triangles};
  uint32_t* all_pairs = carve.take<uint32_t>(2 * most);
  uint64_t* keys = carve.take<uint64_t>(most);
  if (carve.short_) return Status::kWorkspaceTooSmall;
  // The edges that cut: the drawn ones, then the diagonals (which make no pieces).
  run.in = drawn;
  run.in.edge_pairs = all_pairs;
  run.in.n_edges = append_diagonals(drawn, all_pairs, keys);
  run.n_drawn = drawn.n_edges;
  run.g = make_grid(drawn, p);
  uint64_t face_pairs = 0, edge_pairs = 0;
  bounds(run.in, run.g, &face_pairs, &edge_pairs);
  if (face_pairs > 0xffffffffu || edge_pairs > 0xffffffffu) return Status::kCellPairOverflow;
  const uint32_t cells = run.cells = run.g.cells();
  run.st.b = run.g.nx > run.g.ny ? run.g.nx : run.g.ny;
  run.st.cells = cells;
  SolidEdge* lite = carve.take<SolidEdge>(run.in.n_edges);
  run.blocking = carve.take<uint32_t>(cells);
  run.face_first = carve.take<uint32_t>(size_t{cells} + 1);
  run.face_list = carve.take<uint32_t>(size_t(face_pairs));
  run.edge_first = carve.take<uint32_t>(size_t{cells} + 1);
  run.edge_list = carve.take<uint32_t>(size_t(edge_pairs));
  run.edge_kept = carve.take<uint8_t>(run.in.n_edges);
  run.cuts = carve.take<Cut>(size_t{crossing_capacity} * 2);
  if (carve.short_) return Status::kWorkspaceTooSmall;
  Topology topo = lite_topology(run.in, lite);
  const size_t inc_bytes = incidence_bytes(topo, incidence_capacity);
  uint8_t* inc_mem = carve.take<uint8_t>(inc_bytes);
  if (carve.short_) return Status::kWorkspaceTooSmall;

  run.choose_blocking();
  run.list_faces();
  run.list_edges();
  run.cut_pairs(crossing_capacity);
  if (run.st.crossings > crossing_capacity) {
    if (stats) *stats = run.st;
    return Status::kCrossingCapacity;
  }
  run.sort_cuts();

  // The vertices lying on edges: visibility can change there too (solid/incidence.h).
  Incidences inc;
  uint32_t needed = 0;
  Status s = find_incidences(topo, incidence_capacity, inc_mem, inc_bytes, &inc, &needed);
  run.st.incidences = needed;
  if (s != Status::kOk) {
    if (stats) *stats = run.st;
    return s;
  }

  // Step 9: pieces and their midpoints, for the drawn edges only.
  uint64_t k = 0;
  for (uint32_t e = 0; e < drawn.n_edges; ++e) {
    const Edge3 ed = edge_of(run.in, e);
    while (k < run.n_cuts && run.cuts[k].edge < e) ++k;
    if (ed.b.x == ed.a.x && ed.b.y == ed.a.y) continue;  // a point on paper: no pieces
    s = run.edge_pieces(e, k, inc, p.every_piece, sink);
    if (s != Status::kOk) break;
  }
  if (stats) *stats = run.st;
  return s;
}

}  // namespace haloplot
