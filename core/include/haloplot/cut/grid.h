// CUT's adaptive uniform grid (paper C2-C3). Cells are squares of side `cell` steps laid
// from the scene's lower-left corner. They partition the plane exactly: a point belongs to
// column floor((x - ox) / cell) and row floor((y - oy) / cell), so a vertical grid line lies in
// the cell to its right and a horizontal one in the cell above it, as the paper requires.
#pragma once
#include <stdint.h>

#include "haloplot/geometry/contract.h"
#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/product.h"

namespace haloplot {

enum class CellCover : uint8_t {
  kExact,        // the cells the segment passes through, column by column (default)
  kBoundingBox,  // every cell of the segment's bounding box: the paper's shortcut; costs more
                 // (cell, edge) pairs and so more pair tests on long diagonal edges
};

struct Grid {
  int32_t ox = 0, oy = 0;  // lower-left corner of cell (0, 0), in steps
  int32_t cell = 1;        // side of a cell, in steps, at most 2^20
  uint32_t nx = 1, ny = 1;
  // floor(v / cell) as (v * reciprocal) >> 42 with reciprocal = ceil(2^42 / cell): a multiply
  // instead of a division in the hottest loops. Exact for 0 <= v < 2^21: the product exceeds
  // v / cell by v * e / 2^42 < 2^-21 (0 <= e < 1), less than the 1 / cell that a quotient
  // needs to move, since cell <= 2^20; and v * reciprocal < 2^21 * 2^42 fits 64 bits.
  // tests/unit/test_numeric checks every boundary for many cell sides.
  uint64_t reciprocal = uint64_t{1} << 42;

