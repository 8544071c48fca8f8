// The band rule: which band owns a visible piece, decided exactly.
//
// A band is a half-open range of plot rows [y0, y1). A visible piece of an edge belongs to the
// band that holds its upper end (the end with the larger y; either end of a level piece), so
// each piece has exactly one owner, the same half-open rule CUT uses for grid cells. A piece
// that reaches past y1 is carried up: the band above draws it whole, from the lower end this
// band saw, so a piece is never split at a border and the banded plot is the unbanded one.
//
// Positions along an edge are DRAW's Q0.32 fractions, compared with rows exactly
// (geometry/rows.h).
#pragma once
#include <stdint.h>

#include "geometry/contract.h"
#include "geometry/fraction.h"
#include "geometry/rows.h"

namespace haloplot {

// The rows an edge covers, inclusive.
inline int32_t edge_row_min(const Edge3& e) { return e.a.y < e.b.y ? e.a.y : e.b.y; }
inline int32_t edge_row_max(const Edge3& e) { return e.a.y < e.b.y ? e.b.y : e.a.y; }

// Does the edge reach any row of [lo, hi] (inclusive)?
inline bool edge_meets_rows(const Edge3& e, int64_t lo, int64_t hi) {
  return edge_row_max(e) >= lo && edge_row_min(e) <= hi;
}

// The piece [t0, t1] of e (t0 < t1): its lower end and upper end in y. A level edge's t0 is
// its lower end, so level pieces are never carried.
inline bool rising(const Edge3& e) { return e.b.y >= e.a.y; }
inline int64_t lower_end(const Edge3& e, int64_t t0, int64_t t1) { return rising(e) ? t0 : t1; }
inline int64_t upper_end(const Edge3& e, int64_t t0, int64_t t1) { return rising(e) ? t1 : t0; }

}  // namespace haloplot
