// The face grid against a brute-force reference: every face listed, in ascending order, in
// exactly the cells whose square [ox + i cell, ox + (i + 1) cell) x [oy + j cell, ...) meets
// the face's bounding box, found by testing every cell of the grid against every box (no
// column or row arithmetic); the count the sizing query makes is the number of those
// (cell, face) pairs, and the grid builds in exactly the bytes the query asks for. However
// large the faces, those pairs are at most kFaceGridPairsPerFace a face, and a scene of small
// faces keeps the grid of about one face per cell.
#include <algorithm>
#include <random>
#include <vector>

#include "../check.h"
#include "haloplot/solid/face_grid.h"

using namespace haloplot;

namespace {

// The faces of each cell, the reference way.
std::vector<std::vector<uint32_t>> reference_cells(const std::vector<Point3>& v,
                                                   const std::vector<Triangle>& t, const Grid& g) {
  std::vector<std::vector<uint32_t>> cells(g.cells());
  for (uint32_t f = 0; f < t.size(); ++f) {
    int64_t x0 = INT64_MAX, y0 = INT64_MAX, x1 = INT64_MIN, y1 = INT64_MIN;
    for (uint32_t k : t[f].v) {
      x0 = std::min<int64_t>(x0, v[k].x), x1 = std::max<int64_t>(x1, v[k].x);
      y0 = std::min<int64_t>(y0, v[k].y), y1 = std::max<int64_t>(y1, v[k].y);
    }
    for (uint32_t j = 0; j < g.ny; ++j)
      for (uint32_t i = 0; i < g.nx; ++i) {
        const int64_t cx = g.ox + int64_t{i} * g.cell, cy = g.oy + int64_t{j} * g.cell;
        if (x1 >= cx && x0 < cx + g.cell && y1 >= cy && y0 < cy + g.cell)
          cells[j * g.nx + i].push_back(f);
      }
  }
  return cells;
}

// The grid's cells and pairs (its lists lie in a buffer freed on return).
FaceGrid check_scene(const std::vector<Point3>& v, const std::vector<Triangle>& t) {
  Topology topo;
  topo.vertices = v.data();
  topo.n_vertices = uint32_t(v.size());
  topo.triangles = t.data();
  topo.n_triangles = uint32_t(t.size());
  const size_t bytes = face_grid_bytes(topo);
  std::vector<uint64_t> buffer(bytes / 8 + 1);
  FaceGrid fg;
  CHECK(build_face_grid(topo, buffer.data(), bytes, &fg) == Status::kOk);
  const std::vector<std::vector<uint32_t>> want = reference_cells(v, t, fg.grid);
  size_t pairs = 0;
  for (const std::vector<uint32_t>& c : want) pairs += c.size();
  CHECK_EQ(size_t{fg.pairs}, pairs);
  CHECK(pairs <= size_t{kFaceGridPairsPerFace} * t.size());
  // The query asks for the index and the pairs, no more: a byte short of that is refused.
  CHECK(bytes <= (size_t{fg.grid.cells()} + 1) * 4 + pairs * 4 + 16);
  CHECK(build_face_grid(topo, buffer.data(), (size_t{fg.grid.cells()} + 1) * 4 + pairs * 4 - 1,
                        &fg) == Status::kWorkspaceTooSmall);
  CHECK(build_face_grid(topo, buffer.data(), bytes, &fg) == Status::kOk);
  for (uint32_t c = 0; c < fg.grid.cells(); ++c) {
    const std::vector<uint32_t> got(fg.faces + fg.first[c], fg.faces + fg.first[c + 1]);
    CHECK(got == want[c]);
  }
  return fg;
}

// Pairs of the brute-force reference in the grid of about one face per cell (per axis
// isqrt(n) + 1 along the longer side), the grid every scene had before the bound.
size_t pairs_in_fine_grid(const std::vector<Point3>& v, const std::vector<Triangle>& t) {
  uint32_t per_axis = 0;
  while (uint64_t{per_axis + 1} * (per_axis + 1) <= t.size()) ++per_axis;
  const Grid g = grid_over(v.data(), uint32_t(v.size()), per_axis + 1);
  size_t pairs = 0;
  for (const std::vector<uint32_t>& c : reference_cells(v, t, g)) pairs += c.size();
  return pairs;
}

// Long slivers fanned across a square, as a model's thin faces seen edge-on do: in cells of
// about one face each every face meets dozens of them, so the cells grow (and the grid stays
// exact); a fine mesh of small faces, within the bound, keeps its cells of one face each.
void large_faces() {
  std::vector<Point3> v;
  std::vector<Triangle> t;
  const int32_t side = 1 << 16;
  for (uint32_t k = 0; k < 400; ++k) {
    const int32_t x = int32_t(k * 163 % 397) * (side / 397);
    const int32_t y = int32_t(k * 89 % 389) * (side / 389);
    const uint32_t a = uint32_t(v.size());
    v.push_back(Point3{x, 0, 0});
    v.push_back(Point3{x + 37, 0, 0});
    v.push_back(Point3{side - x, side, 0});
    v.push_back(Point3{0, y, 0});
    v.push_back(Point3{side, side - y, 0});
    v.push_back(Point3{0, y + 41, 0});
    t.push_back(Triangle{{a, a + 1, a + 2}, 2 * k});
    t.push_back(Triangle{{a + 3, a + 4, a + 5}, 2 * k + 1});
  }
  CHECK(pairs_in_fine_grid(v, t) > size_t{4 * kFaceGridPairsPerFace} * t.size());
  check_scene(v, t);

  std::vector<Point3> fine;
  std::vector<Triangle> small;
  const uint32_t m = 30;  // (m - 1)^2 squares, two faces each
  for (uint32_t j = 0; j < m; ++j)
    for (uint32_t i = 0; i < m; ++i) fine.push_back(Point3{int32_t(i * 100), int32_t(j * 100), 0});
  for (uint32_t j = 0; j + 1 < m; ++j)
    for (uint32_t i = 0; i + 1 < m; ++i) {
      const uint32_t a = j * m + i;
      small.push_back(Triangle{{a, a + 1, a + m + 1}, uint32_t(small.size())});
      small.push_back(Triangle{{a, a + m + 1, a + m}, uint32_t(small.size())});
    }
  uint32_t per_axis = 0;
  while (uint64_t{per_axis + 1} * (per_axis + 1) <= small.size()) ++per_axis;
  const FaceGrid fg = check_scene(fine, small);
  CHECK_EQ(fg.grid.cell, grid_over(fine.data(), uint32_t(fine.size()), per_axis + 1).cell);
}

void random_scenes() {
  std::mt19937 rng(5);
  for (int scene = 0; scene < 40; ++scene) {
    // Small and large spans, so faces range from inside one cell to across the whole grid.
    const int32_t span = scene % 4 == 0 ? 8 : (scene % 4 == 1 ? 400 : 200000);
    std::uniform_int_distribution<int32_t> coord(1000, 1000 + span);
    std::vector<Point3> v(30 + scene * 7);
    for (Point3& p : v) p = Point3{coord(rng), coord(rng), coord(rng)};
    std::uniform_int_distribution<uint32_t> pick(0, uint32_t(v.size()) - 1);
    std::vector<Triangle> t(20 + scene * 11);
    for (uint32_t f = 0; f < t.size(); ++f) {
      t[f] = Triangle{{pick(rng), pick(rng), pick(rng)}, f};
      if (f % 9 == 0) t[f].v[2] = t[f].v[1];  // degenerate: a segment, then a point
      if (f % 27 == 0) t[f].v[1] = t[f].v[0];
    }
    check_scene(v, t);
  }
}

// By hand: a 10 x 10 square of vertices, two faces, the grid 2 x 2 cells of side 5 (per axis
// isqrt(2) + 1 = 2). The first face's box [0, 4] x [0, 9] meets the left column only; the
// second's, [0, 9] x [5, 9], the top row; a box ending on x = 5 would reach the right column.
void by_hand() {
  const std::vector<Point3> v = {{0, 0, 0}, {4, 9, 0}, {9, 9, 0}, {0, 5, 0}, {9, 0, 0}};
  const std::vector<Triangle> t = {{{0, 1, 3}, 0}, {{3, 1, 2}, 1}};
  check_scene(v, t);
  Topology topo;
  topo.vertices = v.data();
  topo.n_vertices = uint32_t(v.size());
  topo.triangles = t.data();
  topo.n_triangles = uint32_t(t.size());
  std::vector<uint64_t> buffer(face_grid_bytes(topo) / 8 + 1);
  FaceGrid fg;
  CHECK(build_face_grid(topo, buffer.data(), buffer.size() * 8, &fg) == Status::kOk);
  CHECK(fg.grid.nx == 2 && fg.grid.ny == 2 && fg.grid.cell == 5);
  CHECK_EQ(fg.pairs, 4u);  // face 0: cells 0 and 2; face 1: cells 2 and 3
}

}  // namespace

int main() {
  random_scenes();
  large_faces();
  by_hand();
  return check::finish("face_grid");
}
