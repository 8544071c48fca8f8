#include "motion/stroke_simplify.h"

#include <stdint.h>

#include "haloplot/geometry/wide.h"

namespace haloplot {
namespace {

constexpr int64_t kCoordLimit = int64_t{1} << kSimplifyCoordBits;

bool in_budget(const PathPoint& p) {
  return p.x > -kCoordLimit && p.x < kCoordLimit && p.y > -kCoordLimit && p.y < kCoordLimit;
}

// Is p within tol of the segment a-b (exactly)?
bool near_segment(const PathPoint& a, const PathPoint& b, const PathPoint& p, uint32_t tol) {
  const int64_t dx = int64_t{b.x} - a.x, dy = int64_t{b.y} - a.y;
  const int64_t vx = int64_t{p.x} - a.x, vy = int64_t{p.y} - a.y;
  const uint64_t tol2 = uint64_t{tol} * tol;
  const int64_t t = vx * dx + vy * dy, len2 = dx * dx + dy * dy;
  if (t <= 0) return uint64_t(vx * vx + vy * vy) <= tol2;
  if (t >= len2) {
    const int64_t wx = int64_t{p.x} - b.x, wy = int64_t{p.y} - b.y;
    return uint64_t(wx * wx + wy * wy) <= tol2;
  }
  const int64_t cross = vx * dy - vy * dx;  // distance = |cross| / sqrt(len2)
  return mul_i64(cross, cross) <= mul_u64(tol2, uint64_t(len2));
}

}  // namespace

uint32_t simplify_strokes(PathPoint* p, uint32_t n, uint32_t tol, uint32_t* dropped) {
  // The box of the strokes' points: a point on its edge is kept, so the box, and with it where
  // the drawing is placed on the page, stays as it was.
  int32_t x0 = INT32_MAX, y0 = INT32_MAX, x1 = INT32_MIN, y1 = INT32_MIN;
  for (uint32_t i = 1; i < n; ++i) {
    if (p[i].pen_down == 0) continue;
    const PathPoint* ends[2] = {&p[i - 1], &p[i]};
    for (const PathPoint* q : ends) {
      x0 = q->x < x0 ? q->x : x0, x1 = q->x > x1 ? q->x : x1;
      y0 = q->y < y0 ? q->y : y0, y1 = q->y > y1 ? q->y : y1;
    }
  }
  auto on_box = [&](const PathPoint& q) {
    return q.x == x0 || q.x == x1 || q.y == y0 || q.y == y1;
  };
  uint32_t w = 0;  // points kept so far: p[0, w)
  for (uint32_t i = 0; i < n;) {
    p[w++] = p[i];
    // A run of pen-down points after p[i] (p[i] is its start, whatever its pen state).
    uint32_t end = i + 1;
    while (end < n && p[end].pen_down != 0) ++end;
    uint32_t a = i;  // the last kept point (its index in the input)
    while (a + 1 < end) {
      // The farthest b (within the window) such that every point between a and b is near a-b.
      uint32_t b = a + 1;
      for (uint32_t c = a + 2; c < end && c <= a + kSimplifyWindow; ++c) {
        bool fits = in_budget(p[a]) && in_budget(p[c]);
        for (uint32_t k = a + 1; k < c && fits; ++k)
          fits = in_budget(p[k]) && !on_box(p[k]) && near_segment(p[a], p[c], p[k], tol);
        if (!fits) break;
        b = c;
      }
      *dropped += b - a - 1;
      p[w++] = p[b];
      a = b;
    }
    i = end;
  }
  return w;
}

}  // namespace haloplot
