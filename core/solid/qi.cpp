#include "haloplot/solid/qi.h"

#include "haloplot/solid/classify.h"
#include "haloplot/solid/face_grid.h"
#include "memory/carve.h"
#include "solid/build_parts.h"
#include "solid/cover.h"
#include "solid/pierce.h"

namespace haloplot {
namespace {

struct Ctx {
  const Topology& topo;
  const uint8_t* front;
  const CutSet& cs;
  const Incidences& inc;
  bool two_sided;  // every face hides, seen from either side (qi.h)
  // Where edges pass through faces (the mesh pierces itself: qi.h), the faces to ask; null
  // when the mesh needs none.
  const FaceGrid* pierce_grid = nullptr;
  // Per vertex, what its star's cover is without asking its faces (plain_star); null: ask.
  const uint8_t* plain = nullptr;
};

// Vertex v's star seen from v's own point, which the walk asks about each edge of v: plain when
// star_cover is 0 there whatever it asks. Only for a mesh whose faces hide from the front alone
// (closed and consistently oriented: each side of a face has exactly two faces, one traversing
// it each way, so v's star is closed fans), in two cases:
// - kNoFrontFace: no face of the star faces the viewer; none counts.
// - kOneFan: every face faces it (doubled area > 0) and the fans wind once around v in all.
//   Their corners at v then split the turn into sectors between distinct rays, one to each
//   neighbour, and a nudge along one of those rays (along a side of a face) lies strictly
//   outside every face but the two along it, which hold it in their plane (star_cover).
// The winding: how many faces' half-open sectors (side out of v, side into v] hold the ray of
// one side, r; each fan holds it as many times as it winds round, and there is at least one fan.
constexpr uint8_t kAskFaces = 0, kNoFrontFace = 1, kOneFan = 2;

uint8_t plain_star(const Topology& topo, const uint8_t* front, uint32_t v) {
  const uint32_t k0 = topo.vertex_face_first[v], k1 = topo.vertex_face_first[v + 1];
  uint32_t fronts = 0;
  for (uint32_t k = k0; k < k1; ++k) fronts += front[topo.vertex_faces[k]] != 0;
  if (fronts == 0) return kNoFrontFace;
  if (fronts != k1 - k0) return kAskFaces;  // a contour passes through v
  const Point3 a = topo.vertices[v];
  int64_t rx = 0, ry = 0;
  uint32_t winding = 0;
  for (uint32_t k = k0; k < k1; ++k) {
    const uint32_t* tv = topo.triangles[topo.vertex_faces[k]].v;
    const uint32_t i1 = tv[0] == v ? tv[1] : (tv[1] == v ? tv[2] : tv[0]);
    const uint32_t i2 = tv[0] == v ? tv[2] : (tv[1] == v ? tv[0] : tv[1]);
    // 21-bit differences: the products stay below 2^43 (corner_cover_halves' budget).
    const int64_t ux = topo.vertices[i1].x - a.x, uy = topo.vertices[i1].y - a.y;
    const int64_t wx = topo.vertices[i2].x - a.x, wy = topo.vertices[i2].y - a.y;
    if (ux * wy - uy * wx <= 0) return kAskFaces;
    if (k == k0) rx = ux, ry = uy;
    winding += ux * ry - uy * rx > 0 && rx * wy - ry * wx >= 0;
  }
  return winding == 1 ? kOneFan : kAskFaces;
}

int face_cover(const Ctx& c, uint32_t t, const CoverPoint& p) {
  const uint32_t* v = c.topo.triangles[t].v;
  const Point3 &a = c.topo.vertices[v[0]], &b = c.topo.vertices[v[1]], &d = c.topo.vertices[v[2]];
  if (!c.two_sided) return c.front[t] ? cover_halves(a, b, d, p) : 0;
  // A face seen from behind covers as the same face wound the other way round.
  return projected_area2(a, b, d) >= 0 ? cover_halves(a, b, d, p) : cover_halves(a, d, b, p);
}

int faces_of_vertex(const Ctx& c, uint32_t v, const CoverPoint& p) {
  int sum = 0;
  for (uint32_t k = c.topo.vertex_face_first[v]; k < c.topo.vertex_face_first[v + 1]; ++k)
    sum += face_cover(c, c.topo.vertex_faces[k], p);
  return sum;
}

// faces_of_vertex(c, v, p) where p is v's own point at v's depth nudged toward vertex `to`
// (vertex_toward(v, to)): each face asked with v as its first corner, by corner_cover_halves.
// A face with `to` as a corner holds the nudge in its plane: level and rising as steeply, it
// never covers (its rise times the area is dir_z times the area, exactly), so it is not asked.
// along_face: the edge from v to `to` is a side of a face.
int star_cover(const Ctx& c, uint32_t v, uint32_t to, bool along_face, const CoverPoint& p) {
  if (c.plain != nullptr && (c.plain[v] == kNoFrontFace || (c.plain[v] == kOneFan && along_face)))
    return 0;
  const Point3& a = c.topo.vertices[v];
  int sum = 0;
  for (uint32_t k = c.topo.vertex_face_first[v]; k < c.topo.vertex_face_first[v + 1]; ++k) {
    const uint32_t t = c.topo.vertex_faces[k];
    if (!c.two_sided && !c.front[t]) continue;
    const uint32_t* tv = c.topo.triangles[t].v;
    // The other two corners in the triangle's turn, v first (a turn keeps the doubled area).
    const uint32_t i1 = tv[0] == v ? tv[1] : (tv[1] == v ? tv[2] : tv[0]);
    const uint32_t i2 = tv[0] == v ? tv[2] : (tv[1] == v ? tv[0] : tv[1]);
    if (i1 == to || i2 == to) continue;
    const Point3 &b = c.topo.vertices[i1], &d = c.topo.vertices[i2];
    // A face seen from behind covers as the same face wound the other way round (face_cover).
    const bool flip = c.two_sided && projected_area2(a, b, d) < 0;
    sum += flip ? corner_cover_halves(a, d, b, p) : corner_cover_halves(a, b, d, p);
  }
  return sum;
}

// The cover of p by the faces of edge g: its two, or every face of a non-manifold edge (all
// of v0's star that hold v1) when every face counts.
int faces_of_edge(const Ctx& c, uint32_t g, const CoverPoint& p) {
  const SolidEdge& e = c.topo.edges[g];
  int sum = 0;
  if (c.two_sided && !e.regular && e.face[0] != kNoFace && e.face[1] != kNoFace) {
    for (uint32_t k = c.topo.vertex_face_first[e.v0]; k < c.topo.vertex_face_first[e.v0 + 1]; ++k) {
      const uint32_t* t = c.topo.triangles[c.topo.vertex_faces[k]].v;
      if (t[0] == e.v1 || t[1] == e.v1 || t[2] == e.v1)
        sum += face_cover(c, c.topo.vertex_faces[k], p);
    }
    return sum;
  }
  for (int s = 0; s < 2; ++s)
    if (e.face[s] != kNoFace) sum += face_cover(c, e.face[s], p);
  return sum;
}

// The faces whose boundary passes through v's point, asked with p's nudge, by rule.
struct Local {
  int star = 0, same = 0, through = 0;
  int total() const { return star + same + through; }
};

// The local cover at vertex v's own point, nudged toward vertex `to`: p is
// vertex_toward(v, to), as every caller asks.
Local local_cover(const Ctx& c, uint32_t v, uint32_t to, bool along_face, const CoverPoint& p) {
  Local l;
  l.star = star_cover(c, v, to, along_face, p);
  for (uint32_t u = c.inc.same_next[v]; u != v; u = c.inc.same_next[u])
    l.same += faces_of_vertex(c, u, p);
  for (uint32_t k = c.inc.vertex_first[v]; k < c.inc.vertex_first[v + 1]; ++k)
    l.through += faces_of_edge(c, c.inc.by_edge[c.inc.by_vertex[k]].edge, p);
  return l;
}

void count_local(const Local& l, QiStats* st) {
  if (st == nullptr) return;
  if (l.star != 0) ++st->wedge;
  if (l.same != 0) ++st->quarter;
  if (l.through != 0) ++st->delta;
}

// The change of QI where the walk along e (direction dx, dy, dz) crosses behind edge g.
// The walk crosses g from its right to its left on paper when s > 0.
int crossing_change(const Ctx& c, uint32_t g, int64_t dx, int64_t dy) {
  const SolidEdge& ge = c.topo.edges[g];
  if (!c.two_sided && !is_fold(ge.cls)) return 0;
  // Two-sided: each face of g on the side the walk enters starts covering it, each on the side
  // it leaves stops; faces on both sides (a surface's interior) cancel.
  const int jump = c.two_sided ? paper_jump(c.topo, g) : front_face_side(c.topo, c.front, g);
  if (jump == 0) return 0;
  const Point3 a = c.topo.vertices[ge.v0], b = c.topo.vertices[ge.v1];
  const int64_t s = int64_t{b.x - a.x} * dy - int64_t{b.y - a.y} * dx;
  return 2 * (s > 0 ? jump : -jump);
}

// The change of QI where the walk passes through the point of vertex w (incidence r), with
// the walk's direction `sign` (+1 from v0, -1 from v1).
int passage_change(const Ctx& c, const Incidence& r, int sign) {
  const SolidEdge& e = c.topo.edges[r.edge];
  const Point3 a = c.topo.vertices[e.v0], b = c.topo.vertices[e.v1];
  const Point3 w = c.topo.vertices[r.vertex];
  CoverPoint after;
  after.x = w.x;
  after.y = w.y;
  after.d = 1;
  after.zn = Wide::from_i64(int64_t{a.z} * r.den + int64_t{b.z - a.z} * r.num);
  after.zd = r.den;
  after.dir_x = sign * (b.x - a.x);
  after.dir_y = sign * (b.y - a.y);
  after.dir_z = sign * (b.z - a.z);
  CoverPoint before = after;
  before.dir_x = -after.dir_x;
  before.dir_y = -after.dir_y;
  before.dir_z = -after.dir_z;
  return faces_of_vertex(c, r.vertex, after) - faces_of_vertex(c, r.vertex, before);
}

// Walks edge e from v0 (forward) or from v1, starting with QI q; calls piece(t0, t1, q) for
// each stretch when forward. Returns the QI on arrival.
// Where the edge passes through faces (solid/pierce.h), for a mesh that pierces itself: the
// next such place after `after`, walking from v0. An event that cannot be counted exactly is
// a conflict (the fallback then decides the picture).
PierceEvent next_pierce_of(const Ctx& c, uint32_t e, int64_t after, QiStats* st) {
  if (c.pierce_grid == nullptr) return PierceEvent{kNoPierce, 0, true};
  uint64_t tests = 0;
  const PierceEvent ev =
      next_pierce_event(c.topo, *c.pierce_grid, c.two_sided ? nullptr : c.front, e, after, &tests);
  if (st != nullptr) {
    st->pierce_tests += tests;
    if (ev.t != kNoPierce) ++st->pierces;
    if (!ev.exact) ++st->conflicts;
  }
  return ev;
}

// The cover change of every pierce along the edge, from v0 to v1.
int all_pierces(const Ctx& c, uint32_t e, QiStats* st) {
  int sum = 0;
  for (PierceEvent ev = next_pierce_of(c, e, -1, st); ev.t != kNoPierce;
       ev = next_pierce_of(c, e, ev.t, st))
    sum += ev.change;
  return sum;
}

// Walks edge e from v0 (forward) or from v1, starting with QI q; calls piece(t0, t1, q) for
// each stretch when forward. Returns the QI on arrival. Pierces are found from v0 on, so a
// walk from v1 (which emits nothing) takes their sum at once.
template <typename Piece>
int32_t walk(const Ctx& c, uint32_t e, bool forward, int32_t q, QiStats* st, Piece piece) {
  const SolidEdge& se = c.topo.edges[e];
  const Point3 a = c.topo.vertices[se.v0], b = c.topo.vertices[se.v1];
  const int sign = forward ? 1 : -1;
  const int64_t dx = sign * int64_t{b.x - a.x}, dy = sign * int64_t{b.y - a.y};
  const Crossing* cx = c.cs.begin(e);
  const uint32_t ncx = c.cs.count(e);
  const Incidence* ix = c.inc.by_edge + c.inc.edge_first[e];
  const uint32_t nix = c.inc.edge_first[e + 1] - c.inc.edge_first[e];
  int64_t at = forward ? 0 : (int64_t{1} << 32);
  if (!forward) q -= all_pierces(c, e, st);
  PierceEvent pe = forward ? next_pierce_of(c, e, -1, st) : PierceEvent{kNoPierce, 0, true};
  uint32_t i = 0, j = 0;  // events taken from each list
  while (i < ncx || j < nix || pe.t != kNoPierce) {
    // Next crossing and next incidence in walking order, or the next pierce before both.
    const Crossing* nc = i < ncx ? (forward ? cx + i : cx + (ncx - 1 - i)) : nullptr;
    const Incidence* ni = j < nix ? (forward ? ix + j : ix + (nix - 1 - j)) : nullptr;
    bool take_crossing = ni == nullptr;
    if (nc != nullptr && ni != nullptr) take_crossing = forward ? nc->t <= ni->t : nc->t >= ni->t;
    int64_t t = nc == nullptr && ni == nullptr ? kNoPierce : (take_crossing ? nc->t : ni->t);
    int change = 0;
    if (pe.t < t) {  // forward only
      t = pe.t;
      change = pe.change;
      pe = next_pierce_of(c, e, pe.t, st);
    } else if (take_crossing) {
      change = crossing_change(c, nc->front_edge(), dx, dy);
      if (st != nullptr && change != 0) ++st->crossings;
      ++i;
    } else {
      change = passage_change(c, *ni, sign);
      if (st != nullptr && change != 0) ++st->half;
      ++j;
    }
    if (change == 0) continue;
    if (forward) piece(at, t, q);
    at = t;
    q += change;
    if (st != nullptr && (q & 1) != 0) ++st->occluded;
  }
  if (forward) piece(at, int64_t{1} << 32, q);
  return q;
}

bool degenerate(const Ctx& c, uint32_t e) {
  const Point3 a = c.topo.vertices[c.topo.edges[e].v0], b = c.topo.vertices[c.topo.edges[e].v1];
  return a.x == b.x && a.y == b.y;
}

uint32_t other_end(const SolidEdge& e, uint32_t v) { return e.v0 == v ? e.v1 : e.v0; }

// base(v) from a ray cast along edge (v -> to): only the faces of v's grid cell can cover it.
int32_t cast_base(const Ctx& c, const FaceGrid& fg, uint32_t v, uint32_t to) {
  const Point3 pv = c.topo.vertices[v];
  const CoverPoint p = vertex_toward(pv, c.topo.vertices[to]);
  int32_t q = 0;
  for (const uint32_t* t = fg.begin(pv.x, pv.y); t != fg.end(pv.x, pv.y); ++t)
    q += face_cover(c, *t, p);
  return q - local_cover(c, v, to, false, p).total();
}

}  // namespace

bool qi_contour_diagonal(const Topology& topo, const QiState& state, uint32_t e) {
  if (state.two_sided) return paper_contour(topo, e);
  return topo.edges[e].cls == EdgeClass::kH3 || edge_on_contour(topo, e);
}

namespace {

// The propagation's parts (qi.h's QiSplit): vertices by number, part_vertices to a part; an
// edge belongs to the part of its v0. A part walks its own edges from its own vertices; where
// one of them ends at another part's vertex, the QI it arrives with is kept (a crossing record)
// and checked against that vertex's own once every part is done.
struct CrossRecord {
  uint32_t vertex;
  int32_t base;
};

struct Split {
  uint32_t part_vertices;
  uint32_t n_parts;
  uint32_t part(uint32_t v) const { return v / part_vertices; }
};

Split split_of(const Topology& topo, uint32_t part_vertices) {
  const uint32_t pv = part_vertices < 1 ? 1 : part_vertices;
  const uint32_t n = topo.n_vertices / pv + (topo.n_vertices % pv != 0 ? 1 : 0);
  return Split{pv, n < 1 ? 1 : n};
}

// Edges whose ends lie in different parts: the crossing records a run can make.
uint32_t crossing_edges(const Topology& topo, const Split& sp) {
  if (sp.n_parts == 1) return 0;
  uint32_t n = 0;
  for (uint32_t e = 0; e < topo.n_edges; ++e)
    n += sp.part(topo.edges[e].v0) != sp.part(topo.edges[e].v1) ? 1 : 0;
  return n;
}

}  // namespace

size_t qi_bytes(const Topology& topo, uint32_t part_vertices) {
  const Split sp = split_of(topo, part_vertices);
  ByteCounter c;
  c.take<uint8_t>(face_grid_bytes(topo));
  c.take<int32_t>(topo.n_vertices);
  c.take<int32_t>(topo.n_edges);
  c.take<uint32_t>(topo.n_vertices);
  c.take<uint8_t>(topo.n_vertices);  // plain
  if (sp.n_parts > 1) {
    c.take<uint32_t>(2 * size_t{sp.n_parts} + 1);
    c.take<CrossRecord>(crossing_edges(topo, sp));
    c.take<QiStats>(sp.n_parts);
  }
  return c.total + 8;
}

namespace {

// The vertices [lo, hi) a breadth-first spread may enter; an edge is its own when its v0 is.
struct Own {
  uint32_t lo, hi;
  bool has(uint32_t v) const { return lo <= v && v < hi; }
};

// Breadth first from queue[0, tail) (Heger's queue), over the edges of `own` not yet walked.
// An edge that arrives outside `own` leaves a crossing record instead of entering it.
void spread(const Ctx& c, QiState& s, const Own& own, uint32_t* queue, uint32_t tail,
            CrossRecord* cross, uint32_t* n_cross, QiStats& st) {
  const Topology& topo = c.topo;
  uint32_t head = 0;
  while (head < tail) {
    const uint32_t v = queue[head++];
    for (uint32_t k = topo.vertex_edge_first[v]; k < topo.vertex_edge_first[v + 1]; ++k) {
      const uint32_t e = topo.vertex_edges[k];
      const SolidEdge& se = topo.edges[e];
      // Another part's edge is neither read nor written here (its part may be running).
      if (!own.has(se.v0) || s.q_at_v0[e] != kQiUnknown) continue;
      const uint32_t x = other_end(se, v);
      int32_t arrive_base;
      if (degenerate(c, e)) {
        ++st.degenerate;
        arrive_base = s.base[v];
        s.q_at_v0[e] = s.base[v];  // a point: nothing is drawn from it
      } else {
        const Point3 pv = topo.vertices[v], px = topo.vertices[x];
        const bool along_face = se.face[0] != kNoFace || se.face[1] != kNoFace;
        const Local start = local_cover(c, v, x, along_face, vertex_toward(pv, px));
        count_local(start, &st);
        const int32_t q0 = s.base[v] + start.total();
        if ((q0 & 1) != 0) ++st.occluded;
        const bool forward = se.v0 == v;
        const int32_t q1 = walk(c, e, forward, q0, &st, [](int64_t, int64_t, int32_t) {});
        const Local end = local_cover(c, x, v, along_face, vertex_toward(px, pv));
        count_local(end, &st);
        arrive_base = q1 - end.total();
        s.q_at_v0[e] = forward ? q0 : q1;
      }
      ++st.edges_walked;
      if (!own.has(x)) {
        cross[(*n_cross)++] = CrossRecord{x, arrive_base};
      } else if (s.base[x] == kQiUnknown) {
        s.base[x] = arrive_base;
        queue[tail++] = x;
      } else if (s.base[x] != arrive_base) {
        // Two paths disagree: Heger re-initialises. Exact predicates should never get here.
        ++st.conflicts;
        if (!degenerate(c, e)) {
          s.base[x] = cast_base(c, s.grid, x, v);
          ++st.ray_casts;
        }
      }
    }
  }
}

// Every vertex of `own` not yet reached seeds a spread with a ray cast.
void propagate_own(const Ctx& c, QiState& s, const Own& own, uint32_t* queue, CrossRecord* cross,
                   uint32_t* n_cross, QiStats& st) {
  const Topology& topo = c.topo;
  for (uint32_t seed = own.lo; seed < own.hi; ++seed) {
    if (s.base[seed] != kQiUnknown) continue;
    // A seed needs an edge that is not a point on paper, to ask the faces with a direction.
    uint32_t via = kNoFace;
    for (uint32_t k = topo.vertex_edge_first[seed]; k < topo.vertex_edge_first[seed + 1]; ++k)
      if (!degenerate(c, topo.vertex_edges[k])) via = topo.vertex_edges[k];
    if (via == kNoFace) continue;
    s.base[seed] = cast_base(c, s.grid, seed, other_end(topo.edges[via], seed));
    ++st.ray_casts;
    ++st.components;
    queue[0] = seed;
    spread(c, s, own, queue, 1, cross, n_cross, st);
  }
}

void add(QiStats& to, const QiStats& p) {
  to.components += p.components;
  to.ray_casts += p.ray_casts;
  to.conflicts += p.conflicts;
  to.edges_walked += p.edges_walked;
  to.crossings += p.crossings;
  to.wedge += p.wedge;
  to.delta += p.delta;
  to.quarter += p.quarter;
  to.half += p.half;
  to.occluded += p.occluded;
  to.degenerate += p.degenerate;
  to.pierces += p.pierces;
  to.pierce_tests += p.pierce_tests;
}

// The parts' shared state; part k writes base and queue at its own vertices, q_at_v0 at its own
// edges, and its own slice of the crossing records and its stats.
struct PartRun {
  const Ctx* c;
  QiState* s;
  Split sp;
  uint32_t* queue;
  uint32_t* cross_first;  // [n_parts + 1]: part k's records start here
  uint32_t* cross_used;   // [n_parts]: how many it made
  CrossRecord* cross;
  QiStats* stats;
  uint32_t workers;
};

void run_part(const PartRun& r, uint32_t k) {
  const uint32_t lo = k * r.sp.part_vertices;
  const uint32_t n = r.c->topo.n_vertices;
  const Own own{lo, n - lo < r.sp.part_vertices ? n : lo + r.sp.part_vertices};
  uint32_t made = 0;
  propagate_own(*r.c, *r.s, own, r.queue + lo, r.cross + r.cross_first[k], &made, r.stats[k]);
  r.cross_used[k] = made;
}

void run_worker(void* arg, uint32_t w) {
  const PartRun& r = *static_cast<const PartRun*>(arg);
  for (uint32_t k = w; k < r.sp.n_parts; k += r.workers) run_part(r, k);
}

// The plain stars of vertices [lo, hi), into plain (written by no other part).
void fill_plain(const Ctx& c, uint8_t* plain, uint32_t lo, uint32_t hi) {
  for (uint32_t v = lo; v < hi; ++v) plain[v] = plain_star(c.topo, c.front, v);
}

struct PlainRun {
  const Ctx* c;
  uint8_t* plain;
  Split sp;
  uint32_t workers;
};

void plain_worker(void* arg, uint32_t w) {
  const PlainRun& r = *static_cast<const PlainRun*>(arg);
  const uint32_t n = r.c->topo.n_vertices;
  for (uint32_t k = w; k < r.sp.n_parts; k += r.workers) {
    const uint32_t lo = k * r.sp.part_vertices;
    fill_plain(*r.c, r.plain, lo, n - lo < r.sp.part_vertices ? n : lo + r.sp.part_vertices);
  }
}

}  // namespace

Status propagate_qi(const Topology& topo, const uint8_t* front, const CutSet& cutset,
                    const Incidences& inc, void* buffer, size_t bytes, QiState* out, QiStats* stats,
                    bool find_pierces, QiSplit split, QiGrid grid) {
  if (cutset.n_edges != topo.n_edges) return Status::kBadParameter;
  const Split sp = split_of(topo, split.part_vertices);
  Carver carve(buffer, bytes);
  QiState s;
  if (grid == QiGrid::kKeep) {
    if (out->grid.first != reinterpret_cast<const uint32_t*>(carve.next))
      return Status::kBadParameter;
    s.grid = out->grid;
  } else {
    // The arrays carved after the grid are written only once it is built: until then they are
    // its parts' scratch.
    const Status gs = build_face_grid(topo, buffer, bytes, &s.grid, 1, split.parts);
    if (gs != Status::kOk) return gs;
  }
  carve.take<uint8_t>(face_grid_bytes(s.grid));
  s.base = carve.take<int32_t>(topo.n_vertices);
  s.q_at_v0 = carve.take<int32_t>(topo.n_edges);
  uint32_t* queue = carve.take<uint32_t>(topo.n_vertices);
  uint8_t* plain = carve.take<uint8_t>(topo.n_vertices);
  PartRun r{};
  if (sp.n_parts > 1) {
    r.cross_first = carve.take<uint32_t>(2 * size_t{sp.n_parts} + 1);
    r.cross = carve.take<CrossRecord>(crossing_edges(topo, sp));
    r.stats = carve.take<QiStats>(sp.n_parts);
  }
  if (carve.short_) return Status::kWorkspaceTooSmall;
  s.two_sided = qi_two_sided(topo);
  Ctx c{topo, front, cutset, inc, s.two_sided};
  if (find_pierces) {
    s.pierces = true;
    c.pierce_grid = &s.grid;
  }
  for (uint32_t v = 0; v < topo.n_vertices; ++v) s.base[v] = kQiUnknown;
  for (uint32_t e = 0; e < topo.n_edges; ++e) s.q_at_v0[e] = kQiUnknown;
  const Parts runner = split.parts != nullptr ? *split.parts : Parts{};
  if (!s.two_sided) {
    // Before any walk: a part's walks ask the stars of other parts' vertices where they end.
    if (sp.n_parts == 1) {
      fill_plain(c, plain, 0, topo.n_vertices);
    } else {
      const uint32_t want = runner.split();
      PlainRun pr{&c, plain, sp, want < sp.n_parts ? want : sp.n_parts};
      run_parts(runner, pr.workers, &plain_worker, &pr);
    }
    c.plain = plain;
  }
  QiStats st;
  uint32_t none = 0;
  if (sp.n_parts == 1) {
    propagate_own(c, s, Own{0, topo.n_vertices}, queue, nullptr, &none, st);
  } else {
    // Each part's records start where the edges it owns that leave it begin.
    uint32_t* first = r.cross_first;
    for (uint32_t k = 0; k <= sp.n_parts; ++k) first[k] = 0;
    for (uint32_t e = 0; e < topo.n_edges; ++e) {
      const uint32_t p0 = sp.part(topo.edges[e].v0);
      if (p0 != sp.part(topo.edges[e].v1)) ++first[p0 + 1];
    }
    for (uint32_t k = 0; k < sp.n_parts; ++k) first[k + 1] += first[k];
    r.cross_used = first + sp.n_parts + 1;
    for (uint32_t k = 0; k < sp.n_parts; ++k) r.stats[k] = QiStats{};
    r.c = &c;
    r.s = &s;
    r.sp = sp;
    r.queue = queue;
    const uint32_t want = runner.split();
    r.workers = want < sp.n_parts ? want : sp.n_parts;
    run_parts(runner, r.workers, &run_worker, &r);
    // In part order, so the sums and any conflict are the same however the parts ran.
    uint32_t tail = 0;
    for (uint32_t k = 0; k < sp.n_parts; ++k) {
      add(st, r.stats[k]);
      for (uint32_t i = first[k]; i < first[k] + r.cross_used[k]; ++i) {
        const CrossRecord& x = r.cross[i];
        if (s.base[x.vertex] == kQiUnknown) {  // reached from no edge of its own part
          s.base[x.vertex] = x.base;
          queue[tail++] = x.vertex;
        } else if (s.base[x.vertex] != x.base) {
          ++st.conflicts;
        }
      }
    }
    // What only another part's edge reached (a vertex whose own edges are points on paper)
    // spreads from there over the edges left.
    spread(c, s, Own{0, topo.n_vertices}, queue, tail, nullptr, &none, st);
  }
  *out = s;
  if (stats != nullptr) *stats = st;
  return Status::kOk;
}

Status emit_edge_qi_pieces(const Topology& topo, const uint8_t* front, const CutSet& cutset,
                           const Incidences& inc, const QiState& state, uint32_t e, QiSink sink) {
  const Ctx c{topo, front, cutset, inc, state.two_sided, state.pierces ? &state.grid : nullptr};
  if (degenerate(c, e) || state.q_at_v0[e] == kQiUnknown) return Status::kOk;
  Status status = Status::kOk;
  QiPiece pending{{e, 0, 0}, 0};
  bool have = false;
  auto flush = [&]() {
    if (have && status == Status::kOk) status = sink.emit(sink.context, pending);
    have = false;
  };
  walk(c, e, true, state.q_at_v0[e], nullptr, [&](int64_t t0, int64_t t1, int32_t q) {
    if (t1 <= t0) return;
    if (have && pending.q == q && pending.t1 == t0) {
      pending.t1 = t1;
      return;
    }
    flush();
    pending = QiPiece{{e, t0, t1}, q};
    have = true;
  });
  flush();
  return status;
}

namespace {

// The emission's parts (emit_qi_pieces): part k walks edges [e_lo, e_hi) into its share of
// the buffer, kept[0, n); stop: the first edge it could not keep (e_hi when it kept them all).
struct KeptPiece {
  int64_t t0, t1;
  uint32_t edge;
  int32_t q;
};
struct EmitPart {
  KeptPiece* kept;
  uint32_t cap, n, e_lo, e_hi, stop;
};
struct EmitRun {
  const Topology* topo;
  const uint8_t* front;
  const CutSet* cs;
  const Incidences* inc;
  const QiState* state;
  EmitPart* parts;
  uint32_t n_parts, workers;
};

constexpr uint32_t kEmitPartsPerWorker = 4;  // taken in turn: pierces crowd where solids meet
constexpr uint32_t kEmitMaxParts = 64;

bool emitted(const Topology& topo, const QiState& state, uint32_t e) {
  return e < topo.n_drawn || qi_contour_diagonal(topo, state, e);
}

Status emit_edges(const EmitRun& r, uint32_t lo, uint32_t hi, QiSink sink) {
  for (uint32_t e = lo; e < hi; ++e) {
    if (!emitted(*r.topo, *r.state, e)) continue;
    const Status s = emit_edge_qi_pieces(*r.topo, r.front, *r.cs, *r.inc, *r.state, e, sink);
    if (s != Status::kOk) return s;
  }
  return Status::kOk;
}

Status keep_qi_piece(void* context, const QiPiece& p) {
  EmitPart* part = static_cast<EmitPart*>(context);
  if (part->n == part->cap) return Status::kWorkspaceTooSmall;
  part->kept[part->n++] = KeptPiece{p.t0, p.t1, p.edge, p.q};
  return Status::kOk;
}

void emit_worker(void* arg, uint32_t w) {
  const EmitRun& r = *static_cast<const EmitRun*>(arg);
  for (uint32_t k = w; k < r.n_parts; k += r.workers) {
    EmitPart& p = r.parts[k];
    for (uint32_t e = p.e_lo; e < p.e_hi; ++e) {
      if (!emitted(*r.topo, *r.state, e)) continue;
      const uint32_t n = p.n;
      if (emit_edge_qi_pieces(*r.topo, r.front, *r.cs, *r.inc, *r.state, e,
                              QiSink{&keep_qi_piece, &p}) != Status::kOk) {
        p.n = n;  // full: this edge on, on the calling thread
        p.stop = e;
        break;
      }
    }
  }
}

// The workers: the runner's count (at most kEmitMaxParts / kEmitPartsPerWorker), fewer where
// one would get fewer edges than Parts::min_work; one without pierces (see qi.h), a runner, or
// a buffer that gives each part a share of a few pieces.
uint32_t emit_workers(const Topology& topo, const QiState& state, const PartsBuffer& pb,
                      uint32_t* cap) {
  if (!state.pierces || pb.parts == nullptr || pb.buffer == nullptr) return 1;
  uint32_t n = pb.parts->split();
  if (n > kEmitMaxParts / kEmitPartsPerWorker) n = kEmitMaxParts / kEmitPartsPerWorker;
  const uint64_t worth = pb.parts->min_work == 0 ? n : topo.n_edges / pb.parts->min_work;
  if (worth < n) n = worth < 1 ? 1 : uint32_t(worth);
  const size_t books = carve_round(sizeof(EmitPart) * kEmitMaxParts);
  if (n < 2 || pb.bytes < books) return 1;
  const size_t share = (pb.bytes - books) / (n * kEmitPartsPerWorker) / sizeof(KeptPiece);
  *cap = share > 0xffffffffu ? 0xffffffffu : uint32_t(share);
  return *cap < 4 ? 1 : n;
}

}  // namespace

Status emit_qi_pieces(const Topology& topo, const uint8_t* front, const CutSet& cutset,
                      const Incidences& inc, const QiState& state, QiSink sink, PartsBuffer pb) {
  uint32_t cap = 0;
  const uint32_t workers = kRunsParts ? emit_workers(topo, state, pb, &cap) : 1;
  EmitRun r{&topo, front, &cutset, &inc, &state, nullptr, 1, workers};
  if (workers < 2) return emit_edges(r, 0, topo.n_edges, sink);
  r.n_parts = workers * kEmitPartsPerWorker;
  r.parts = static_cast<EmitPart*>(pb.buffer);
  KeptPiece* kept = reinterpret_cast<KeptPiece*>(static_cast<uint8_t*>(pb.buffer) +
                                                 carve_round(sizeof(EmitPart) * kEmitMaxParts));
  // Rounds of edges, the buffer used again in each: a part gets about half as many edges as
  // its share holds pieces (an edge gives one or a few), so the pages the parts write stay
  // those of the buffer, however many edges.
  const uint64_t per_round = uint64_t{r.n_parts} * (cap / 2 < 1 ? 1 : cap / 2);
  for (uint32_t a = 0; a < topo.n_edges;) {
    const uint32_t b = topo.n_edges - a < per_round ? topo.n_edges : uint32_t(a + per_round);
    for (uint32_t k = 0; k < r.n_parts; ++k) {
      const uint32_t lo = a + uint32_t(uint64_t{b - a} * k / r.n_parts);
      const uint32_t hi = a + uint32_t(uint64_t{b - a} * (k + 1) / r.n_parts);
      r.parts[k] = EmitPart{kept + size_t{cap} * k, cap, 0, lo, hi, hi};
    }
    run_parts(*pb.parts, workers, &emit_worker, &r);
    for (uint32_t k = 0; k < r.n_parts; ++k) {
      const EmitPart& p = r.parts[k];
      for (uint32_t i = 0; i < p.n; ++i) {
        const KeptPiece& x = p.kept[i];
        const Status s = sink.emit(sink.context, QiPiece{{x.edge, x.t0, x.t1}, x.q});
        if (s != Status::kOk) return s;
      }
      const Status s = emit_edges(r, p.stop, p.e_hi, sink);
      if (s != Status::kOk) return s;
    }
    a = b;
  }
  return Status::kOk;
}

}  // namespace haloplot
