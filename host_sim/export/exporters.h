// Exporters for plotters that run other firmware. Both take the planned path (pen-up travel
// and pen-down strokes, in plot steps) and a scale in plot steps per millimetre.
//
// G-code (grbl-style pen plotters): G21 G90, pen by "M3 S<value>" / "M5" or by "G1 Z<z>",
// "G4 P<seconds>" dwells after each pen move, G0 travel, G1 drawing at the draw feed.
// HPGL: IN; SP1; then PU x,y; / PD x,y,...; in plotter units of 0.025 mm (40 per mm).
// Both write paper coordinates (export/page.h): a path point plus the style's offset, from the
// page's lower-left corner, y up; the SVG of the same plot places every point at the same spot.
#pragma once
#include <iosfwd>
#include <vector>

#include "motion/machine.h"
#include "motion/path_plan.h"

namespace haloplot::host {

struct ExportStyle {
  uint32_t steps_per_mm = 80;  // plot steps per millimetre
  bool pen_by_z = false;       // G1 Z pen instead of M3/M5
  int32_t pen_down_s = 1000;   // M3 S value
  int32_t z_up_um = 2000, z_down_um = 0;
  // The page placement (export/page.h): added to every point, in plot steps.
  int32_t offset_x = 0, offset_y = 0;
};

void write_gcode(std::ostream& out, const std::vector<PathPoint>& path, const Machine& m,
                 const ExportStyle& s);
void write_hpgl(std::ostream& out, const std::vector<PathPoint>& path, const ExportStyle& s);

// "12.345": plot steps in millimetres, exactly rounded to 3 decimals (integer arithmetic).
std::string mm_text(int64_t steps, uint32_t steps_per_mm);

}  // namespace haloplot::host
