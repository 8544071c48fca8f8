// The host's side of sub-step units (core/include/haloplot/geometry/units.h), as the core's job
// does it: lengths given in steps become the scene's units on the way in, drawn spans become steps
// on the way out, once, with the core's own rounding (so a host plot and a controller plot agree).
#pragma once
#include <cstdint>
#include <vector>

#include "haloplot/cut/cut.h"
#include "haloplot/draw/draw.h"
#include "haloplot/surface/hatch.h"
#include "pipeline/drawing_modes.h"

namespace haloplot::host {

DrawParams draw_in_units(DrawParams d, int32_t substep_bits);
CutParams cut_in_units(CutParams c, int32_t substep_bits);
ModeSpec mode_in_units(ModeSpec m, int32_t substep_bits);
HatchParams hatch_in_units(HatchParams h, int32_t substep_bits);

void spans_to_steps(std::vector<Span>* spans, int32_t substep_bits);
void drawing_to_steps(ModeDrawing* d, int32_t substep_bits);

}  // namespace haloplot::host
