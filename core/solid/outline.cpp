#include "haloplot/solid/outline.h"

#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/predicates.h"
#include "haloplot/solid/classify.h"
#include "haloplot/solid/face_grid.h"
#include "haloplot/sort/lower_bound.h"
#include "memory/carve.h"
#include "solid/cover.h"
#include "sort/in_place_sort.h"

namespace haloplot {
namespace {

constexpr uint32_t kNone = 0xffffffffu;
constexpr int64_t kOne = int64_t{1} << 32;

struct Node {
  uint32_t t;        // position along the contour edge, Q0.32 from v0
  uint32_t partner;  // the other contour edge (index among contour edges)
  uint32_t partner_node;
};

// The contours the outlines run along, as paper shows them: H3 on a closed solid (classify.h's
// paper_h3); on any other mesh, whose QI counts both sides of every face (solid/qi.h), every
// edge whose faces lie on one side of it on paper: a fold either way, an open surface's rim, a
// fin.
bool outline_contour(const Topology& topo, uint32_t e) {
  return qi_two_sided(topo) ? paper_contour(topo, e) : paper_h3(topo, e);
}

// The side of contour e its (front) faces lie on: +1 left of v0 -> v1, -1 right.
int contour_side(const Topology& topo, uint32_t e) {
  if (qi_two_sided(topo)) return paper_jump(topo, e) > 0 ? 1 : -1;
  int side = 1;
  paper_h3(topo, e, &side);
  return side;
}

enum SegState : uint8_t { kOpen = 0, kInWalk = 1, kOutline = 2, kNotOutline = 3 };

// Nodes on one side: incidences (another vertex inside a contour edge) cut it too, so the
// pieces of an overlap are asked separately. Counted with the crossings' two sides.
size_t count_contour_touches(const Topology& topo, const Incidences& inc) {
  size_t n = 0;
  for (uint32_t e = 0; e < topo.n_edges; ++e)
    if (outline_contour(topo, e)) n += inc.edge_first[e + 1] - inc.edge_first[e];
  return n;
}

size_t count_contour_crossings(const Topology& topo, const CutSet& cs) {
  size_t n = 0;
  for (uint32_t e = 0; e < topo.n_edges; ++e) {
    if (!outline_contour(topo, e)) continue;
    for (const Crossing* c = cs.begin(e); c != cs.begin(e) + cs.count(e); ++c)
      if (!c->near_miss() && outline_contour(topo, c->front_edge())) ++n;
  }
  return n;
}

uint32_t count_contours(const Topology& topo) {
  uint32_t n = 0;
  for (uint32_t e = 0; e < topo.n_edges; ++e) n += outline_contour(topo, e) ? 1 : 0;
  return n;
}

template <typename C>
void count_arrays(C& c, const Topology& topo, uint32_t n_h3, size_t k) {
  c.template take<uint32_t>(topo.n_edges);  // contour index of each edge
  c.template take<uint32_t>(n_h3);          // edge of each contour
  c.template take<uint8_t>(n_h3);           // vector runs v0 -> v1
  c.template take<uint32_t>(n_h3 + 1);      // node_first
  c.template take<Node>(2 * k);
  c.template take<uint8_t>(n_h3 + 2 * k);     // segment state
  c.template take<uint8_t>(n_h3 + 2 * k);     // segment visible
  c.template take<uint32_t>(n_h3 + 2 * k);    // the walk
  c.template take<uint8_t>(topo.n_vertices);  // vector ends and starts per vertex (A/B)
  c.template take<uint8_t>(face_grid_bytes(topo));
}

struct Ctx {
  const Topology& topo;
  const uint8_t* front;
  uint32_t* index;
  uint32_t* edge;
  uint8_t* forward;
  uint32_t* node_first;
  Node* nodes;
  uint8_t* state;
  uint8_t* visible;
  uint8_t* ends;  // per vertex: low nibble vectors ending, high nibble vectors starting (saturated)
  OutlineStats* st;
  const Incidences* inc;
  FaceGrid grid;

  // A contour edge touched by another vertex (on it, or on one of its ends, or sharing an end's
  // point): collinear overlaps and T-junctions that CUT does not report, so a trace through it
  // cannot be trusted.
  bool singular(uint32_t h) const {
    const SolidEdge& e = topo.edges[edge[h]];
    if (inc->edge_first[edge[h] + 1] != inc->edge_first[edge[h]]) return true;
    const uint32_t corners[2] = {e.v0, e.v1};
    for (uint32_t v : corners)
      if (inc->same_next[v] != v || inc->vertex_first[v + 1] != inc->vertex_first[v]) return true;
    return false;
  }

