// A solid's lines across band borders (conductor.h): a band cuts its outlines, hatch lines,
// intersection lines and contour diagonals at its borders, and the band below defers its piece
// ending on the border (band_path.cpp defer_joined); here the band above joins it to its own piece
// starting there. Part of the solid stage (reached through SolidStage::join), so a program that
// plots edges in bands never links it (test lean_link).
#include "band/band_attempt.h"
#include "haloplot/band/conductor.h"
#include "haloplot/sort/lower_bound.h"
#include "sort/in_place_sort.h"

namespace haloplot {
namespace {

// An end of one of the band's own segments on its bottom border: where the piece deferred from
// below that the border cut off may go on.
struct BorderEnd {
  RowPoint p;
  uint32_t segment;
  uint32_t used;  // joined already: one join at each end
};

// Is P (the shared end) within two units of the stroke from a to b, and between them? Two
// pieces of one straight line that a border cut at P (rounded) are: then the joined stroke is
// the one the whole-model plot draws. |cross| <= 2 max(|dx|, |dy|) bounds the distance by two
// units (the Euclidean length is at least the larger side); coordinates below 2^21 keep the
// products below 2^44.
bool joins_in_line(const RowPoint& a, const RowPoint& p, const RowPoint& b) {
  const int64_t dx = int64_t{b.x} - a.x, dy = int64_t{b.y} - a.y;
  const int64_t px = int64_t{p.x} - a.x, py = int64_t{p.y} - a.y;
  const int64_t cross = dx * py - dy * px, side = (dx < 0 ? -dx : dx) > (dy < 0 ? -dy : dy)
                                                      ? (dx < 0 ? -dx : dx)
                                                      : (dy < 0 ? -dy : dy);
  const int64_t before = px * (int64_t{b.x} - p.x) + py * (int64_t{b.y} - p.y);
  return (cross < 0 ? -cross : cross) <= 2 * side && before > 0;
}

}  // namespace

// A solid's band cuts its outlines, hatch lines, intersection lines and contour diagonals at
// its borders, both bands at the same rounded point. The band below defers its piece ending on
// the border (defer_joined); here each such deferred segment that meets one of the band's own
// segments there, in line with it, becomes part of it: one stroke, the whole-model plot's, drawn
// without lifting the pen at the border. The merged deferred segments are dropped from u;
// returns how many segments are left. Workspace from `free`; too little room joins none.
uint32_t BandConductor::join_at_border(const Attempt& a, Segment2* u, uint32_t n_own, uint32_t nu,
                                       uint8_t* free) const {
  if (nu == n_own) return nu;
  BorderEnd* ends = reinterpret_cast<BorderEnd*>(align_up(free));
  const int32_t y0 = int32_t(a.y0);
  uint32_t n_ends = 0;
  for (uint32_t i = 0; i < n_own; ++i) n_ends += (u[i].y0 == y0 ? 1 : 0) + (u[i].y1 == y0 ? 1 : 0);
  if (reinterpret_cast<uint8_t*>(ends + n_ends) > arena_ + arena_bytes_) return nu;
  n_ends = 0;
  for (uint32_t i = 0; i < n_own; ++i) {
    if (u[i].y0 == y0) ends[n_ends++] = BorderEnd{RowPoint{u[i].x0, u[i].y0}, i, 0};
    if (u[i].y1 == y0) ends[n_ends++] = BorderEnd{RowPoint{u[i].x1, u[i].y1}, i, 0};
  }
  sort_in_place(ends, n_ends,
                [](const BorderEnd& p, const BorderEnd& q) { return point_less(p.p, q.p); });
  uint32_t kept = n_own;
  for (uint32_t j = n_own; j < nu; ++j) {
    const Segment2 d = u[j];
    bool merged = false;
    for (int side = 0; side < 2 && !merged; ++side) {
      const RowPoint p = side == 0 ? RowPoint{d.x0, d.y0} : RowPoint{d.x1, d.y1};
      const RowPoint far = side == 0 ? RowPoint{d.x1, d.y1} : RowPoint{d.x0, d.y0};
      if (p.y != y0) continue;
      const uint32_t lo =
          lower_bound_index(0, n_ends, [&](uint32_t i) { return point_less(ends[i].p, p); });
      for (uint32_t k = lo; k < n_ends && !merged && ends[k].p.x == p.x && ends[k].p.y == p.y;
           ++k) {
        Segment2& g = u[ends[k].segment];
        const bool at_start = g.x0 == p.x && g.y0 == p.y;
        if (ends[k].used || !(at_start || (g.x1 == p.x && g.y1 == p.y))) continue;
        const RowPoint other = at_start ? RowPoint{g.x1, g.y1} : RowPoint{g.x0, g.y0};
        if (!joins_in_line(far, p, other)) continue;
        g = Segment2{far.x, far.y, other.x, other.y};
        ends[k].used = 1;
        merged = true;
      }
    }
    if (!merged) u[kept++] = d;
  }
  return kept;
}

}  // namespace haloplot
