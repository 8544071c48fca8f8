// The face grid against a brute-force reference: every face listed, in ascending order, in
// exactly the cells whose square [ox + i cell, ox + (i + 1) cell) x [oy + j cell, ...) meets
// the face's bounding box, found by testing every cell of the grid against every box (no
// column or row arithmetic); the count the sizing query makes is the number of those
// (cell, face) pairs, and the grid builds in exactly the bytes the query asks for.
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

void check_scene(const std::vector<Point3>& v, const std::vector<Triangle>& t) {
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
  // The query asks for the index and the pairs, no more: a byte short of that is refused.
  CHECK(bytes <= (size_t{fg.grid.cells()} + 1) * 4 + pairs * 4 + 16);
  CHECK(build_face_grid(topo, buffer.data(), (size_t{fg.grid.cells()} + 1) * 4 + pairs * 4 - 1,
                        &fg) == Status::kWorkspaceTooSmall);
  CHECK(build_face_grid(topo, buffer.data(), bytes, &fg) == Status::kOk);
  for (uint32_t c = 0; c < fg.grid.cells(); ++c) {
    const std::vector<uint32_t> got(fg.faces + fg.first[c], fg.faces + fg.first[c + 1]);
    CHECK(got == want[c]);
  }
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
  by_hand();
  return check::finish("face_grid");
}
