// SVG of visible spans. Plotter y grows upward, SVG y downward: the picture is flipped so it
// looks as it will on paper. The viewBox is in steps, so the SVG measures like the plot.
#pragma once
#include <iosfwd>
#include <vector>

#include "draw/draw.h"

namespace haloplot::host {

struct SvgStyle {
  int pixels = 1200;        // width of the longer side, in px
  double stroke_steps = 0;  // 0: about 1/1000 of the picture
  // A second pen drawn over the first, wider (the outline pass of the hidden-line modes).
  const std::vector<Span>* second_pen = nullptr;
  double second_pen_width = 2.5;  // times the first pen's stroke
};

void write_svg(std::ostream& out, const std::vector<Span>& spans, const SvgStyle& style);

}  // namespace haloplot::host
