#include "haloplot/solid/fallback.h"

#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/predicates.h"
#include "haloplot/geometry/rows.h"
#include "haloplot/geometry/wide.h"
#include "haloplot/solid/classify.h"
#include "haloplot/solid/face_grid.h"
#include "haloplot/solid/qi.h"
#include "memory/carve.h"
#include "solid/cover.h"
#include "solid/pierce.h"
#include "sort/in_place_sort.h"

namespace haloplot {
namespace {

constexpr int64_t kOne = int64_t{1} << 32;

enum Vc : uint8_t { kVcUnknown = 0, kVcVisible = 1, kVcHidden = 2, kVcUnusable = 3 };

// Does the outline pass ask about edge e: a contour as paper shows it (classify.h's paper_h3),
// or an edge with one face? Counting both sides of every face, any edge whose faces lie on one
// side of it on paper.
bool outline_candidate(const Topology& topo, uint32_t e, bool any_facing) {
  const SolidEdge& se = topo.edges[e];
  if (any_facing) return paper_contour(topo, e);
  return paper_h3(topo, e) || ((se.face[0] == kNoFace) != (se.face[1] == kNoFace));
}

// Does the run draw edge e: every drawn edge, and the diagonals that are contours (H3 on a
// closed solid; counting both sides, any whose faces lie on one side of it on paper).
bool draws_edge(const Topology& topo, uint32_t e, bool any_facing) {
  if (e < topo.n_drawn) return true;
  if (any_facing) return paper_contour(topo, e);
  return topo.edges[e].cls == EdgeClass::kH3 || edge_on_contour(topo, e);
}

// The outline pass's table: for each drawn candidate edge, the sorted positions along it where
// it passes in front of another edge (CUT records those on the edge behind).
template <typename C>
void count_outline(C& c, const Topology& topo, size_t fronts) {
  c.template take<uint32_t>(size_t{topo.n_edges} + 1);
  c.template take<uint32_t>(fronts);
}

// Is the crossing record's front edge one the outline pass cuts at it?
bool front_candidate(const Topology& topo, const Crossing& r, bool any_facing) {
  const uint32_t f = r.front_edge();
  return !r.near_miss() && draws_edge(topo, f, any_facing) &&
         outline_candidate(topo, f, any_facing);
}

size_t count_fronts(const Topology& topo, const CutSet& cs, bool any_facing) {
  size_t n = 0;
  for (uint32_t i = 0; i < cs.n_crossings; ++i)
    if (front_candidate(topo, cs.crossings[i], any_facing)) ++n;
  return n;
}

// Kira's condition at position m of edge e, away from its face(s): no face at all there.
bool outside_empty(const Topology& topo, const FaceGrid& fg, const SolidEdge& se, int64_t m,
                   int32_t dir_x, int32_t dir_y) {
  const Point3 a = topo.vertices[se.v0], b = topo.vertices[se.v1];
  CoverPoint p;
  p.d = kOne;
  p.x = int64_t{a.x} * kOne + int64_t{b.x - a.x} * m;
  p.y = int64_t{a.y} * kOne + int64_t{b.y - a.y} * m;
  p.dir_x = dir_x;
  p.dir_y = dir_y;
  const int32_t cx = cell_x(p), cy = cell_y(p);
  for (const uint32_t* k = fg.begin(cx, cy); k != fg.end(cx, cy); ++k) {
    const uint32_t* v = topo.triangles[*k].v;
    if (projection_cover_halves(topo.vertices[v[0]], topo.vertices[v[1]], topo.vertices[v[2]], p) !=
        0)
      return false;
  }
  return true;
}

// The direction away from edge e's face(s) in projection, or (0, 0) when the face is edge-on.
// (A contour's two faces lie on the same side of it on paper; the first that is not edge-on
// says which.)
void outward(const Topology& topo, const SolidEdge& se, int32_t* dx, int32_t* dy) {
  const Point3 a = topo.vertices[se.v0], b = topo.vertices[se.v1];
  const int64_t ex = int64_t{b.x} - a.x, ey = int64_t{b.y} - a.y;
  int64_t side = 0;
  for (int k = 0; k < 2 && side == 0; ++k) {
    if (se.face[k] == kNoFace) continue;
    const uint32_t* v = topo.triangles[se.face[k]].v;
    const uint32_t c =
        v[0] != se.v0 && v[0] != se.v1 ? v[0] : (v[1] != se.v0 && v[1] != se.v1 ? v[1] : v[2]);
    const Point3 p = topo.vertices[c];
    side = ex * (int64_t{p.y} - a.y) - ey * (int64_t{p.x} - a.x);
  }
  // The face on the left of a -> b: outside is to the right, (ey, -ex); and the other way.
  *dx = side == 0 ? 0 : int32_t(side > 0 ? ey : -ey);
  *dy = side == 0 ? 0 : int32_t(side > 0 ? -ex : ex);
}

// The outline runs of one edge, from its visible pieces in order: each piece is cut wherever
// the edge crosses another (either way) or meets a vertex, each part asked the condition, and
// the parts that pass are joined into runs.
struct OutlineRuns {
  const Topology& topo;
  const FaceGrid& fg;
  const CutSet& cs;
  const Incidences& inc;
  const uint32_t* front_first;
  const uint32_t* front_t;
  FallbackSink sink;
  bool any_facing = false;
  uint32_t e = 0;
  int32_t dir_x = 0, dir_y = 0;
  bool on = false, have = false, last_pass = false;
  int64_t run_t0 = 0, run_t1 = 0;
  uint64_t tests = 0;

