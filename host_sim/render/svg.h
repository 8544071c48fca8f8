// SVG of a drawing. Plotter y grows upward, SVG y downward: the picture is flipped so it looks
// as it will on paper.
//
// write_plot_svg: the plot as a plotter takes it (vpype, the AxiDraw Inkscape extension). The
// page is the SVG (width and height in mm, viewBox in mm, so a user unit is a millimetre); each
// pen layer is an Inkscape layer (<g inkscape:groupmode="layer" inkscape:label="1 visible">),
// each pen-down stroke one <path> of one subpath, in the planned order; point (x, y) of the
// path is at (x + offset_x, page height - (y + offset_y)) in mm, to three decimals, exactly
// the G-code's X and page height - Y (export/page.h). No background unless asked for.
//
// write_svg: the older cropped picture (the drawing's bounding box plus a border, a white
// background), for `replay`.
#pragma once
#include <iosfwd>
#include <vector>

#include "export/exporters.h"
#include "export/page.h"
#include "export/plot_layers.h"
#include "haloplot/draw/draw.h"

namespace haloplot::host {

struct PlotSvgStyle {
  Page page;
  ExportStyle placement;      // steps_per_mm and the page offset, as the G-code's
  double pen_width_mm = 0.3;  // --pen-width: the stroke width (outlines: times their factor)
  bool background = false;    // --background: a white page-sized rectangle, for viewing
  PathClean clean;            // --min-stroke, --no-cleanup: the planner's clean-up
  PathStats path_stats;       // out: what write_plot_page()'s planning did (its clean-up)
};

void write_plot_svg(std::ostream& out, const std::vector<PlannedLayer>& layers,
                    const PlotSvgStyle& style);

struct SvgStyle {
  double steps_per_mm = 80;  // the plotter's scale: the SVG's size in mm is steps / this
  double stroke_steps = 0;   // 0: about 1/1000 of the picture
  // A second pen drawn over the first, wider (the outline pass of the hidden-line modes).
  const std::vector<Span>* second_pen = nullptr;
  double second_pen_width = 2.5;  // times the first pen's stroke
};

void write_svg(std::ostream& out, const std::vector<Span>& spans, const SvgStyle& style);

}  // namespace haloplot::host
