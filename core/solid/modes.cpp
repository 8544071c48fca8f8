#include "haloplot/solid/modes.h"

#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/quarter_turn.h"
#include "haloplot/geometry/wide.h"

namespace haloplot {

int64_t paper_length(const Edge3& e) {
  const int64_t dx = e.b.x - e.a.x, dy = e.b.y - e.a.y;
  const int64_t l = isqrt_u64(static_cast<uint64_t>(dx * dx + dy * dy));
  return l > 0 ? l : 1;
}

int page_dash_ranges(const Edge3& e, int64_t t0, int64_t t1, const StrokeStyle& style,
                     int64_t ranges[kPageDashes][2]) {
  // (v - ca) 2^32 for page coordinates below 2^kCoordBits: one int64.
  static_assert(kCoordBits + 1 + 32 < 63, "a page coordinate's parameter fits in int64");
  const Edge3 p = style.turned ? unturn_edge(e) : e;
  const int64_t dx = int64_t{p.b.x} - p.a.x, dy = int64_t{p.b.y} - p.a.y;
  const bool along_x = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
  const int64_t ca = along_x ? p.a.x : p.a.y, cb = along_x ? p.b.x : p.b.y;
  if (ca == cb) return 0;  // a point on paper
  const int64_t period = int64_t{style.dash} + style.gap;
  constexpr int64_t kOneT = int64_t{1} << 32;  // t = 1 in Q0.32
  const int64_t lo = ca < cb ? ca : cb, hi = ca < cb ? cb : ca;
  const int64_t k0 = floor_div(lo, period), k1 = floor_div(hi, period);
  int n = 0;
  // Windows in the order t runs: c ascending when the edge runs up its axis.
  for (int64_t i = 0; i <= k1 - k0 && n < kPageDashes; ++i) {
    const int64_t k = ca < cb ? k0 + i : k1 - i;
    int64_t w0 = k * period, w1 = w0 + style.dash;
    w0 = w0 < lo ? lo : w0;
    w1 = w1 > hi ? hi : w1;
    if (w1 <= w0) continue;
    // * 2^32, not << 32: w - ca is negative on an edge running down its axis.
    int64_t a = (w0 - ca) * kOneT / (cb - ca), b = (w1 - ca) * kOneT / (cb - ca);
    if (b < a) {
      const int64_t u = a;
      a = b;
      b = u;
    }
    a = a < t0 ? t0 : a;
    b = b > t1 ? t1 : b;
    if (b <= a) continue;
    ranges[n][0] = a;
    ranges[n][1] = b;
    ++n;
  }
  return n;
}

}  // namespace haloplot
