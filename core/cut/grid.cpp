#include "haloplot/cut/grid.h"

#include "haloplot/geometry/product.h"
#include "haloplot/geometry/wide.h"

namespace haloplot {

#if UINTPTR_MAX > 0xffffffffu
namespace {

// floor(sqrt(v)) for v < 2^62 by the bit-pair method, as isqrt_u64, but each step decided
// without a branch: the steps go either way about equally often, so a branch per step would
// mispredict about half of them. A 64-bit target's (where 64-bit operations are one
// instruction); tests/unit/test_cut_grid checks it by the root's definition.
static_assert(2 * kDiffBits + 1 <= 62, "a squared length must fit the root's 62 bits");
uint32_t root_without_branches(uint64_t v) {
  uint64_t root = 0, rem = 0;
  for (int shift = v == 0 ? -2 : (63 - __builtin_clzll(v)) & ~1; shift >= 0; shift -= 2) {
    rem = (rem << 2) | ((v >> shift) & 3u);
    const uint64_t trial = (root << 2) | 1u;
    const uint64_t take = uint64_t(rem >= trial);
    rem -= trial & (0 - take);
    root = (root << 1) | take;
  }
  return static_cast<uint32_t>(root);
}

}  // namespace
#endif

uint32_t projected_length(const Edge3& e) {
  const int32_t dx = e.b.x - e.a.x, dy = e.b.y - e.a.y;
  const uint64_t squared = static_cast<uint64_t>(mul_narrow<kDiffBits, kDiffBits>(dx, dx) +
                                                 mul_narrow<kDiffBits, kDiffBits>(dy, dy));
#if UINTPTR_MAX > 0xffffffffu
  return root_without_branches(squared);
#else
  return isqrt_u64(squared);
#endif
}

uint32_t average_length(const Edge3* edges, uint32_t n) {
  if (n == 0) return 0;
  const uint32_t stride = length_stride(n);
  uint64_t sum = 0, count = 0;  // at most 2^32 lengths below 2^21: fits in 53 bits
  for (uint32_t i = 0; i < n; i += stride, ++count) sum += projected_length(edges[i]);
  return static_cast<uint32_t>(sum / count);
}

namespace {

uint32_t cells_for(int32_t width, int32_t height, int32_t cell) {
  const uint64_t nx = static_cast<uint64_t>((width + cell - 1) / cell);
  const uint64_t ny = static_cast<uint64_t>((height + cell - 1) / cell);
  const uint64_t total = nx * ny;
  return total > 0xffffffffu ? 0xffffffffu : static_cast<uint32_t>(total);
}

}  // namespace

Grid choose_grid(const Edge3* edges, uint32_t n, const GridParams& params) {
  if (n == 0) return Grid{};
  Extent x;
  for (uint32_t i = 0; i < n; ++i) x.add(edges[i]);
  return grid_for(x, n, params.cell <= 0 ? average_length(edges, n) : 0, params);
}

Grid grid_for(const Extent& x, uint32_t n, uint32_t average, const GridParams& params) {
  Grid g;
  const int32_t xmin = x.xmin, ymin = x.ymin;
  const int32_t width = x.xmax - xmin + 1, height = x.ymax - ymin + 1;
  int32_t cell = params.cell;
  if (cell <= 0) {
    // Paper C2: G = lambda * L. lambda is Q8.8; the product fits easily in 64 bits.
    const uint64_t side = (uint64_t{average} * params.lambda_q8) >> 8;
    cell = side < 1 ? 1
                    : (side > static_cast<uint64_t>(kCoordLimit) ? kCoordLimit
                                                                 : static_cast<int32_t>(side));
  }
  // Cap the cell count so the per-cell index stays linear in N. Coarsening the grid keeps
  // CUT correct; it only adds pair tests in crowded cells.
  const uint64_t cap64 = params.max_cells ? params.max_cells : 2ull * n + 64;
  const uint32_t cap = cap64 > 0x7fffffffu ? 0x7fffffffu : static_cast<uint32_t>(cap64);
  while (cells_for(width, height, cell) > cap) {
    // Grow by about 1/8 per step: close to the largest grid that fits the cap.
    cell += cell / 8 + 1;
  }
  if (cell > kCoordLimit) cell = kCoordLimit;  // one cell covers the whole range already
  g.ox = xmin;
  g.oy = ymin;
  g.set_cell(cell);
  g.nx = static_cast<uint32_t>((width + cell - 1) / cell);
  g.ny = static_cast<uint32_t>((height + cell - 1) / cell);
  return g;
}

}  // namespace haloplot
