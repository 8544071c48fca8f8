// Hatching for a plotter: the visible part of every face filled with parallel lines (the
// paper's Figure 4 shades squares with lines at an angle proportional to their distance).
// What every hatching shares: its parameters, the lines' direction per polygon, and the
// stroke a hatching hands out. Two ways draw it:
//   solid/hatch_lines.h   each face's lattice lines as segments on the face, what shows of each
//                         decided like an edge's; the hidden-line run draws them (the job, the
//                         bands, the controller);
//   surface/region_hatch.h  Franklin 1980 steps 10-11: the planar graph of the visible
//                         segments, its regions and their faces, each region's lines clipped to
//                         it (the reference the first is tested against).
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "solid/mesh.h"
#include "status/status.h"
#include "view/trig.h"

namespace haloplot {

struct HatchParams {
  int32_t spacing = 120;           // steps between lines (1.5 mm at 80 steps/mm)
  int32_t angle_mdeg = 45000;      // the lines' angle for a face at depth 0
  int32_t mdeg_per_depth = 90000;  // added across the whole depth range (2^20): nearer, steeper
  bool front_only = true;          // hatch only faces facing the viewer (closed solids)
  // Lines shorter than this on paper along both axes are not laid (solid/hatch_lines.h): a
  // line across a corner's tip would be a dot. The job sets one step.
  int32_t min_length = 0;
};

// The lines' direction for triangle t's polygon: its angle grows with the polygon's mean
// depth (Franklin's Figure 4). The polygon is the run of consecutive triangles with its id,
// so both halves of a quad agree (a band holds every triangle of a polygon it holds one of).
SinCos hatch_direction(const Triangle* triangles, uint32_t n_triangles, const Point3* vertices,
                       uint32_t t, const HatchParams& params);
inline SinCos hatch_direction(const SolidInput& in, uint32_t t, const HatchParams& params) {
  return hatch_direction(in.triangles, in.n_triangles, in.vertices, t, params);
}

struct HatchStroke {
  uint32_t face;  // triangle
  uint32_t polygon;
  Edge3 line;  // the visible piece, ends rounded to steps
};

struct HatchSink {
  Status (*emit)(void* context, const HatchStroke& stroke);
  void* context;
};

}  // namespace haloplot
