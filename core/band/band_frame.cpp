// A solid banded in the page turned a quarter (BandSpec::turn_wide, geometry/quarter_turn.h):
// the conductor reads the model's vertices turned, works in that frame throughout (rows, the
// carry, the columns of the pen path), and turns each point back before it leaves. Strokes
// are rounded in the page's frame (band_attempt.h frame_point; round_to_steps below), so a
// turned plot's steps are the page's, not a rounding of its turned points.
#include "band/band_attempt.h"
#include "haloplot/band/conductor.h"

namespace haloplot {

Status BandConductor::solid_vertex(uint32_t index, Point3* out) const {
  const Status s = solid_.vertex(solid_.ctx, index, out);
  if (ok(s) && turned_) *out = turn_point(*out);
  return s;
}

Segment2 BandConductor::page_segment(const Segment2& g) const {
  if (!turned_) return g;
  const Point3 a = unturn_point(Point3{g.x0, g.y0, 0}), b = unturn_point(Point3{g.x1, g.y1, 0});
  return Segment2{a.x, a.y, b.x, b.y};
}

// A column's segments (band-frame units) to steps: turned back to the page, rounded there,
// then turned in steps (the offset turn_steps(): any whole number keeps the turn exact).
void BandConductor::steps_to_band(Segment2* g, uint32_t n) const {
  for (uint32_t i = 0; i < n; ++i) g[i] = page_segment(g[i]);
  round_to_steps(g, n, spec_.substep_bits);
  if (!turned_) return;
  const int32_t c = turn_steps();
  for (uint32_t i = 0; i < n; ++i) g[i] = Segment2{g[i].y0, c - g[i].x0, g[i].y1, c - g[i].x1};
}

void BandConductor::steps_to_page(PathPoint* p, uint32_t n) const {
  if (!turned_) return;
  const int32_t c = turn_steps();
  for (uint32_t i = 0; i < n; ++i) {
    const int32_t x = c - p[i].y, y = p[i].x;
    p[i].x = x;
    p[i].y = y;
  }
}

}  // namespace haloplot