  uint32_t segs(uint32_t h) const { return node_first[h + 1] - node_first[h] + 1; }
  uint32_t seg_id(uint32_t h, uint32_t k) const { return node_first[h] + h + k; }
  int64_t t_lo(uint32_t h, uint32_t k) const { return k == 0 ? 0 : nodes[node_first[h] + k - 1].t; }
  int64_t t_hi(uint32_t h, uint32_t k) const {
    return k + 1 == segs(h) ? kOne : nodes[node_first[h] + k].t;
  }
  uint32_t start_vertex(uint32_t h) const {
    return forward[h] ? topo.edges[edge[h]].v0 : topo.edges[edge[h]].v1;
  }
  uint32_t end_vertex(uint32_t h) const {
    return forward[h] ? topo.edges[edge[h]].v1 : topo.edges[edge[h]].v0;
  }
  void direction(uint32_t h, int64_t* dx, int64_t* dy) const {
    const Point3 a = topo.vertices[topo.edges[edge[h]].v0],
                 b = topo.vertices[topo.edges[edge[h]].v1];
    *dx = forward[h] ? b.x - a.x : a.x - b.x;
    *dy = forward[h] ? b.y - a.y : a.y - b.y;
  }
};

// Kira's condition: just outside the segment (to the left of its vector, away from its front
// face) no face of the picture lies at all.
bool outside_is_empty(const Ctx& c, uint32_t h, uint32_t k) {
  ++c.st->condition_tests;
  const int64_t t0 = c.t_lo(h, k), t1 = c.t_hi(h, k);
  if (t1 - t0 < 2) return false;  // no position strictly inside: not drawable anyway
  const int64_t m = t0 + (t1 - t0) / 2;
  const SolidEdge& e = c.topo.edges[c.edge[h]];
  const Point3 a = c.topo.vertices[e.v0], b = c.topo.vertices[e.v1];
  int64_t dx, dy;
  c.direction(h, &dx, &dy);
  CoverPoint p;
  p.d = kOne;
  p.x = int64_t{a.x} * kOne + int64_t{b.x - a.x} * m;
  p.y = int64_t{a.y} * kOne + int64_t{b.y - a.y} * m;
  p.dir_x = static_cast<int32_t>(-dy);
  p.dir_y = static_cast<int32_t>(dx);
  // Only faces whose bounding box holds the point can hold it: its grid cell's.
  const int32_t cx = static_cast<int32_t>(p.x >> 32), cy = static_cast<int32_t>(p.y >> 32);
  for (const uint32_t* t = c.grid.begin(cx, cy); t != c.grid.end(cx, cy); ++t) {
    const uint32_t* v = c.topo.triangles[*t].v;
    if (projection_cover_halves(c.topo.vertices[v[0]], c.topo.vertices[v[1]], c.topo.vertices[v[2]],
                                p) != 0)
      return false;
  }
  return true;
}

// Is direction d1 before d2, counter-clockwise from b (angles in (0, 2pi])?
bool ccw_before(int64_t bx, int64_t by, int64_t d1x, int64_t d1y, int64_t d2x, int64_t d2y) {
  auto half = [&](int64_t x, int64_t y) {
    const int64_t cr = cross(bx, by, x, y);
    return (cr > 0 || (cr == 0 && dot(bx, by, x, y) < 0)) ? 0 : 1;
  };
  const int h1 = half(d1x, d1y), h2 = half(d2x, d2y);
  if (h1 != h2) return h1 < h2;
  return cross(d1x, d1y, d2x, d2y) > 0;
}

// The segment after (h, k) along the vectors, or kNone. *checked: the arrival was at a type A
// vertex and the segment passed the condition there (it must, or the circuit is abandoned).
uint32_t next_segment(const Ctx& c, uint32_t h, uint32_t k, bool* abandon, uint32_t* nh,
                      uint32_t* nk) {
  const uint32_t n = c.segs(h);
  const bool at_node = c.forward[h] ? k + 1 < n : k > 0;
  if (at_node) {
    const Node& x = c.nodes[c.node_first[h] + (c.forward[h] ? k : k - 1)];
    if (x.partner == kNone) return kNone;  // a touch, not a crossing (singular edges only)
    *nh = x.partner;
    *nk = c.forward[x.partner] ? x.partner_node + 1 : x.partner_node;
    return c.seg_id(*nh, *nk);
  }
  const uint32_t v = c.end_vertex(h);
  if ((c.ends[v] & 0x0f) >= 2 && !outside_is_empty(c, h, k)) {
    *abandon = true;  // type A: the arriving segment is not an outline
    return kNone;
  }
  int64_t dx, dy;
  c.direction(h, &dx, &dy);
  uint32_t best = kNone;
  int64_t bx = 0, by = 0;
  for (uint32_t i = c.topo.vertex_edge_first[v]; i < c.topo.vertex_edge_first[v + 1]; ++i) {
    const uint32_t g = c.index[c.topo.vertex_edges[i]];
    if (g == kNone || g == h || c.start_vertex(g) != v) continue;
    int64_t gx, gy;
    c.direction(g, &gx, &gy);
    // Type B: keep the most counterclockwise turn, seen from the way back (-d).
    if (best == kNone || ccw_before(-dx, -dy, bx, by, gx, gy)) {
      best = g;
      bx = gx;
      by = gy;
    }
  }
  if (best == kNone) return kNone;
  *nh = best;
  *nk = c.forward[best] ? 0 : c.segs(best) - 1;
  return c.seg_id(*nh, *nk);
}

struct VisibleCursor {
  const Ctx* c;
  uint32_t h;
  uint32_t k;
};

Status mark_visible(void* context, const QiPiece& piece) {
  VisibleCursor* v = static_cast<VisibleCursor*>(context);
  const Ctx& c = *v->c;
  while (v->k < c.segs(v->h)) {
    const int64_t m = c.t_lo(v->h, v->k) + (c.t_hi(v->h, v->k) - c.t_lo(v->h, v->k)) / 2;
    if (m >= piece.t1) break;
    if (m >= piece.t0) c.visible[c.seg_id(v->h, v->k)] = piece.q == 0;
    ++v->k;
  }
  return Status::kOk;
}

// Contour edges, their vectors (front face on the right), and the vertex types: how many
// vectors end and start at each vertex says where a trace must ask or choose (types A, B).
void orient_contours(Ctx& c) {
  const Topology& topo = c.topo;
  uint32_t h = 0;
  for (uint32_t v = 0; v < topo.n_vertices; ++v) c.ends[v] = 0;
  for (uint32_t e = 0; e < topo.n_edges; ++e) {
    c.index[e] = kNone;
    if (!outline_contour(topo, e)) continue;
    c.index[e] = h;
    c.edge[h] = e;
    c.forward[h] = contour_side(topo, e) < 0;  // front face (the faces) on the right
    const uint32_t s = c.start_vertex(h), t = c.end_vertex(h);
    if ((c.ends[t] & 0x0f) < 15) ++c.ends[t];
    if ((c.ends[s] >> 4) < 15) c.ends[s] = static_cast<uint8_t>(c.ends[s] + 0x10);
    ++h;
  }
  for (uint32_t v = 0; v < topo.n_vertices; ++v) {
    if ((c.ends[v] & 0x0f) >= 2) ++c.st->contours_end_twice;
    if ((c.ends[v] >> 4) >= 2) ++c.st->contours_start_twice;
  }
}

// Crossing nodes on both edges of every contour pair, sorted along each edge and linked to
// their partner, so a trace can turn onto the other contour at a crossing.
void place_nodes(Ctx& c, const CutSet& cutset, const Incidences& inc, uint32_t n_h3) {
  const Topology& topo = c.topo;
  for (uint32_t i = 0; i <= n_h3; ++i) c.node_first[i] = 0;
  for (uint32_t e = 0; e < topo.n_edges; ++e) {
    if (c.index[e] == kNone) continue;
    for (const Crossing* x = cutset.begin(e); x != cutset.begin(e) + cutset.count(e); ++x) {
      if (x->near_miss() || c.index[x->front_edge()] == kNone) continue;
      ++c.node_first[c.index[e] + 1];
      ++c.node_first[c.index[x->front_edge()] + 1];
    }
    c.node_first[c.index[e] + 1] += inc.edge_first[e + 1] - inc.edge_first[e];
  }
  for (uint32_t i = 0; i < n_h3; ++i) c.node_first[i + 1] += c.node_first[i];
  for (uint32_t e = 0; e < topo.n_edges; ++e) {
    if (c.index[e] == kNone) continue;
    for (const Crossing* x = cutset.begin(e); x != cutset.begin(e) + cutset.count(e); ++x) {
      const uint32_t g = x->front_edge();
      if (x->near_miss() || c.index[g] == kNone) continue;
      const Edge3 pe = topo.edge3(e), pg = topo.edge3(g);
      const CrossingTest ct = test_crossing(pg, pe);  // along g: tn / den
      const uint32_t tg = frac_q32_small(ct.tn, ct.den);
      c.nodes[c.node_first[c.index[e]]++] = Node{x->t, c.index[g], kNone};
      c.nodes[c.node_first[c.index[g]]++] = Node{tg, c.index[e], kNone};
    }
    for (uint32_t i = inc.edge_first[e]; i < inc.edge_first[e + 1]; ++i)
      c.nodes[c.node_first[c.index[e]]++] = Node{inc.by_edge[i].t, kNone, kNone};
  }
  for (uint32_t i = n_h3; i > 0; --i) c.node_first[i] = c.node_first[i - 1];
  c.node_first[0] = 0;
  for (uint32_t i = 0; i < n_h3; ++i)
    sort_in_place(c.nodes + c.node_first[i], c.node_first[i + 1] - c.node_first[i],
                  [](const Node& a, const Node& b) {
                    return a.t < b.t || (a.t == b.t && a.partner < b.partner);
                  });
  for (uint32_t i = 0; i < n_h3; ++i)
    for (uint32_t n = c.node_first[i]; n < c.node_first[i + 1]; ++n) {
      const uint32_t p = c.nodes[n].partner;
      if (p == kNone) continue;
      for (uint32_t m = c.node_first[p]; m < c.node_first[p + 1]; ++m)
        if (c.nodes[m].partner == i) c.nodes[n].partner_node = m - c.node_first[p];
    }
}

// A failed trace's segments, each asked the condition on its own (no circuit vouches for them).
void ask_one_by_one(Ctx& c, const uint32_t* walk, uint32_t n, uint32_t n_h3) {
  for (uint32_t i = 0; i < n; ++i) {
    // The contour edge holding segment walk[i]: the last h with seg_id(h, 0) <= it.
    const uint32_t hh =
        lower_bound_index(1, n_h3, [&](uint32_t h) { return c.seg_id(h, 0) <= walk[i]; }) - 1;
    const uint32_t kk = walk[i] - c.seg_id(hh, 0);
    ++c.st->one_by_one;
    c.state[walk[i]] = c.visible[walk[i]] && outside_is_empty(c, hh, kk) ? kOutline : kNotOutline;
  }
}

// One trace from visible segment (h0, k0): along the vectors until it closes, so that one test
// of the condition settles the whole circuit; otherwise its segments are asked one by one.
void trace_from(Ctx& c, uint32_t* walk, uint32_t n_h3, uint32_t h0, uint32_t k0) {
  const uint32_t s0 = c.seg_id(h0, k0);
  uint32_t n = 0, ch = h0, ck = k0;
  bool closed = false, abandon = false, invisible = false;
  walk[n++] = s0;
  c.state[s0] = kInWalk;
  for (;;) {
    if (c.singular(ch)) break;  // asked one by one below
    uint32_t nh = 0, nk = 0;
    const uint32_t s = next_segment(c, ch, ck, &abandon, &nh, &nk);
    if (s == s0) {
      closed = true;
      break;
    }
    if (s == kNone || c.state[s] != kOpen) break;  // dead end, or a loop missing its start
    walk[n++] = s;
    c.state[s] = kInWalk;
    invisible = invisible || !c.visible[s];
    ch = nh;
    ck = nk;
  }
  if (!closed) return ask_one_by_one(c, walk, n, n_h3);
  ++c.st->circuits;
  if (!invisible) ++c.st->potential;
  const bool outline = !invisible && outside_is_empty(c, h0, k0);
  c.st->outlines += outline;
  const uint8_t verdict = outline ? kOutline : kNotOutline;
  for (uint32_t i = 0; i < n; ++i) c.state[walk[i]] = verdict;
}

// Every open segment settled: an invisible one is no outline, a visible one starts a trace.
void trace_circuits(Ctx& c, uint32_t* walk, uint32_t n_h3) {
  for (uint32_t h0 = 0; h0 < n_h3; ++h0)
    for (uint32_t k0 = 0; k0 < c.segs(h0); ++k0) {
      const uint32_t s0 = c.seg_id(h0, k0);
      if (c.state[s0] != kOpen) continue;
      if (!c.visible[s0]) {
        c.state[s0] = kNotOutline;
        continue;
      }
      trace_from(c, walk, n_h3, h0, k0);
    }
}

// The outline segments to the sink, merged along each edge.
Status emit_outlines(const Ctx& c, uint32_t n_h3, OutlineSink sink) {
  for (uint32_t i = 0; i < n_h3; ++i) {
    OutlineSegment pending{c.edge[i], 0, 0};
    bool have = false;
    for (uint32_t kk = 0; kk < c.segs(i); ++kk) {
      if (c.state[c.seg_id(i, kk)] != kOutline) continue;
      ++c.st->outline_segments;
      if (have && pending.t1 == c.t_lo(i, kk)) {
        pending.t1 = c.t_hi(i, kk);
        continue;
      }
      if (have) {
        const Status s = sink.emit(sink.context, pending);
        if (s != Status::kOk) return s;
      }
      pending = OutlineSegment{c.edge[i], c.t_lo(i, kk), c.t_hi(i, kk)};
      have = true;
    }
    if (have) {
      const Status s = sink.emit(sink.context, pending);
      if (s != Status::kOk) return s;
    }
  }
  return Status::kOk;
}

}  // namespace

size_t outline_bytes(const Topology& topo, const CutSet& cutset, const Incidences& inc) {
  ByteCounter c;
  count_arrays(c, topo, count_contours(topo),
               count_contour_crossings(topo, cutset) + (count_contour_touches(topo, inc) + 1) / 2);
  return c.total + 8;
}

Status find_outlines(const Topology& topo, const uint8_t* front, const CutSet& cutset,
                     const Incidences& inc, const QiState& qi, void* buffer, size_t bytes,
                     OutlineSink sink, OutlineStats* stats) {
  if (cutset.n_edges != topo.n_edges) return Status::kBadParameter;
  const uint32_t n_h3 = count_contours(topo);
  const size_t crossings = count_contour_crossings(topo, cutset);
  const size_t k = crossings + (count_contour_touches(topo, inc) + 1) / 2;  // 2k nodes at most
  Carver carve(buffer, bytes);
  OutlineStats st;
  Ctx c{topo,
        front,
        carve.take<uint32_t>(topo.n_edges),
        carve.take<uint32_t>(n_h3),
        carve.take<uint8_t>(n_h3),
        carve.take<uint32_t>(n_h3 + 1),
        carve.take<Node>(2 * k),
        carve.take<uint8_t>(n_h3 + 2 * k),
        carve.take<uint8_t>(n_h3 + 2 * k),
        nullptr,
        &st,
        &inc,
        FaceGrid{}};
  uint32_t* walk = carve.take<uint32_t>(n_h3 + 2 * k);
  c.ends = carve.take<uint8_t>(topo.n_vertices);
  const size_t grid_bytes = face_grid_bytes(topo);
  uint8_t* grid_buffer = carve.take<uint8_t>(grid_bytes);
  if (carve.short_) return Status::kWorkspaceTooSmall;
  const Status gs = build_face_grid(topo, grid_buffer, grid_bytes, &c.grid);
  if (gs != Status::kOk) return gs;
  st.contour_edges = n_h3;
  st.contour_crossings = static_cast<uint32_t>(crossings);

  orient_contours(c);
  place_nodes(c, cutset, inc, n_h3);
  st.unit_segments = n_h3 + c.node_first[n_h3];

  // Which unit segments are visible, from the QI.
  for (uint32_t i = 0; i < n_h3 + 2 * k; ++i) {
    c.state[i] = kOpen;
    c.visible[i] = 0;
  }
  for (uint32_t i = 0; i < n_h3; ++i) {
    VisibleCursor cur{&c, i, 0};
    const Status s =
        emit_edge_qi_pieces(topo, front, cutset, inc, qi, c.edge[i], QiSink{&mark_visible, &cur});
    if (s != Status::kOk) return s;
  }

  trace_circuits(c, walk, n_h3);
  const Status s = emit_outlines(c, n_h3, sink);
  if (s != Status::kOk) return s;
  if (stats != nullptr) *stats = st;
  return Status::kOk;
}

}  // namespace haloplot
