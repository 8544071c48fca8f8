#include "haloplot/solid/face_grid.h"

#include "haloplot/geometry/wide.h"
#include "memory/carve.h"
#include "solid/build_parts.h"

namespace haloplot {
namespace {

Edge3 face_box(const Topology& topo, uint32_t t) {
  const uint32_t* v = topo.triangles[t].v;
  const Point3 a = topo.vertices[v[0]], b = topo.vertices[v[1]], c = topo.vertices[v[2]];
  Edge3 box;
  box.a = Point3{min_i32(a.x, min_i32(b.x, c.x)), min_i32(a.y, min_i32(b.y, c.y)), 0};
  box.b = Point3{max_i32(a.x, max_i32(b.x, c.x)), max_i32(a.y, max_i32(b.y, c.y)), 0};
  return box;
}

// The cells for_each_cell() visits for faces [t0, t1)'s boxes (kBoundingBox, no reach): each
// box's columns times its rows, counted without the walk. The box is ordered (a <= b) and
// inside the grid, which spans every vertex, so no clamping or swap changes the range.
uint64_t count_pairs(const Topology& topo, const Grid& g, uint32_t t0, uint32_t t1) {
  uint64_t n = 0;
  for (uint32_t t = t0; t < t1; ++t) {
    const Edge3 box = face_box(topo, t);
    n += uint64_t{g.col(box.b.x) - g.col(box.a.x) + 1} * (g.row(box.b.y) - g.row(box.a.y) + 1);
  }
  return n;
}

// Faces [t0, t1) counted into count[cell], then each dropped at cursor[cell], moving it on.
void count_cells(const Topology& topo, const Grid& g, uint32_t t0, uint32_t t1, uint32_t* count) {
  for (uint32_t t = t0; t < t1; ++t)
    for_each_cell(g, face_box(topo, t), CellCover::kBoundingBox, 0,
                  [&](uint32_t c) { ++count[c]; });
}
void fill_cells(const Topology& topo, const Grid& g, uint32_t t0, uint32_t t1, uint32_t* cursor,
                uint32_t* faces) {
  for (uint32_t t = t0; t < t1; ++t)
    for_each_cell(g, face_box(topo, t), CellCover::kBoundingBox, 0,
                  [&](uint32_t c) { faces[cursor[c]++] = t; });
}

// A face's box and its few cells cost about a CUT pair test each, some 8 (Parts::min_work).
uint32_t part_count(const Parts* parts, uint32_t n_faces) {
  return build_part_count(parts, uint64_t{n_faces} * 8);
}

// The counting sort in parts of the faces, each with its own cursor into every cell: part k
// counts its faces per cell, one pass over the counts gives each part its place in every cell's
// list (after the parts before it), and part k drops its faces there in ascending order. Every
// cell's list comes out as one part makes it, face for face. The last part's cursors are the
// index itself (as one part's are); the others' lie in the scratch, cells words each.
struct GridParts {
  const Topology* topo;
  Grid g;
  uint32_t n;
  uint32_t* first;
  uint32_t* scratch;
  uint32_t* faces;
  uint64_t pairs[kMaxBuildParts] = {};

