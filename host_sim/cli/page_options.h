// The page options `plot` and `draw` share (export/page.h, render/svg.h): --page, --landscape,
// --margin, --fit, --scale, --pen-width MM and --background; and the plot SVG written with
// them: the layers planned, a model's drawing centred on the page.
#pragma once
#include <string>
#include <vector>

#include "cli/options.h"
#include "export/plot_layers.h"
#include "render/svg.h"

namespace haloplot::host {

extern const char* const kPageValued[4];  // --page --margin --scale --pen-width
extern const char* const kPageFlags[3];   // --landscape --fit --background

// The SVG style from the options: the page, --pen-width (default 0.3 mm), --background, and
// the steps per mm. `model`: the scene is a model the projection fitted; for an .edges or
// .cut scene, already in steps, --fit and --scale are refused (nothing to fit).
bool parse_plot_svg_style(const Options& o, bool model, uint32_t steps_per_mm, PlotSvgStyle* style,
                          std::string* error);

// Plans the layers (plot_layers.h), centres a model's drawing on the page (style->placement
// gets the offset, for a G-code of the same plot) and writes the SVG to `path` atomically.
// *joined (may be null): the plot as one pen path. Returns "" or the error.
std::string write_plot_page(const std::string& path, const std::vector<StrokeLayer>& layers,
                            bool model, PlotSvgStyle* style,
                            std::vector<PathPoint>* joined = nullptr);
// The same for layers planned already (plot_layers.h cut_planned_layers).
std::string write_planned_page(const std::string& path, const std::vector<PlannedLayer>& planned,
                               bool model, PlotSvgStyle* style,
                               std::vector<PathPoint>* joined = nullptr);

}  // namespace haloplot::host
