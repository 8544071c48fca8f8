// SVG of visible spans. Plotter y grows upward, SVG y downward: the picture is flipped so it
// looks as it will on paper. The viewBox is in steps, so the SVG measures like the plot, and
// the width and height are in millimetres at the plotter's steps per mm, so plotter tools
// (vpype, Inkscape's AxiDraw extension) and printers draw it at its real size.
#pragma once
#include <iosfwd>
#include <vector>

#include "draw/draw.h"

namespace haloplot::host {

struct SvgStyle {
  double steps_per_mm = 80;  // the plotter's scale: the SVG's size in mm is steps / this
  double stroke_steps = 0;   // 0: about 1/1000 of the picture
  // A second pen drawn over the first, wider (the outline pass of the hidden-line modes).
  const std::vector<Span>* second_pen = nullptr;
  double second_pen_width = 2.5;  // times the first pen's stroke
};

void write_svg(std::ostream& out, const std::vector<Span>& spans, const SvgStyle& style);

}  // namespace haloplot::host
