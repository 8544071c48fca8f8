#include "haloplot/solid/face_grid.h"

#include "haloplot/geometry/wide.h"
#include "memory/carve.h"

namespace haloplot {
namespace {

Grid choose_grid(const Topology& topo, uint32_t coarsen) {
  const uint32_t per_axis = static_cast<uint32_t>(isqrt_u64(topo.n_triangles) + 1);
  return grid_over(topo.vertices, topo.n_vertices, per_axis / (coarsen > 1 ? coarsen : 1));
}

Edge3 face_box(const Topology& topo, uint32_t t) {
  const uint32_t* v = topo.triangles[t].v;
  const Point3 a = topo.vertices[v[0]], b = topo.vertices[v[1]], c = topo.vertices[v[2]];
  Edge3 box;
  box.a = Point3{min_i32(a.x, min_i32(b.x, c.x)), min_i32(a.y, min_i32(b.y, c.y)), 0};
  box.b = Point3{max_i32(a.x, max_i32(b.x, c.x)), max_i32(a.y, max_i32(b.y, c.y)), 0};
  return box;
}

// The cells for_each_cell() visits for each face's box (kBoundingBox, no reach): the box's
// columns times its rows, counted without the walk. The box is ordered (a <= b) and inside
// the grid, which spans every vertex, so no clamping or swap changes the range.
uint64_t count_pairs(const Topology& topo, const Grid& g) {
  uint64_t n = 0;
  for (uint32_t t = 0; t < topo.n_triangles; ++t) {
    const Edge3 box = face_box(topo, t);
    n += uint64_t{g.col(box.b.x) - g.col(box.a.x) + 1} * (g.row(box.b.y) - g.row(box.a.y) + 1);
  }
  return n;
}

}  // namespace

size_t face_grid_bytes(const Topology& topo, uint32_t coarsen) {
  const Grid g = choose_grid(topo, coarsen);
  ByteCounter c;
  c.take<uint32_t>(size_t{g.cells()} + 1);
  // More pairs than 32 bits count is refused by the build; size it as if none.
  const uint64_t pairs = count_pairs(topo, g);
  c.take<uint32_t>(pairs > 0xffffffffu ? 0 : static_cast<size_t>(pairs));
  return c.total + 8;
}

Status build_face_grid(const Topology& topo, void* buffer, size_t bytes, FaceGrid* out,
                       uint32_t coarsen) {
  const Grid g = choose_grid(topo, coarsen);
  const uint64_t pairs = count_pairs(topo, g);
  if (pairs > 0xffffffffu) return Status::kCellPairOverflow;
  Carver carve(buffer, bytes);
  uint32_t* first = carve.take<uint32_t>(size_t{g.cells()} + 1);
  uint32_t* faces = carve.take<uint32_t>(static_cast<size_t>(pairs));
  if (carve.short_) return Status::kWorkspaceTooSmall;
  for (uint32_t c = 0; c <= g.cells(); ++c) first[c] = 0;
  for (uint32_t t = 0; t < topo.n_triangles; ++t)
    for_each_cell(g, face_box(topo, t), CellCover::kBoundingBox, 0,
                  [&](uint32_t c) { ++first[c + 1]; });
  for (uint32_t c = 0; c < g.cells(); ++c) first[c + 1] += first[c];
  for (uint32_t t = 0; t < topo.n_triangles; ++t)
    for_each_cell(g, face_box(topo, t), CellCover::kBoundingBox, 0,
                  [&](uint32_t c) { faces[first[c]++] = t; });
  for (uint32_t c = g.cells(); c > 0; --c) first[c] = first[c - 1];
  first[0] = 0;
  out->grid = g;
  out->first = first;
  out->faces = faces;
  out->pairs = static_cast<uint32_t>(pairs);
  return Status::kOk;
}

}  // namespace haloplot