  void start(uint32_t edge) {
    e = edge;
    have = last_pass = false;
    on = outline_candidate(topo, e, any_facing);
    if (on) outward(topo, topo.edges[e], &dir_x, &dir_y);
    on = on && (dir_x != 0 || dir_y != 0);
  }
  Status finish() {
    Status s = Status::kOk;
    if (have && sink.outline != nullptr)
      s = sink.outline(sink.context, FallbackPiece{{e, run_t0, run_t1}, 0, false, true});
    have = false;
    return s;
  }
  // A band's window [lo, hi) of the edge (solid/fallback.h): a part too short to test that a
  // border cut off a longer one is asked just beyond the border, inside that longer part (the
  // band holds the faces of the row beyond each border: band/solid_band.cpp).
  bool window = false;
  int64_t lo = 0, hi = kOne;
  Status part(int64_t u0, int64_t u1) {
    if (u1 <= u0) return Status::kOk;
    int64_t m = u0 + (u1 - u0) / 2;
    if (u1 - u0 < 2)
      m = window && u0 == lo && lo > 0 ? lo - 1 : (window && u1 == hi && hi < kOne ? hi : -1);
    const bool pass =
        m < 0 ? last_pass : (++tests, outside_empty(topo, fg, topo.edges[e], m, dir_x, dir_y));
    last_pass = pass;
    if (pass && have && run_t1 == u0) {
      run_t1 = u1;
      return Status::kOk;
    }
    const Status s = finish();
    if (pass) {
      run_t0 = u0;
      run_t1 = u1;
      have = true;
    }
    return s;
  }
  // A visible piece [t0, t1) of the edge.
  Status visible(int64_t t0, int64_t t1) {
    if (!on) return Status::kOk;
    const Crossing* cx = cs.begin(e);
    const uint32_t ncx = cs.count(e);
    const Incidence* ix = inc.by_edge + inc.edge_first[e];
    const uint32_t nix = inc.edge_first[e + 1] - inc.edge_first[e];
    const uint32_t* fx = front_t + front_first[e];
    const uint32_t nfx = front_first[e + 1] - front_first[e];
    uint32_t i = 0, j = 0, k = 0;
    int64_t at = t0;
    for (;;) {  // the next cut of the three sorted lists
      int64_t t = kOne + 1;
      if (i < ncx && cx[i].t < t) t = cx[i].t;
      if (j < nix && ix[j].t < t) t = ix[j].t;
      if (k < nfx && fx[k] < t) t = fx[k];
      if (t > kOne) break;
      if (i < ncx && cx[i].t == t) ++i;
      if (j < nix && ix[j].t == t) ++j;
      if (k < nfx && fx[k] == t) ++k;
      if (t <= at) continue;
      if (t >= t1) break;
      const Status s = part(at, t);
      if (!ok(s)) return s;
      at = t;
    }
    return part(at, t1);
  }
};

// The outline pass's table, filled: for each candidate edge, where it passes in front of
// another (count, place, sort), so its visible pieces are cut there too.
void place_fronts(const Topology& topo, const CutSet& cutset, bool any_facing,
                  uint32_t* front_first, uint32_t* front_t) {
  for (uint32_t e = 0; e <= topo.n_edges; ++e) front_first[e] = 0;
  for (uint32_t i = 0; i < cutset.n_crossings; ++i) {
    const Crossing& r = cutset.crossings[i];
    if (front_candidate(topo, r, any_facing)) ++front_first[r.front_edge() + 1];
  }
  for (uint32_t e = 0; e < topo.n_edges; ++e) front_first[e + 1] += front_first[e];
  for (uint32_t e = 0; e < topo.n_edges; ++e)  // every record, by the edge behind
    for (const Crossing* r = cutset.begin(e); r != cutset.begin(e) + cutset.count(e); ++r) {
      if (!front_candidate(topo, *r, any_facing)) continue;
      const uint32_t f = r->front_edge();
      const CrossingTest x = test_crossing(topo.edge3(f), topo.edge3(e));
      front_t[front_first[f]++] = frac_q32_small(x.tn, x.den);
    }
  for (uint32_t e = topo.n_edges; e > 0; --e) front_first[e] = front_first[e - 1];
  front_first[0] = 0;
  for (uint32_t e = 0; e < topo.n_edges; ++e)
    sort_in_place(front_t + front_first[e], front_first[e + 1] - front_first[e],
                  [](uint32_t a, uint32_t b) { return a < b; });
}

// The V.C. table starts unknown except where it must never be used: a vertex where an edge
// or another vertex meets it, a peculiar vertex, or one on a hidden fold (H2).
void start_vc(const Topology& topo, const uint8_t* front, const Incidences& inc, bool use_vc,
              uint8_t* vc, FallbackStats& st) {
  for (uint32_t v = 0; v < topo.n_vertices; ++v) {
    const bool singular =
        use_vc && (inc.same_next[v] != v || inc.vertex_first[v] != inc.vertex_first[v + 1]);
    vc[v] = (use_vc && !singular) ? kVcUnknown : kVcUnusable;
  }
  if (!use_vc) return;
  // Contour vectors run with the front face on their right (Kira): count starts and ends.
  for (uint32_t v = 0; v < topo.n_vertices; ++v) {
    uint32_t starts = 0, ends = 0;
    bool h2 = false;
    for (uint32_t k = topo.vertex_edge_first[v]; k < topo.vertex_edge_first[v + 1]; ++k) {
      const SolidEdge& e = topo.edges[topo.vertex_edges[k]];
      if (e.cls == EdgeClass::kH2) h2 = true;
      if (e.cls != EdgeClass::kH3) continue;
      // Front face on the left of v0 -> v1 means the vector runs v1 -> v0.
      const bool from_v1 = front_face_side(topo, front, topo.vertex_edges[k]) > 0;
      const uint32_t start = from_v1 ? e.v1 : e.v0;
      ++(start == v ? starts : ends);
    }
    if (ends >= 2) ++st.contours_end_twice;
    if (starts >= 2) ++st.contours_start_twice;
    if (ends >= 2 || starts >= 2 || h2) vc[v] = kVcUnusable;
  }
}

// What one piece was found to be: its QI (kQiUnknown when a class or the V.C. decided),
// hidden or not, and whether a test point decided it.
struct Verdict {
  int32_t q;
  bool hidden, tested;
};

// One run's shared state, and the edge in hand: its pieces are cut, judged, merged while
// equal, and handed to the sink one behind (and their visible parts to the outline pass).
struct FallbackRun {
  const Topology& topo;
  const uint8_t* front;
  const FaceGrid& fg;
  const CutSet& cutset;
  const Incidences& inc;
  const FallbackParams& params;
  FallbackSink sink;
  uint8_t* vc;
  OutlineRuns& runs;
  FallbackStats& st;
  bool use_front;               // only front faces count (else either side of every face)
  const uint8_t* pierce_front;  // the front table when only front faces count, else null
  // The edge in hand.
  uint32_t e = 0;
  Point3 a{}, b{};
  int64_t lo = 0, hi = kOne;
  bool by_class = false, vc_edge = false;
  FallbackPiece pending{{0, 0, 0}, 0, false, true};
  bool have = false;
  Status status = Status::kOk;
  int32_t last_q = 0;
  bool last_hidden = false;

