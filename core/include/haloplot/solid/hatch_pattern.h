// The hatching's pattern: its parameters and the lines' direction per polygon. Both ways of
// drawing a hatching read it (solid/hatch_lines.h, surface/region_hatch.h through
// surface/hatch.h), so it lives here, below both layers.
#pragma once
#include <stdint.h>

#include "haloplot/solid/mesh.h"
#include "haloplot/view/trig.h"

namespace haloplot {

struct HatchParams {
  int32_t spacing = 120;           // steps between lines (1.5 mm at 80 steps/mm)
  int32_t angle_mdeg = 45000;      // the lines' angle for a face at depth 0
  int32_t mdeg_per_depth = 90000;  // added across the whole depth range (2^20): nearer, steeper
  bool front_only = true;          // hatch only faces facing the viewer (closed solids)
  // Lines across a small flat polygon shorter than this on paper along both axes are not laid
  // (solid/hatch_lines.h): a line across a corner's tip would be a dot. The job sets one step.
  int32_t min_length = 0;
  // The vertices are the page turned a quarter (geometry/quarter_turn.h; a banded plot of a
  // wide solid): the lines are the page's lattice, found in the turned frame.
  bool turned = false;
};

// The lines' direction for triangle t's polygon: its angle grows with the polygon's mean
// depth (Franklin's Figure 4). The polygon is the run of consecutive triangles with its id,
// so both halves of a quad agree (a band holds every triangle of a polygon it holds one of).
SinCos hatch_direction(const Triangle* triangles, uint32_t n_triangles, const Point3* vertices,
                       uint32_t t, const HatchParams& params);
inline SinCos hatch_direction(const SolidInput& in, uint32_t t, const HatchParams& params) {
  return hatch_direction(in.triangles, in.n_triangles, in.vertices, t, params);
}

}  // namespace haloplot
