#include "cli/page_options.h"

#include <cstdlib>
#include <iostream>

#include "io/atomic_file.h"

namespace haloplot::host {

const char* const kPageValued[4] = {"--page", "--margin", "--scale", "--pen-width"};
const char* const kPageFlags[3] = {"--landscape", "--fit", "--background"};

bool parse_plot_svg_style(const Options& o, bool model, uint32_t steps_per_mm, PlotSvgStyle* style,
                          std::string* error) {
  PlotSvgStyle s;
  if (!parse_page(o, &s.page, error)) return false;
  if (!model && s.page.placed) {
    *error = std::string(o.has("--fit") ? "--fit" : "--scale") +
             " is for models (.obj, .stl, .ply): an .edges or .cut scene is in plot steps "
             "already, drawn where its coordinates say";
    return false;
  }
  const std::string w = o.get("--pen-width", "0.3");
  char* end = nullptr;
  s.pen_width_mm = std::strtod(w.c_str(), &end);
  if (w.empty() || end != w.c_str() + w.size() || !(s.pen_width_mm > 0) || s.pen_width_mm > 100) {
    *error = "--pen-width '" + w + "' must be a width in mm in (0, 100]";
    return false;
  }
  s.background = o.has("--background");
  s.placement.steps_per_mm = steps_per_mm;
  *style = s;
  return true;
}

std::string write_plot_page(const std::string& path, const std::vector<StrokeLayer>& layers,
                            bool model, PlotSvgStyle* style, std::vector<PathPoint>* joined) {
  std::vector<PlannedLayer> planned;
  const Status s = plan_layers(layers, &planned);
  if (!ok(s)) return path + ": planning the pen path failed: " + status_name(s);
  const std::vector<PathPoint> all = joined_path(planned);
  if (model)
    centring_offset(style->page, style->placement.steps_per_mm, all, &style->placement.offset_x,
                    &style->placement.offset_y);
  if (joined != nullptr) *joined = all;
  return write_atomically(path, [&](std::ostream& out) {
    write_plot_svg(out, planned, *style);
    return true;
  });
}

}  // namespace haloplot::host
