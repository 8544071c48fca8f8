// CUT's grid choice measures the scene's edges by their projected lengths, floor of the exact
// root: on a host without a branch per step (cut/grid.cpp). Each length is checked by the
// root's definition, r^2 <= dx^2 + dy^2 < (r + 1)^2, in unsigned __int128: on the lengths of
// the range's ends, on both sides of every perfect square up to 2^21, and on random edges.
#include <cstdint>
#include <vector>

#include "../check.h"
#include "haloplot/cut/grid.h"

using namespace haloplot;

namespace {

bool is_floor_root(uint32_t r, int64_t dx, int64_t dy) {
  const unsigned __int128 v = (unsigned __int128)(dx * dx) + (unsigned __int128)(dy * dy);
  const unsigned __int128 lo = (unsigned __int128)r * r, hi = (unsigned __int128)(r + 1) * (r + 1);
  return lo <= v && v < hi;
}

// An edge from (x0, 0) to (x0 + dx, dy), its ends inside the range.
Edge3 edge(int32_t dx, int32_t dy) {
  const int32_t x0 = dx < 0 ? -dx : 0, y0 = dy < 0 ? -dy : 0;
  return Edge3{{x0, y0, 0}, {x0 + dx, y0 + dy, 0}};
}

void check_length(int32_t dx, int32_t dy) {
  const uint32_t r = projected_length(edge(dx, dy));
  CHECK_MSG(is_floor_root(r, dx, dy), "projected_length(" + std::to_string(dx) + ", " +
                                          std::to_string(dy) + ") = " + std::to_string(r));
}

}  // namespace

int main() {
  // The ends of the range: no length, one step, the longest edge on an axis and on the diagonal.
  const int32_t m = kCoordMax;
  for (int32_t dx : {0, 1, -1, 2, 3, m, -m, m - 1})
    for (int32_t dy : {0, 1, -1, 2, 3, m, -m, m - 1}) check_length(dx, dy);
  // Along an axis the squared length is a perfect square: the root is |dx| exactly; one step
  // across makes it one more than a square, which must still floor to |dx|.
  for (int32_t d = 0; d <= m; d += d < 4096 ? 1 : 97) {
    check_length(d, 0);
    check_length(d, 1);
    check_length(0, -d);
  }
  // Just below a perfect square s^2: the largest v = dx^2 + dy^2 under it floors to s - 1.
  // dx = s - 1 and dy with dy^2 <= 2s - 2 lies at most 2s - 2 above (s - 1)^2 = s^2 - 2s + 1.
  for (int32_t s = 2; s <= m; s += s < 4096 ? 1 : 89) {
    int32_t dy = 0;
    while (int64_t{dy + 1} * (dy + 1) <= 2 * int64_t{s} - 2) ++dy;
    check_length(s - 1, dy);
  }
  // Random edges over the range (a fixed linear congruential sequence).
  uint64_t state = 12345;
  auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return int32_t((state >> 33) % (2 * uint64_t(m) + 1)) - m;
  };
  for (int i = 0; i < 200000; ++i) check_length(next(), next());
  return check::finish("cut_grid");
}
