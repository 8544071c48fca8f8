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

#include "haloplot/geometry/contract.h"
#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/rows.h"
#include "haloplot/solid/mesh.h"
#include "haloplot/status/status.h"

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

// Does the triangle reach any row of [lo, hi] (inclusive)?
inline bool triangle_meets_rows(const Point3& a, const Point3& b, const Point3& c, int64_t lo,
                                int64_t hi) {
  const int32_t y_min = a.y < b.y ? (a.y < c.y ? a.y : c.y) : (b.y < c.y ? b.y : c.y);
  const int32_t y_max = a.y > b.y ? (a.y > c.y ? a.y : c.y) : (b.y > c.y ? b.y : c.y);
  return y_max >= lo && y_min <= hi;
}

// The faces a solid's band holds, in scene order: those meeting its rows (read(i, &t, &meets)
// says whether triangle i does), and with `whole_polygons` every triangle of a polygon (a run
// of consecutive triangles with one id) that one of them belongs to: hatching reads the whole
// polygon for its lines' direction. take(i, t) for each; the host that streams a band and the
// conductor that gathers it ask this one rule.
template <typename Read, typename Take>
Status for_band_triangles(uint32_t n, bool whole_polygons, Read read, Take take) {
  uint32_t i = 0;
  while (i < n) {
    Triangle t;
    bool meets = false;
    Status s = read(i, &t, &meets);
    if (!ok(s)) return s;
    if (!whole_polygons) {
      if (meets) take(i, t);
      ++i;
      continue;
    }
    uint32_t end = i + 1;
    bool any = meets;
    for (; end < n; ++end) {
      Triangle u;
      bool m = false;
      s = read(end, &u, &m);
      if (!ok(s)) return s;
      if (u.polygon != t.polygon) break;
      any = any || m;
    }
    for (uint32_t k = i; any && k < end; ++k) {
      s = k == i ? Status::kOk : read(k, &t, &meets);
      if (!ok(s)) return s;
      take(k, t);
    }
    i = end;
  }
  return Status::kOk;
}

}  // namespace haloplot