  void set_cell(int32_t side) {
    cell = side;
    reciprocal = ((uint64_t{1} << 42) + uint64_t(side) - 1) / uint64_t(side);
  }
  uint32_t divide(uint32_t v) const {
    return static_cast<uint32_t>(mul_u32x64(v, reciprocal) >> 42);
  }
  uint32_t cells() const { return nx * ny; }
  uint32_t col(int32_t x) const { return divide(static_cast<uint32_t>(x - ox)); }
  uint32_t row(int32_t y) const { return divide(static_cast<uint32_t>(y - oy)); }
  uint32_t cell_of(int32_t x, int32_t y) const { return row(y) * nx + col(x); }
};

inline int32_t min_i32(int32_t a, int32_t b) { return a < b ? a : b; }
inline int32_t max_i32(int32_t a, int32_t b) { return a > b ? a : b; }

// A grid over the points' bounding box with about `per_axis` square cells along its longer
// side (at least one step each): the vertex, face and Franklin grids of the hidden-line stages.
inline Grid grid_over(const Point3* p, uint32_t n, uint32_t per_axis) {
  int32_t x0 = kCoordMax, y0 = kCoordMax, x1 = 0, y1 = 0;
  for (uint32_t v = 0; v < n; ++v) {
    x0 = min_i32(x0, p[v].x);
    y0 = min_i32(y0, p[v].y);
    x1 = max_i32(x1, p[v].x);
    y1 = max_i32(y1, p[v].y);
  }
  if (n == 0) x0 = y0 = x1 = y1 = 0;
  if (per_axis < 1) per_axis = 1;
  const uint32_t extent = static_cast<uint32_t>(max_i32(x1 - x0, y1 - y0)) + 1;
  Grid g;
  g.ox = x0;
  g.oy = y0;
  g.set_cell(max_i32(1, static_cast<int32_t>((extent + per_axis - 1) / per_axis)));
  g.nx = g.divide(static_cast<uint32_t>(x1 - x0)) + 1;
  g.ny = g.divide(static_cast<uint32_t>(y1 - y0)) + 1;
  return g;
}

// The columns [c0, c1] and rows [r0, r1] of a segment's bounding box from x0 <= x1, dilated by
// `reach` and clamped to the grid: where for_each_cell() and cells_in_block() both start.
struct CellSpan {
  uint32_t c0, c1, r0, r1;
};
__attribute__((always_inline)) inline CellSpan cell_span(const Grid& g, int32_t x0, int32_t y0,
                                                         int32_t x1, int32_t y1, int32_t reach) {
  const int32_t xmax_scene = g.ox + static_cast<int32_t>(g.nx) * g.cell - 1;
  const int32_t ymax_scene = g.oy + static_cast<int32_t>(g.ny) * g.cell - 1;
  return CellSpan{g.col(max_i32(x0 - reach, g.ox)), g.col(min_i32(x1 + reach, xmax_scene)),
                  g.row(max_i32(min_i32(y0, y1) - reach, g.oy)),
                  g.row(min_i32(max_i32(y0, y1) + reach, ymax_scene))};
}

// Visit every cell the projection of `e` may touch, calling visit(cell_index). `reach` > 0
// dilates the bounding box by that many steps (used when CUT also records near misses) and
// implies the bounding-box cover. Every point of the segment lies in a visited cell; a few
// extra cells may be visited, which costs time but never correctness (paper, notes on C3.1).
template <typename Visit>
void for_each_cell(const Grid& g, const Edge3& e, CellCover cover, int32_t reach, Visit visit) {
  int32_t x0 = e.a.x, y0 = e.a.y, x1 = e.b.x, y1 = e.b.y;
  if (x0 > x1) {  // walk columns left to right
    int32_t t = x0;
    x0 = x1;
    x1 = t;
    t = y0;
    y0 = y1;
    y1 = t;
  }
  const CellSpan span = cell_span(g, x0, y0, x1, y1, reach);
  const uint32_t c0 = span.c0, c1 = span.c1, r0 = span.r0, r1 = span.r1;
  // One column or one row: the bounding box is exact, and no division is needed.
  if (cover == CellCover::kBoundingBox || reach > 0 || c0 == c1 || r0 == r1) {
    for (uint32_t r = r0; r <= r1; ++r)
      for (uint32_t c = c0; c <= c1; ++c) visit(r * g.nx + c);
    return;
  }
  // Exact walk: in column c the segment spans x in [xl, xh]; y is monotone in x, so its rows
  // lie between the rows of y(xl) and y(xh). Using the closed column (xh on the boundary)
  // adds at most a cell the segment only touches at a grid corner: safe. Only the interior
  // column borders need a division: the ends are the endpoints themselves.
  const int64_t dx = x1 - x0, dy = y1 - y0;  // dx > 0 here, since c0 != c1
  int32_t ya = y0;                           // floor(y) where the segment enters column c
  for (uint32_t c = c0; c <= c1; ++c) {
    int32_t yb = y1;
    if (c != c1) {  // floor(y) on the border x = ox + (c + 1) * cell; |dy * (x - x0)| < 2^41
      const int64_t xh = g.ox + static_cast<int64_t>(c + 1) * g.cell;
      yb = y0 + static_cast<int32_t>(floor_div(dy * (xh - x0), dx));
    }
    const uint32_t lo = g.row(min_i32(ya, yb));
    const uint32_t hi = g.row(max_i32(ya, yb));
    for (uint32_t r = lo; r <= hi; ++r) visit(r * g.nx + c);
    ya = yb;
  }
}

// for_each_cell()'s cells when they lie in a 2 x 2 block of cells (most edges, when the cell
// side is about the edges' length), without a branch on the edge: the block's four cells, each
// with weight 1 where for_each_cell() visits it and 0 where not. Returns false, and writes
// nothing, for a larger block. The 2 x 2 exact case decides the row at the column border by a
// product comparison where for_each_cell() divides: floor(y0 + dy (X - x0) / dx) >= Y, with
// Y an integer and dx > 0, holds exactly when dy (X - x0) >= (Y - y0) dx (below 2^41 each).
static_assert(2 * kDiffBits <= 63, "the block's border comparison must fit int64_t");
struct CellBlock {
  uint32_t cell[4];
  uint32_t weight[4];
};
inline bool cells_in_block(const Grid& g, const Edge3& e, CellCover cover, int32_t reach,
                           CellBlock* out) {
  const bool swap = e.a.x > e.b.x;  // read left to right, as for_each_cell() does
  const int32_t x0 = swap ? e.b.x : e.a.x, y0 = swap ? e.b.y : e.a.y;
  const int32_t x1 = swap ? e.a.x : e.b.x, y1 = swap ? e.a.y : e.b.y;
  const CellSpan span = cell_span(g, x0, y0, x1, y1, reach);
  const uint32_t c0 = span.c0, c1 = span.c1, r0 = span.r0, r1 = span.r1;
  if (c1 - c0 > 1 || r1 - r0 > 1) return false;
  const uint32_t two_cols = c1 - c0, two_rows = r1 - r0;
  // The exact walk's row at the border x = X between the columns: r1 (k) or r0.
  const int64_t border_x = g.ox + static_cast<int64_t>(c1) * g.cell;
  const int64_t border_y = g.oy + static_cast<int64_t>(r1) * g.cell;
  const bool k = int64_t{y1 - y0} * (border_x - x0) >= (border_y - y0) * int64_t{x1 - x0};
  const bool rising = y0 < y1;
  // Rising, the walk takes (c0, r0), (c0, r1) if k, (c1, r0) if not, and (c1, r1); falling,
  // (c0, r1), (c0, r0) if not k, (c1, r1) if k, and (c1, r0).
  const bool exact = cover == CellCover::kExact && reach == 0 && two_cols != 0 && two_rows != 0;
  out->cell[0] = r0 * g.nx + c0;
  out->cell[1] = r0 * g.nx + c1;
  out->cell[2] = r1 * g.nx + c0;
  out->cell[3] = r1 * g.nx + c1;
  out->weight[0] = exact ? uint32_t(rising || !k) : 1u;
  out->weight[1] = exact ? uint32_t(!rising || !k) : two_cols;
  out->weight[2] = exact ? uint32_t(!rising || k) : two_rows;
  out->weight[3] = exact ? uint32_t(rising || k) : (two_cols & two_rows);
  return true;
}

struct GridParams {
  uint32_t lambda_q8 = 256;  // cell side = lambda * average projected length; Q8.8, 1.0 default
  int32_t cell = 0;          // > 0 forces the cell side in steps (benchmarks, tests)
  uint32_t max_cells = 0;    // 0: at most 2 * N + 64 cells, so the cell index stays O(N) bytes
};

// Choose the grid for a scene (paper C1-C2). Edges must already be range-checked.
Grid choose_grid(const Edge3* edges, uint32_t n, const GridParams& params);

// Average projected length in steps (floor), from exact integer square roots over a fixed
// stride sample of at most kLengthSample edges: the grid needs an estimate, not every edge.
inline constexpr uint32_t kLengthSample = 4096;
uint32_t average_length(const Edge3* edges, uint32_t n);

// choose_grid's halves, so a caller may gather the scene's extent and the sampled lengths in
// parts (CUT's plan on a host): the extent grows edge by edge, the lengths are exact, and
// grid_for gives the grid choose_grid gives for the same extent and average (n > 0).
struct Extent {
  int32_t xmin = kCoordMax, ymin = kCoordMax, xmax = 0, ymax = 0;
  void add(const Edge3& e) {
    xmin = min_i32(xmin, min_i32(e.a.x, e.b.x));
    xmax = max_i32(xmax, max_i32(e.a.x, e.b.x));
    ymin = min_i32(ymin, min_i32(e.a.y, e.b.y));
    ymax = max_i32(ymax, max_i32(e.a.y, e.b.y));
  }
};
inline uint32_t length_stride(uint32_t n) { return n > kLengthSample ? n / kLengthSample : 1; }
uint32_t projected_length(const Edge3& e);  // floor of the exact root
Grid grid_for(const Extent& x, uint32_t n, uint32_t average, const GridParams& params);

}  // namespace haloplot
