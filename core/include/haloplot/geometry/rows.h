// Plot rows against positions along an edge, exactly: which side of row y a Q0.32 position
// lies on, and the positions an edge has in a range of rows. The band conductor decides with
// them which band owns a piece (band/band_rule.h); CUT and the solids' hidden-line run use them
// to work inside one band's rows.
//
// y(t) = ya + dy t / 2^32 is compared with a row exactly: ya 2^32 (52 bits) + dy t (53 bits)
// - y 2^32 (y within 2^21: 53 bits) < 2^55.
#pragma once
#include <stdint.h>

#include "haloplot/geometry/contract.h"
#include "haloplot/geometry/fraction.h"

namespace haloplot {

// Rows within this distance of the coordinate range are all a band ever asks about.
inline constexpr int64_t kBandRowLimit = int64_t{1} << (kCoordBits + 1);
static_assert(int64_t{kCoordMax} * kFracOne + int64_t{kCoordMax} * kFracOne +
                      kBandRowLimit * kFracOne <
                  (int64_t{1} << 62),
              "row comparison must fit int64_t");

// Sign of y(t) - y for a position t (Q0.32, 0..2^32) along e and a row y (|y| < kBandRowLimit).
inline int row_compare(const Edge3& e, int64_t t32, int64_t y) {
  const int64_t v = (int64_t{e.a.y} - y) * kFracOne + int64_t{e.b.y - e.a.y} * t32;
  return (v > 0) - (v < 0);
}

// The positions of an edge in rows [y0, y1), as a half-open Q0.32 range [lo, hi) (lo == hi:
// none). Bands that cut an edge at their borders (solids: band windows) tile it exactly: the
// band above starts where this one ends, computed from the same row. A level edge is whole in
// the band that holds its row. (y - ya) 2^32 fits 54 bits.
struct RowWindow {
  int64_t lo, hi;
};
inline int64_t clamp_position(int64_t t) { return t < 0 ? 0 : (t > kFracOne ? kFracOne : t); }
inline RowWindow row_window(const Edge3& e, int64_t y0, int64_t y1) {
  const int64_t dy = int64_t{e.b.y} - e.a.y;
  if (dy == 0) return e.a.y >= y0 && e.a.y < y1 ? RowWindow{0, kFracOne} : RowWindow{0, 0};
  // Rising: the first position at or above row y is ceil((y - ya) 2^32 / dy). Falling: the
  // first one below row y is floor((ya - y) 2^32 / -dy) + 1.
  auto first_at = [&](int64_t y) {
    return clamp_position(dy > 0 ? -floor_div((e.a.y - y) * kFracOne, dy)
                                 : floor_div((e.a.y - y) * kFracOne, -dy) + 1);
  };
  const int64_t a = first_at(y0), b = first_at(y1);
  return dy > 0 ? RowWindow{a, b} : RowWindow{b, a};
}

// Does position t (Q0.32) of e lie in rows [y0, y1)? The same as row_window(e, y0, y1) holding t.
inline bool position_in_rows(const Edge3& e, int64_t t32, int64_t y0, int64_t y1) {
  return row_compare(e, t32, y0) >= 0 && row_compare(e, t32, y1) < 0;
}

}  // namespace haloplot
