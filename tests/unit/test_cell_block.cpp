// cells_in_block() (cut/grid.h), CUT's branch-free walk for edges inside a 2 x 2 block of
// cells, against for_each_cell(), the walk it stands in for: the same cells, each once, for
// every edge it accepts, under both covers and with reach; and it accepts exactly the edges
// whose cells lie in a 2 x 2 block. Edges are drawn near grid lines and corners, where the
// exact cover's row at the column border is decided, and vertical, horizontal and
// zero-length ones too.
#include <algorithm>
#include <string>
#include <vector>

#include "../check.h"
#include "../support/scenes.h"
#include "haloplot/cut/grid.h"

using namespace haloplot;

namespace {

// A coordinate inside [lo, hi], near a grid line of g half the time.
int32_t near_line(scenes::Rng& r, int32_t origin, int32_t cell, uint32_t lines, int32_t lo,
                  int32_t hi) {
  int64_t v = r.uniform(lo, hi);
  if (r.uniform(0, 1) == 0) v = origin + int64_t{cell} * r.uniform(0, lines) + r.uniform(-2, 2);
  return int32_t(std::min<int64_t>(std::max<int64_t>(v, lo), hi));
}

void check_edge(const Grid& g, const Edge3& e, CellCover cover, int32_t reach,
                const std::string& what) {
  std::vector<uint32_t> walked;
  for_each_cell(g, e, cover, reach, [&](uint32_t c) { walked.push_back(c); });
  std::sort(walked.begin(), walked.end());
  CellBlock b;
  const bool accepted = cells_in_block(g, e, cover, reach, &b);
  // for_each_cell() visits a 2 x 2 block at most: its columns and rows are the box's.
  uint32_t c_lo = g.nx, c_hi = 0, r_lo = g.ny, r_hi = 0;
  for (uint32_t c : walked) {
    c_lo = std::min(c_lo, c % g.nx), c_hi = std::max(c_hi, c % g.nx);
    r_lo = std::min(r_lo, c / g.nx), r_hi = std::max(r_hi, c / g.nx);
  }
  CHECK_MSG(accepted == (c_hi - c_lo <= 1 && r_hi - r_lo <= 1), what + ": accepted");
  if (!accepted) return;
  std::vector<uint32_t> block;
  for (int q = 0; q < 4; ++q) {
    CHECK_MSG(b.weight[q] <= 1 && b.cell[q] < g.cells(), what + ": weight or cell");
    if (b.weight[q] == 1) block.push_back(b.cell[q]);
  }
  std::sort(block.begin(), block.end());
  CHECK_MSG(block == walked, what + ": cells");
}

}  // namespace

int main() {
  scenes::Rng r(7);
  const int32_t sides[] = {1, 3, 64, 1000, 8191, 30000, 1 << 20};
  for (int32_t side : sides) {
    Grid g;
    g.ox = int32_t(r.uniform(0, 500));
    g.oy = int32_t(r.uniform(0, 500));
    g.set_cell(side);
    // At most 2^10 cells a side (CUT's grids keep the cell index within 32 bits).
    const int32_t span = int32_t(std::min<int64_t>(int64_t{side} << 10, kCoordMax - 500));
    g.nx = g.divide(uint32_t(span)) + 1;
    g.ny = g.nx;
    const int32_t x_hi = g.ox + span, y_hi = g.oy + span;
    for (int k = 0; k < 20000; ++k) {
      Edge3 e;
      e.a = Point3{near_line(r, g.ox, side, g.nx, g.ox, x_hi),
                   near_line(r, g.oy, side, g.ny, g.oy, y_hi), 0};
      const int64_t len = r.uniform(0, 3) == 0 ? r.uniform(0, 3) : r.uniform(0, 2 * int64_t{side});
      auto clamp = [](int64_t v, int32_t lo, int32_t hi) {
        return int32_t(std::min<int64_t>(std::max<int64_t>(v, lo), hi));
      };
      e.b = Point3{clamp(e.a.x + r.uniform(-len, len), g.ox, x_hi),
                   clamp(e.a.y + r.uniform(-len, len), g.oy, y_hi), 0};
      if (k % 7 == 0) e.b.x = e.a.x;   // vertical
      if (k % 11 == 0) e.b.y = e.a.y;  // horizontal
      const std::string what = "side " + std::to_string(side) + " edge " + std::to_string(k);
      check_edge(g, e, CellCover::kExact, 0, what + " exact");
      check_edge(g, e, CellCover::kBoundingBox, 0, what + " box");
      check_edge(g, e, CellCover::kExact, int32_t(r.uniform(1, side)), what + " reach");
    }
  }
  return check::finish("cell_block");
}
