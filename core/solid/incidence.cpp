#include "haloplot/solid/incidence.h"

#include "haloplot/cut/grid.h"
#include "haloplot/geometry/wide.h"
#include "haloplot/memory/parts.h"
#include "memory/carve.h"
#include "solid/build_parts.h"
#include "sort/in_place_sort.h"

namespace haloplot {
namespace {

// About one vertex per cell: side = extent / ceil(sqrt(V)), so at most (sqrt(V) + 2)^2 cells.
uint32_t grid_side_cells(uint32_t n_vertices) { return isqrt_u64(n_vertices) + 2; }

// The arrays the Incidences keep, then the search's scratch (last, so a caller can give it
// back once the search is done).
template <typename C>
void count_arrays(C& c, const Topology& topo, uint32_t capacity, bool by_vertex) {
  c.template take<Incidence>(capacity);
  c.template take<uint32_t>(topo.n_edges + 1);
  if (!by_vertex) return;
  c.template take<uint32_t>(capacity);
  c.template take<uint32_t>(topo.n_vertices + 1);
  c.template take<uint32_t>(topo.n_vertices);  // same_next
}
template <typename C>
void count_scratch(C& c, const Topology& topo) {
  const uint32_t side = grid_side_cells(topo.n_vertices);
  c.template take<uint32_t>(size_t{side} * side + 1);  // cell_first (grid scratch)
  c.template take<uint32_t>(topo.n_vertices);          // the cells' vertex lists
}

// Vertices at the same point, in cells [c0, c1) of the vertex grid (two such vertices share a
// cell): each cell's list sorted by (x, y, index), each run of one point linked into a ring in
// index order. Returns how many vertices share their point with another. The cell lists then
// stay in this order: the edges' tests read them in any order (each edge's records are sorted).
uint32_t link_coincident(const Point3* p, const uint32_t* cell_first, uint32_t* order, uint32_t c0,
                         uint32_t c1, uint32_t* same_next) {
  uint32_t coincident = 0;
  for (uint32_t c = c0; c < c1; ++c) {
    uint32_t* list = order + cell_first[c];
    const uint32_t n = cell_first[c + 1] - cell_first[c];
    sort_total(list, n, [p](uint32_t a, uint32_t b) {
      if (p[a].x != p[b].x) return p[a].x < p[b].x;
      if (p[a].y != p[b].y) return p[a].y < p[b].y;
      return a < b;
    });
    for (uint32_t i = 0; i < n;) {
      uint32_t j = i + 1;
      while (j < n && p[list[j]].x == p[list[i]].x && p[list[j]].y == p[list[i]].y) ++j;
      for (uint32_t k = i; k < j; ++k) same_next[list[k]] = list[k + 1 < j ? k + 1 : i];
      if (j - i > 1) coincident += j - i;
      i = j;
    }
  }
  return coincident;
}

// The vertex grid's lists, in `order` by cell (each in index order), cell_first[c] their starts.
void fill_vertex_grid(const Point3* p, uint32_t nv, const Grid& g, uint32_t* cell_first,
                      uint32_t* order) {
  const uint32_t cells = g.cells();
  for (uint32_t c = 0; c <= cells; ++c) cell_first[c] = 0;
  for (uint32_t v = 0; v < nv; ++v) ++cell_first[g.cell_of(p[v].x, p[v].y) + 1];
  for (uint32_t c = 0; c < cells; ++c) cell_first[c + 1] += cell_first[c];
  for (uint32_t v = 0; v < nv; ++v) order[cell_first[g.cell_of(p[v].x, p[v].y)]++] = v;
  for (uint32_t c = cells; c > 0; --c) cell_first[c] = cell_first[c - 1];
  cell_first[0] = 0;
}

// What the edges' tests read: the vertices and their grid.
struct VertexGrid {
  const Topology* topo;
  Grid g;
  const uint32_t* cell_first;
  const uint32_t* order;
};

// Edges [e0, e1) against the vertices of their cells: on the line, strictly between the ends.
// The records go to out[0, room) while they fit, each edge's sorted by position (cells are
// visited left to right, not along the edge); edge_first[e] is where e's start, counted from
// out. Returns how many there are, stored or not.
uint32_t test_edges(const VertexGrid& vg, uint32_t e0, uint32_t e1, Incidence* out, uint32_t room,
                    uint32_t* edge_first) {
  const Topology& topo = *vg.topo;
  const Point3* p = topo.vertices;
  uint32_t n = 0;
  for (uint32_t e = e0; e < e1; ++e) {
    edge_first[e] = n;
    const SolidEdge& se = topo.edges[e];
    const Point3 a = p[se.v0], b = p[se.v1];
    const int64_t dx = b.x - a.x, dy = b.y - a.y;
    if (dx == 0 && dy == 0) continue;
    const Edge3 e3{a, b};
    for_each_cell(vg.g, e3, CellCover::kExact, 0, [&](uint32_t c) {
      for (uint32_t k = vg.cell_first[c]; k < vg.cell_first[c + 1]; ++k) {
        const uint32_t w = vg.order[k];
        if (w == se.v0 || w == se.v1) continue;
        const int64_t wx = p[w].x - a.x, wy = p[w].y - a.y;
        if (dx * wy - dy * wx != 0) continue;
        // Along the longer axis the position is num / den with 0 < num < den.
        const bool use_x = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
        int64_t num = use_x ? wx : wy, den = use_x ? dx : dy;
        if (den < 0) {
          num = -num;
          den = -den;
        }
        if (num <= 0 || num >= den) continue;
        if (n < room) {
          const uint64_t t = (static_cast<uint64_t>(num) << 32) / static_cast<uint64_t>(den);
          out[n] = Incidence{e, w, static_cast<uint32_t>(t), static_cast<uint32_t>(num),
                             static_cast<uint32_t>(den)};
        }
        ++n;
      }
    });
    if (n <= room)
      sort_in_place(out + edge_first[e], n - edge_first[e],
                    [](const Incidence& x, const Incidence& y) {
                      return x.t < y.t || (x.t == y.t && x.vertex < y.vertex);
                    });
  }
  return n;
}

// An edge's walk over the vertex grid costs about as much as a few CUT pair tests, some 8
// (Parts::min_work).
uint32_t part_count(const Parts* parts, uint32_t n_edges) {
  return build_part_count(parts, uint64_t{n_edges} * 8);
}

// The search in parts: the coincident vertices over parts of the cells (about equal vertices
// each), the edges' tests over parts of the edges, each recording into its own equal slice of
// the records. The slices are then joined in part order; a part that outgrew its slice runs
// again into its place once the others are in theirs, so every record is stored exactly when
// one part would have (the total fits), and the arrays are the same whatever the split.
struct SearchParts {
  VertexGrid vg;
  Incidences* r;
  uint32_t capacity;
  uint32_t n;
  uint32_t* order;  // written by the coincident vertices' parts
  uint32_t cell_begin[kMaxBuildParts + 1] = {};
  uint32_t found[kMaxBuildParts] = {};   // each part's records, stored or not
  uint32_t placed[kMaxBuildParts] = {};  // where they start in the joined records
  uint32_t coincident[kMaxBuildParts] = {};

