#include "haloplot/solid/incidence.h"

#include "haloplot/cut/grid.h"
#include "haloplot/geometry/wide.h"
#include "memory/carve.h"
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
  c.template take<uint32_t>(topo.n_vertices);          // cell_vertices / sort order
}

// Vertices at the same point: sorted by (x, y, index) in `order`, each run linked into a ring.
void link_coincident(const Point3* p, uint32_t nv, uint32_t* order, Incidences* out) {
  Incidences& r = *out;
  for (uint32_t v = 0; v < nv; ++v) order[v] = v;
  sort_total(order, nv, [p](uint32_t a, uint32_t b) {
    if (p[a].x != p[b].x) return p[a].x < p[b].x;
    if (p[a].y != p[b].y) return p[a].y < p[b].y;
    return a < b;
  });
  for (uint32_t i = 0; i < nv;) {
    uint32_t j = i + 1;
    while (j < nv && p[order[j]].x == p[order[i]].x && p[order[j]].y == p[order[i]].y) ++j;
    for (uint32_t k = i; k < j; ++k) r.same_next[order[k]] = order[k + 1 < j ? k + 1 : i];
    if (j - i > 1) r.coincident_vertices += j - i;
    i = j;
  }
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
                       Incidences* out, uint32_t* needed, bool by_vertex) {
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
  if (by_vertex) link_coincident(p, nv, order, &r);

  // The vertex grid.
  const Grid g = grid_over(p, nv, side - 2);
  const uint32_t cells = g.cells();
  for (uint32_t c = 0; c <= cells; ++c) cell_first[c] = 0;
  for (uint32_t v = 0; v < nv; ++v) ++cell_first[g.cell_of(p[v].x, p[v].y) + 1];
  for (uint32_t c = 0; c < cells; ++c) cell_first[c + 1] += cell_first[c];
  for (uint32_t v = 0; v < nv; ++v) order[cell_first[g.cell_of(p[v].x, p[v].y)]++] = v;
  for (uint32_t c = cells; c > 0; --c) cell_first[c] = cell_first[c - 1];
  cell_first[0] = 0;

  // Each edge against the vertices of its cells: on the line, strictly between the ends.
  uint32_t n = 0;
  for (uint32_t e = 0; e < topo.n_edges; ++e) {
    r.edge_first[e] = n;
    const SolidEdge& se = topo.edges[e];
    const Point3 a = p[se.v0], b = p[se.v1];
    const int64_t dx = b.x - a.x, dy = b.y - a.y;
    if (dx == 0 && dy == 0) continue;
    const Edge3 e3{a, b};
    for_each_cell(g, e3, CellCover::kExact, 0, [&](uint32_t c) {
      for (uint32_t k = cell_first[c]; k < cell_first[c + 1]; ++k) {
        const uint32_t w = order[k];
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
        if (n < capacity) {
          const uint64_t t = (static_cast<uint64_t>(num) << 32) / static_cast<uint64_t>(den);
          r.by_edge[n] = Incidence{e, w, static_cast<uint32_t>(t), static_cast<uint32_t>(num),
                                   static_cast<uint32_t>(den)};
        }
        ++n;
      }
    });
  }
  r.edge_first[topo.n_edges] = n < capacity ? n : capacity;
  *needed = n;
  if (n > capacity) return Status::kIncidenceCapacity;
  r.n = n;
  // Within an edge, order by position (cells were visited left to right, not along the edge).
  for (uint32_t e = 0; e < topo.n_edges; ++e)
    sort_in_place(r.by_edge + r.edge_first[e], r.edge_first[e + 1] - r.edge_first[e],
                  [](const Incidence& x, const Incidence& y) {
                    return x.t < y.t || (x.t == y.t && x.vertex < y.vertex);
                  });
  if (by_vertex) group_by_vertex(nv, &r);
  *out = r;
  return Status::kOk;
}

}  // namespace haloplot