  uint32_t first_face(uint32_t k) const { return uint32_t(uint64_t{topo->n_triangles} * k / n); }
  uint32_t* cursor(uint32_t k) const {
    return k + 1 == n ? first : scratch + size_t{k} * g.cells();
  }
  static void count_pairs_of(void* arg, uint32_t k) {
    GridParts* self = static_cast<GridParts*>(arg);
    self->pairs[k] =
        count_pairs(*self->topo, self->g, self->first_face(k), self->first_face(k + 1));
  }
  // The last part counts into first[c + 1], as one part does.
  static void count(void* arg, uint32_t k) {
    const GridParts* self = static_cast<const GridParts*>(arg);
    uint32_t* mine = k + 1 == self->n ? self->first + 1 : self->cursor(k);
    for (uint32_t c = 0; c < self->g.cells(); ++c) mine[c] = 0;
    count_cells(*self->topo, self->g, self->first_face(k), self->first_face(k + 1), mine);
  }
  static void fill(void* arg, uint32_t k) {
    const GridParts* self = static_cast<const GridParts*>(arg);
    fill_cells(*self->topo, self->g, self->first_face(k), self->first_face(k + 1), self->cursor(k),
               self->faces);
  }
};

// Out of line: its bookkeeping takes stack only where a runner splits the build.
__attribute__((noinline)) uint64_t count_pairs_in_parts(const Topology& topo, const Grid& g,
                                                        uint32_t n, const Parts* parts) {
  GridParts gp{&topo, g, n, nullptr, nullptr, nullptr};
  run_parts(*parts, gp.n, &GridParts::count_pairs_of, &gp);
  uint64_t sum = 0;
  for (uint32_t k = 0; k < gp.n; ++k) sum += gp.pairs[k];
  return sum;
}

// The (cell, face) pairs of grid g, in parts where a runner splits them.
uint64_t pairs_of(const Topology& topo, const Grid& g, const Parts* parts) {
  const uint32_t n = part_count(parts, topo.n_triangles);
  if (n <= 1) return count_pairs(topo, g, 0, topo.n_triangles);
  return count_pairs_in_parts(topo, g, n, parts);
}

// The grid (about one face per cell) and its pairs. Where the faces' boxes are large beside
// such cells (tests/support's pierced tori of 1M triangles: 14.3 cells a face, the 1M-triangle
// torus 6.9) the pairs, not the cells, are the grid's bytes (58 MB there, the plot's peak):
// the cells then grow until a face lies in at most kFaceGridPairsPerFace of them on average.
// A box of side L meets about (1 + L / s)^2 cells of side s, so the next side is guessed from
// the pairs counted (root p - 1 to root T - 1) and counted again; a grid of one cell holds
// each face once, so the loop ends. Scenes within the bound keep the grid they always had.
constexpr uint32_t kPairsPerFace = kFaceGridPairsPerFace;
struct Chosen {
  Grid g;
  uint64_t pairs;
};
uint32_t first_per_axis(const Topology& topo, uint32_t coarsen) {
  const uint32_t per_axis = static_cast<uint32_t>(isqrt_u64(topo.n_triangles) + 1);
  return per_axis / (coarsen > 1 ? coarsen : 1);
}
bool keeps(const Topology& topo, const Grid& g, uint64_t pairs) {
  return pairs <= uint64_t{kPairsPerFace} * topo.n_triangles || g.cells() == 1;
}
Chosen choose_grid(const Topology& topo, uint32_t coarsen, const Parts* parts) {
  uint32_t per_axis = first_per_axis(topo, coarsen);
  for (;;) {
    const Grid g = grid_over(topo.vertices, topo.n_vertices, per_axis);
    const uint64_t pairs = pairs_of(topo, g, parts);
    if (keeps(topo, g, pairs)) return Chosen{g, pairs};
    // 256 root(pairs / n), with pairs below 2^47 (more than that gives one cell anyway).
    const uint64_t p = pairs < (uint64_t{1} << 47) ? pairs : (uint64_t{1} << 47);
    const uint64_t root_p = isqrt_u64((p << 16) / topo.n_triangles),
                   root_t = isqrt_u64(uint64_t{kPairsPerFace} << 16);
    uint64_t next = uint64_t{per_axis} * (root_t - 256) / (root_p - 256);
    if (next >= per_axis - per_axis / 16) next = per_axis - per_axis / 16 - 1;  // at least a step
    per_axis = next < 1 ? 1 : uint32_t(next);
  }
}

// first[c] ends as cell c's end, as one part leaves it.
__attribute__((noinline)) void fill_in_parts(const Topology& topo, const Grid& g, uint32_t n,
                                             const Parts* parts, uint32_t* first, uint32_t* scratch,
                                             uint32_t* faces) {
  GridParts gp{&topo, g, n, first, scratch, faces};
  const uint32_t cells = g.cells();
  run_parts(*parts, n, &GridParts::count, &gp);
  // Each part's start in every cell: the last part's in first[c] (its count, in first[c + 1],
  // read before it is overwritten one cell on).
  uint32_t at = 0;
  for (uint32_t c = 0; c < cells; ++c) {
    for (uint32_t k = 0; k + 1 < n; ++k) {
      uint32_t& x = scratch[size_t{k} * cells + c];
      const uint32_t count = x;
      x = at;
      at += count;
    }
    const uint32_t last = first[c + 1];
    first[c] = at;
    at += last;
  }
  run_parts(*parts, n, &GridParts::fill, &gp);
}

// After either fill, first[c] is cell c's end, which is c + 1's start: shifted into place.
Status finish(const Grid& g, uint32_t* first, uint32_t* faces, uint64_t pairs, FaceGrid* out) {
  for (uint32_t c = g.cells(); c > 0; --c) first[c] = first[c - 1];
  first[0] = 0;
  out->grid = g;
  out->first = first;
  out->faces = faces;
  out->pairs = static_cast<uint32_t>(pairs);
  return Status::kOk;
}

// One part: each cell's count in first[c + 1], then its start in first[c], where the faces
// are dropped.
void count_in_one(const Topology& topo, const Grid& g, uint32_t* first) {
  for (uint32_t c = 0; c <= g.cells(); ++c) first[c] = 0;
  count_cells(topo, g, 0, topo.n_triangles, first + 1);
}
void fill_in_one(const Topology& topo, const Grid& g, uint32_t* first, uint32_t* faces) {
  for (uint32_t c = 0; c < g.cells(); ++c) first[c + 1] += first[c];
  fill_cells(topo, g, 0, topo.n_triangles, first, faces);
}

// One part on the first grid (about one face per cell), most scenes' own: its cells' counts,
// taken where the index goes, give its pairs, so the faces' boxes are walked twice (count,
// fill), not three times (choose_grid's count first). False, nothing built, where that grid
// grows (or its index does not fit: then it is not the grid the bytes were sized for).
bool build_on_first_grid(const Topology& topo, uint32_t coarsen, void* buffer, size_t bytes,
                         FaceGrid* out, Status* status) {
  const Grid g = grid_over(topo.vertices, topo.n_vertices, first_per_axis(topo, coarsen));
  Carver carve(buffer, bytes);
  uint32_t* first = carve.take<uint32_t>(size_t{g.cells()} + 1);
  if (carve.short_) return false;
  count_in_one(topo, g, first);
  uint64_t pairs = 0;  // a cell counts fewer than 2^32 faces; their sum may not
  for (uint32_t c = 0; c < g.cells(); ++c) pairs += first[c + 1];
  if (!keeps(topo, g, pairs)) return false;
  *status = Status::kCellPairOverflow;
  if (pairs > 0xffffffffu) return true;
  uint32_t* faces = carve.take<uint32_t>(static_cast<size_t>(pairs));
  *status = Status::kWorkspaceTooSmall;
  if (carve.short_) return true;
  fill_in_one(topo, g, first, faces);
  *status = finish(g, first, faces, pairs, out);
  return true;
}

}  // namespace

size_t face_grid_bytes(const Topology& topo, uint32_t coarsen) {
  const Chosen ch = choose_grid(topo, coarsen, nullptr);
  ByteCounter c;
  c.take<uint32_t>(size_t{ch.g.cells()} + 1);
  // More pairs than 32 bits count is refused by the build; size it as if none.
  c.take<uint32_t>(ch.pairs > 0xffffffffu ? 0 : static_cast<size_t>(ch.pairs));
  return c.total + 8;
}

size_t face_grid_bytes(const FaceGrid& fg) {
  ByteCounter c;
  c.take<uint32_t>(size_t{fg.grid.cells()} + 1);
  c.take<uint32_t>(fg.pairs);
  return c.total + 8;
}

size_t face_grid_part_bytes(const Topology& topo, uint32_t coarsen) {
  return size_t{choose_grid(topo, coarsen, nullptr).g.cells()} * 4;
}

// Beyond one part on the first grid, the grid's pairs are counted as it is chosen (in parts
// where a runner splits them), so its index and faces are carved first; then one part or
// several fill them.
Status build_face_grid(const Topology& topo, void* buffer, size_t bytes, FaceGrid* out,
                       uint32_t coarsen, const Parts* parts) {
  Status s = Status::kOk;
  const uint32_t wanted = part_count(parts, topo.n_triangles);
  if (wanted <= 1 && build_on_first_grid(topo, coarsen, buffer, bytes, out, &s)) return s;
  const Chosen ch = choose_grid(topo, coarsen, parts);
  const Grid& g = ch.g;
  if (ch.pairs > 0xffffffffu) return Status::kCellPairOverflow;
  Carver carve(buffer, bytes);
  uint32_t* first = carve.take<uint32_t>(size_t{g.cells()} + 1);
  uint32_t* faces = carve.take<uint32_t>(static_cast<size_t>(ch.pairs));
  if (carve.short_) return Status::kWorkspaceTooSmall;
  // As many parts as the bytes left hold the cursors of (one needs none).
  uint32_t n = wanted;
  const size_t part_bytes = size_t{g.cells()} * 4;
  if (carve.left / part_bytes + 1 < n) n = uint32_t(carve.left / part_bytes + 1);
  if (n <= 1) {
    count_in_one(topo, g, first);
    fill_in_one(topo, g, first, faces);
  } else {
    fill_in_parts(topo, g, n, parts, first, reinterpret_cast<uint32_t*>(carve.next), faces);
  }
  return finish(g, first, faces, ch.pairs, out);
}

}  // namespace haloplot