  uint32_t first_edge(uint32_t j) const { return uint32_t(uint64_t{vg.topo->n_edges} * j / n); }
  uint32_t slice(uint32_t j) const { return uint32_t(uint64_t{capacity} * j / n); }
  uint32_t room(uint32_t j) const { return slice(j + 1) - slice(j); }
  static void link(void* arg, uint32_t j) {
    SearchParts* self = static_cast<SearchParts*>(arg);
    self->coincident[j] =
        link_coincident(self->vg.topo->vertices, self->vg.cell_first, self->order,
                        self->cell_begin[j], self->cell_begin[j + 1], self->r->same_next);
  }
  static void test(void* arg, uint32_t j) {
    SearchParts* self = static_cast<SearchParts*>(arg);
    self->found[j] =
        test_edges(self->vg, self->first_edge(j), self->first_edge(j + 1),
                   self->r->by_edge + self->slice(j), self->room(j), self->r->edge_first);
  }
  // Each edge's start, counted from its part's, from the joined records' start.
  static void place(void* arg, uint32_t j) {
    const SearchParts* self = static_cast<const SearchParts*>(arg);
    for (uint32_t e = self->first_edge(j); e < self->first_edge(j + 1); ++e)
      self->r->edge_first[e] += self->placed[j];
  }
};

// Copies n records from `from` to `to`, which may overlap: forward when moving down.
void move_records(Incidence* to, const Incidence* from, uint32_t n) {
  if (to < from)
    for (uint32_t i = 0; i < n; ++i) to[i] = from[i];
  else if (to > from)
    for (uint32_t i = n; i-- > 0;) to[i] = from[i];
}

// Out of line: its bookkeeping takes stack only where a runner splits the search. Returns the
// records found, stored (in one piece, from by_edge's start) when they fit.
__attribute__((noinline)) uint32_t search_in_parts(const VertexGrid& vg, uint32_t capacity,
                                                   uint32_t n_parts, const Parts& parts,
                                                   uint32_t* order, Incidences* r) {
  SearchParts sp{vg, r, capacity, n_parts, order};
  const uint32_t cells = vg.g.cells(), nv = vg.topo->n_vertices;
  if (r->same_next != nullptr) {
    // Cut the cells where the vertices listed before them reach j / n of them.
    uint32_t c = 0;
    for (uint32_t j = 1; j < n_parts; ++j) {
      const uint32_t want = uint32_t(uint64_t{nv} * j / n_parts);
      while (c < cells && vg.cell_first[c] < want) ++c;
      sp.cell_begin[j] = c;
    }
    sp.cell_begin[n_parts] = cells;
    run_parts(parts, n_parts, &SearchParts::link, &sp);
    for (uint32_t j = 0; j < n_parts; ++j) r->coincident_vertices += sp.coincident[j];
  }
  run_parts(parts, n_parts, &SearchParts::test, &sp);
  uint64_t total = 0;
  for (uint32_t j = 0; j < n_parts; ++j) {
    sp.placed[j] = uint32_t(total < capacity ? total : capacity);
    total += sp.found[j];
  }
  if (total > capacity) return total > 0xffffffffu ? 0xffffffffu : uint32_t(total);
  // Each slice to its place: the ones moving down in part order, then the ones moving up in
  // the reverse order, so none lands on records not yet moved (slices and places both lie in
  // part order, and a slice holds its part's records whole).
  for (uint32_t j = 0; j < n_parts; ++j)
    if (sp.found[j] <= sp.room(j) && sp.placed[j] < sp.slice(j))
      move_records(r->by_edge + sp.placed[j], r->by_edge + sp.slice(j), sp.found[j]);
  for (uint32_t j = n_parts; j-- > 0;)
    if (sp.found[j] <= sp.room(j) && sp.placed[j] > sp.slice(j))
      move_records(r->by_edge + sp.placed[j], r->by_edge + sp.slice(j), sp.found[j]);
  for (uint32_t j = 0; j < n_parts; ++j)
    if (sp.found[j] > sp.room(j))
      test_edges(vg, sp.first_edge(j), sp.first_edge(j + 1), r->by_edge + sp.placed[j], sp.found[j],
                 r->edge_first);
  run_parts(parts, n_parts, &SearchParts::place, &sp);
  return uint32_t(total);
}

// The records grouped by vertex.
void group_by_vertex(uint32_t nv, Incidences* out) {
  Incidences& r = *out;
  const uint32_t n = r.n;
  for (uint32_t v = 0; v <= nv; ++v) r.vertex_first[v] = 0;
  for (uint32_t i = 0; i < n; ++i) ++r.vertex_first[r.by_edge[i].vertex + 1];
  for (uint32_t v = 0; v < nv; ++v) r.vertex_first[v + 1] += r.vertex_first[v];
  for (uint32_t i = 0; i < n; ++i) r.by_vertex[r.vertex_first[r.by_edge[i].vertex]++] = i;
  for (uint32_t v = nv; v > 0; --v) r.vertex_first[v] = r.vertex_first[v - 1];
  r.vertex_first[0] = 0;
}

}  // namespace

size_t incidence_bytes(const Topology& topo, uint32_t capacity, bool by_vertex) {
  ByteCounter c;
  count_arrays(c, topo, capacity, by_vertex);
  count_scratch(c, topo);
  return c.total + 8;
}

size_t incidence_scratch_bytes(const Topology& topo) {
  ByteCounter c;
  count_scratch(c, topo);
  return c.total;
}

Status find_incidences(const Topology& topo, uint32_t capacity, void* buffer, size_t bytes,
                       Incidences* out, uint32_t* needed, bool by_vertex, const Parts* parts) {
  const uint32_t nv = topo.n_vertices;
  const uint32_t side = grid_side_cells(nv);
  Carver carve(buffer, bytes);
  Incidences r;
  r.by_edge = carve.take<Incidence>(capacity);
  r.edge_first = carve.take<uint32_t>(topo.n_edges + 1);
  if (by_vertex) {
    r.by_vertex = carve.take<uint32_t>(capacity);
    r.vertex_first = carve.take<uint32_t>(nv + 1);
    r.same_next = carve.take<uint32_t>(nv);
  }
  uint32_t* cell_first = carve.take<uint32_t>(size_t{side} * side + 1);
  uint32_t* order = carve.take<uint32_t>(nv);
  if (carve.short_) return Status::kWorkspaceTooSmall;
  *needed = 0;

  const Point3* p = topo.vertices;
  const Grid g = grid_over(p, nv, side - 2);
  fill_vertex_grid(p, nv, g, cell_first, order);
  const VertexGrid vg{&topo, g, cell_first, order};
  const uint32_t n_parts = part_count(parts, topo.n_edges);
  uint32_t n = 0;
  if (n_parts > 1) {
    n = search_in_parts(vg, capacity, n_parts, *parts, order, &r);
  } else {
    if (by_vertex)
      r.coincident_vertices = link_coincident(p, cell_first, order, 0, g.cells(), r.same_next);
    n = test_edges(vg, 0, topo.n_edges, r.by_edge, capacity, r.edge_first);
  }
  r.edge_first[topo.n_edges] = n < capacity ? n : capacity;
  *needed = n;
  if (n > capacity) return Status::kIncidenceCapacity;
  r.n = n;
  if (by_vertex) group_by_vertex(nv, &r);
  *out = r;
  return Status::kOk;
}

}  // namespace haloplot
