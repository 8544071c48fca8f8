// The page options `plot` and `draw` share (export/page.h, render/svg.h): --page, --landscape,
// --margin, --fit, --scale, --pen-width MM and --background; and the plot SVG written with
// them: the layers planned, a model's drawing centred on the page.
#pragma once
#include <string>
#include <vector>

#include "cli/options.h"
#include "export/page.h"
#include "export/plot_layers.h"
#include "render/svg.h"

namespace haloplot::host {

// --page --margin --scale --pen-width --min-stroke
extern const char* const kPageValued[6];
extern const char* const kPageFlags[4];  // --landscape --fit --background --no-cleanup

// --page a4|a3|a5|letter|legal|WxH (mm; named sizes portrait), --landscape (the longer side
// across), --margin MM (default 10), --fit (the default) or --scale S. False with *error.
bool parse_page(const Options& o, Page* page, std::string* error);

// The path planner's clean-up (motion/path_plan.h PathClean): --min-stroke MM, by default the
// --pen-width (0.3 mm), 0 keeps every stroke; --no-cleanup (a test's control) plans the strokes
// as drawn, dots and overlaps too.
bool parse_path_clean(const Options& o, uint32_t steps_per_mm, PathClean* clean,
                      std::string* error);
// --stats: what the clean-up dropped and merged (clean_*), lengths in mm.
void print_clean_stats(const PathStats& st, uint32_t steps_per_mm);

// The SVG style from the options: the page, --pen-width (default 0.3 mm), --background, the
// clean-up (parse_path_clean), and the steps per mm. `model`: the scene is a model the projection
// fitted; for an .edges or .cut scene, already in steps, --fit and --scale are refused (nothing to
// fit).
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