  // Halves of cover at p, from the faces of its cell.
  int32_t cover_count(const CoverPoint& p) {
    const int32_t cx = cell_x(p), cy = cell_y(p);
    int32_t q = 0;
    for (const uint32_t* k = fg.begin(cx, cy); k != fg.end(cx, cy); ++k) {
      const uint32_t t = *k;
      const uint32_t* v = topo.triangles[t].v;
      const Point3 &fa = topo.vertices[v[0]], &fb = topo.vertices[v[1]], &fc = topo.vertices[v[2]];
      ++st.face_tests;
      if (use_front) {
        if (front[t]) q += cover_halves(fa, fb, fc, p);
      } else {
        q += projected_area2(fa, fb, fc) >= 0 ? cover_halves(fa, fb, fc, p)
                                              : cover_halves(fa, fc, fb, p);
      }
    }
    return q;
  }

  // A piece is decided by its edge's class, by the piece before (too short to test), by the
  // V.C. of the vertex it ends at, or by a test at its middle, cheapest first.
  Verdict judge(int64_t t0, int64_t t1) {
    if (by_class) {
      ++st.class_saved;
      return Verdict{kQiUnknown, true, true};
    }
    if (t1 - t0 < 2) {
      ++st.short_pieces;
      return Verdict{last_q, last_hidden, false};
    }
    const uint32_t end_v = t0 == 0 ? topo.edges[e].v0 : (t1 == kOne ? topo.edges[e].v1 : kNoFace);
    if (vc_edge && end_v != kNoFace && (vc[end_v] == kVcVisible || vc[end_v] == kVcHidden)) {
      ++st.vc_saved;
      return Verdict{kQiUnknown, vc[end_v] == kVcHidden, true};
    }
    const int32_t q = cover_count(edge_point(Edge3{a, b}, t0 + (t1 - t0) / 2));
    ++st.tests;
    const bool hidden = q != 0;
    if (vc_edge && end_v != kNoFace && vc[end_v] == kVcUnknown)
      vc[end_v] = hidden ? kVcHidden : kVcVisible;
    return Verdict{q, hidden, true};
  }

