// Hatching for a plotter: the visible part of every face filled with parallel lines (the
// paper's Figure 4 shades squares with lines at an angle proportional to their distance).
// What every hatching shares: its parameters and the lines' direction per polygon
// (solid/hatch_pattern.h), and the stroke a hatching hands out. Two ways draw it:
//   solid/hatch_lines.h   each face's lattice lines as segments on the face, what shows of each
//                         decided like an edge's; the hidden-line run draws them (the job, the
//                         bands, the controller);
//   surface/region_hatch.h  Franklin 1980 steps 10-11: the planar graph of the visible
//                         segments, its regions and their faces, each region's lines clipped to
//                         it (the reference the first is tested against).
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/solid/hatch_pattern.h"
#include "haloplot/solid/mesh.h"
#include "haloplot/status/sink.h"
#include "haloplot/status/status.h"

namespace haloplot {

struct HatchStroke {
  uint32_t face;  // triangle
  uint32_t polygon;
  Edge3 line;  // the visible piece, ends rounded to steps
};

using HatchSink = Sink<HatchStroke>;

}  // namespace haloplot
