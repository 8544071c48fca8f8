#include "haloplot/solid/hatch_pattern.h"

namespace haloplot {

// The lines' direction for a polygon: its angle grows with its mean depth (Franklin's Figure 4).
// The polygon is the run of consecutive triangles with its id, so both halves of a quad agree.
SinCos hatch_direction(const Triangle* triangles, uint32_t n_triangles, const Point3* vertices,
                       uint32_t t, const HatchParams& p) {
  uint32_t s = t, e = t + 1;
  while (s > 0 && triangles[s - 1].polygon == triangles[t].polygon) --s;
  while (e < n_triangles && triangles[e].polygon == triangles[t].polygon) ++e;
  int64_t sum = 0, n = 0;
  for (uint32_t i = s; i < e; ++i)
    for (int k = 0; k < 3; ++k, ++n) sum += vertices[triangles[i].v[k]].z;
  const int64_t mean = n > 0 ? sum / n : 0;
  const int64_t angle = p.angle_mdeg + (int64_t{p.mdeg_per_depth} * mean >> kCoordBits);
  return sin_cos_mdeg(static_cast<int32_t>(angle % 360000));
}

}  // namespace haloplot