  // The pending piece to the sink, and its outline runs.
  void flush() {
    status = sink.emit(sink.context, pending);
    if (ok(status) && params.outline && !pending.hidden)
      status = runs.visible(pending.t0, pending.t1);
  }

  // The piece [t0, t1), clipped to the part of the edge this run draws.
  void piece(int64_t t0, int64_t t1) {
    if (t0 < lo) t0 = lo;
    if (t1 > hi) t1 = hi;
    if (t1 <= t0 || status != Status::kOk) return;
    ++st.pieces;
    const Verdict v = judge(t0, t1);
    last_q = v.q;
    last_hidden = v.hidden;
    if (have && !params.window && pending.q == v.q && pending.hidden == v.hidden &&
        pending.t1 == t0) {
      pending.t1 = t1;
      return;
    }
    if (have) flush();
    pending = FallbackPiece{{e, t0, t1}, v.q, v.hidden, v.tested};
    have = true;
  }

  // Cut points: every crossing behind another edge, every vertex the edge passes through,
  // every face it passes through (solid/pierce.h; found one at a time, in order, so an edge
  // that pierces nothing costs one look along its cells). An edge hidden by class needs none.
  void cut_pieces() {
    const Crossing* cx = cutset.begin(e);
    const uint32_t ncx = cutset.count(e);
    const Incidence* ix = inc.by_edge + inc.edge_first[e];
    const uint32_t nix = inc.edge_first[e + 1] - inc.edge_first[e];
    int64_t at = 0;
    uint32_t i = 0, j = 0;
    int64_t pierce =
        by_class ? kNoPierce : next_pierce(topo, fg, pierce_front, e, -1, &st.pierce_tests);
    while (i < ncx || j < nix || pierce != kNoPierce) {
      int64_t t = pierce;
      if (i < ncx && cx[i].t <= t) t = cx[i].t;
      if (j < nix && ix[j].t <= t) t = ix[j].t;
      if (i < ncx && cx[i].t == t) {
        ++i;
      } else if (j < nix && ix[j].t == t) {
        ++j;
      } else {
        ++st.pierces;
        pierce = next_pierce(topo, fg, pierce_front, e, t, &st.pierce_tests);
      }
      // A cut at floor(t * 2^32): the true point lies in [t, t + 1). The middle of [at, t) is
      // at least at + 1 and at most t - 1, so strictly between the true cut points.
      piece(at, t);
      at = t;
    }
    piece(at, kOne);
  }

