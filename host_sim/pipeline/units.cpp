#include "pipeline/units.h"

#include "haloplot/geometry/units.h"

namespace haloplot::host {

DrawParams draw_in_units(DrawParams d, int32_t substep_bits) {
  d.halo = steps_to_units(d.halo, substep_bits);
  return d;
}

CutParams cut_in_units(CutParams c, int32_t substep_bits) {
  c.reach = steps_to_units(c.reach, substep_bits);
  return c;
}

ModeSpec mode_in_units(ModeSpec m, int32_t substep_bits) {
  m.dash_steps = steps_to_units(m.dash_steps, substep_bits);
  m.gap_steps = steps_to_units(m.gap_steps, substep_bits);
  return m;
}

HatchParams hatch_in_units(HatchParams h, int32_t substep_bits) {
  h.spacing = steps_to_units(h.spacing, substep_bits);
  h.min_length = steps_to_units(1, substep_bits);  // as the job: no line shorter than a step
  return h;
}

void spans_to_steps(std::vector<Span>* spans, int32_t substep_bits) {
  for (Span& s : *spans) {
    s.x0 = units_to_steps(s.x0, substep_bits), s.y0 = units_to_steps(s.y0, substep_bits);
    s.x1 = units_to_steps(s.x1, substep_bits), s.y1 = units_to_steps(s.y1, substep_bits);
  }
}

void drawing_to_steps(ModeDrawing* d, int32_t substep_bits) {
  spans_to_steps(&d->spans, substep_bits);
  spans_to_steps(&d->outline, substep_bits);
  spans_to_steps(&d->hatch, substep_bits);
}

}  // namespace haloplot::host
