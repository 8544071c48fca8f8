// The paper a plot lands on, and where on it the drawing goes: the one placement the SVG
// writer, the G-code and the HPGL exporters all use, so a point lands at the same spot of the
// paper in each.
//
// Paper coordinates: the origin is the page's lower-left corner, x to the right, y up, in plot
// steps (steps-per-mm a millimetre). G-code and HPGL write them as they are (mm, or 1/40 mm);
// the SVG, whose y grows downward, writes (x, page height - y) in millimetres, its viewBox the
// page in millimetres.
//
// A model is fitted by the projection into the page's drawable area (the page less its margin
// on every side, View::width/height/margin), lower-left corner at the margin; the exporters
// then add one offset in whole steps (ExportStyle::offset_x/y) that centres the drawing's
// pen-down bounding box in the drawable area. The controller draws the projection's
// coordinates; the offset is the exported files' only difference. An .edges scene is in plot
// steps already: it is drawn where its coordinates say (no offset).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "haloplot/motion/path_plan.h"

namespace haloplot::host {

struct Page {
  // The default: A4 landscape with a 10 mm margin, what an AxiDraw (A4 / letter travel) or a
  // vpype user (`--page-size a4 --landscape`) would set first.
  int64_t width_um = 297000, height_um = 210000;  // after --landscape
  int64_t margin_um = 10000;
  double scale = 0;     // --scale S: S mm on paper per unit of the model file; 0: fit the page
  bool placed = false;  // --fit or --scale given (for refusing them where they cannot apply)
};

// The drawable area in whole plot steps: its lower-left corner (margin, margin) and its size;
// false when the margins leave nothing or the area leaves the coordinate range.
bool page_area(const Page& page, uint32_t steps_per_mm, int32_t* margin, int32_t* width,
               int32_t* height);

// The offset (steps) that centres the pen-down bounding box of `path` in the drawable area;
// (0, 0) for an empty path.
void centring_offset(const Page& page, uint32_t steps_per_mm, const std::vector<PathPoint>& path,
                     int32_t* offset_x, int32_t* offset_y);

// "297", "215.9": thousandths of a millimetre as the shortest decimal.
std::string um_text(int64_t um);

}  // namespace haloplot::host