  // Drawn edge `edge`: its pieces to the sink, its outline runs to the outline pass.
  Status edge(uint32_t edge_index) {
    e = edge_index;
    const SolidEdge& se = topo.edges[e];
    a = topo.vertices[se.v0];
    b = topo.vertices[se.v1];
    if (b.x == a.x && b.y == a.y) return Status::kOk;  // a point on paper: nothing to draw
    // The part of the edge this run draws: all of it, or the band's rows.
    lo = 0;
    hi = kOne;
    if (params.window) {
      const RowWindow w = row_window(Edge3{a, b}, params.row_lo, params.row_hi);
      lo = w.lo;
      hi = w.hi;
      if (lo >= hi) return Status::kOk;
    }
    by_class = params.use_classes && (se.cls == EdgeClass::kH1 || se.cls == EdgeClass::kH2);
    vc_edge = params.use_vc && (se.cls == EdgeClass::kH3 || se.cls == EdgeClass::kH4);
    pending = FallbackPiece{{e, 0, 0}, 0, false, true};
    have = false;
    status = Status::kOk;
    if (params.outline) {
      runs.start(e);
      runs.window = params.window;
      runs.lo = lo;
      runs.hi = hi;
    }
    last_q = 0;
    last_hidden = false;
    cut_pieces();
    if (have && status == Status::kOk) flush();
    if (status == Status::kOk && params.outline) status = runs.finish();
    return status;
  }
};

}  // namespace

size_t fallback_bytes(const Topology& topo, bool shared_grid) {
  ByteCounter c;
  if (!shared_grid) c.take<uint8_t>(face_grid_bytes(topo));
  c.take<uint8_t>(topo.n_vertices);
  return c.total + 8;
}

size_t fallback_outline_bytes(const Topology& topo, const CutSet& cutset, bool any_facing) {
  ByteCounter c;
  count_outline(c, topo, count_fronts(topo, cutset, any_facing));
  return c.total;
}

Status run_fallback(const Topology& topo, const uint8_t* front, const CutSet& cutset,
                    const Incidences& inc, const FallbackParams& params, void* buffer, size_t bytes,
                    FallbackSink sink, FallbackStats* stats, const FaceGrid* grid) {
  if (cutset.n_edges != topo.n_edges) return Status::kBadParameter;
  if ((params.use_classes || params.use_vc || !params.any_facing) && front == nullptr)
    return Status::kBadParameter;
  Carver carve(buffer, bytes);
  const size_t grid_bytes = grid != nullptr ? 0 : face_grid_bytes(topo);
  uint8_t* grid_buffer = carve.take<uint8_t>(grid_bytes);
  uint8_t* vc = carve.take<uint8_t>(topo.n_vertices);
  if (carve.short_) return Status::kWorkspaceTooSmall;
  uint32_t* front_first = nullptr;
  uint32_t* front_t = nullptr;
  if (params.outline) {
    front_first = carve.take<uint32_t>(size_t{topo.n_edges} + 1);
    front_t = carve.take<uint32_t>(count_fronts(topo, cutset, params.any_facing));
    if (carve.short_) return Status::kWorkspaceTooSmall;
  }
  FaceGrid built;
  if (grid == nullptr) {
    const Status gs = build_face_grid(topo, grid_buffer, grid_bytes, &built);
    if (gs != Status::kOk) return gs;
  }
  const FaceGrid& fg = grid != nullptr ? *grid : built;
  if (params.outline) place_fronts(topo, cutset, params.any_facing, front_first, front_t);
  FallbackStats st;
  st.grid_cells = fg.grid.cells();
  st.cell_faces = fg.pairs;
  start_vc(topo, front, inc, params.use_vc, vc, st);

  OutlineRuns runs{topo, fg, cutset, inc, front_first, front_t, sink, params.any_facing};
  const bool use_front = !params.any_facing;
  const uint8_t* pierce_front = use_front ? front : nullptr;
  FallbackRun run{topo, front, fg,   cutset, inc,       params,
                  sink, vc,    runs, st,     use_front, pierce_front};
  for (uint32_t e = 0; e < topo.n_edges; ++e) {
    if (!draws_edge(topo, e, params.any_facing)) continue;
    const Status s = run.edge(e);
    if (s != Status::kOk) return s;
  }
  st.outline_tests = runs.tests;
  if (stats != nullptr) *stats = st;
  return Status::kOk;
}

}  // namespace haloplot
