#include "cli/plot_outputs.h"

#include <cstdio>
#include <iostream>

#include "export/plotter_outputs.h"
#include "io/line_reader.h"

namespace haloplot::host {

const char* const kPlotterOutputOptions[2] = {"--gcode", "--hpgl"};

bool wants_plotter_outputs(const Options& o) {
  return !o.get("--gcode").empty() || !o.get("--hpgl").empty();
}

bool export_style_of(const Options& o, ExportStyle* style, Machine* machine, std::string* error) {
  (void)machine;
  int64_t per_mm = 80;
  if (!o.get("--steps-per-mm").empty() && !parse_int(o.get("--steps-per-mm"), 1, 10000, &per_mm)) {
    *error = "--steps-per-mm '" + o.get("--steps-per-mm") + "' must be an integer in [1, 10000]";
    return false;
  }
  style->steps_per_mm = uint32_t(per_mm);
  return true;
}

int write_plot_outputs(const Options& o, const JobSpec& spec, const std::vector<Edge3>& edges,
                       const ExportStyle& style) {
  PlannedJob planned;
  const Status s = plan_job_path(spec, edges, &planned);
  if (!ok(s)) {
    std::cerr << "haloplot: path planning failed: " << status_name(s) << "\n";
    return 1;
  }
  const double seconds = estimate_plot_seconds(spec, planned.points);
  add_travel_home(spec, &planned.points);
  const std::string error =
      write_plotter_outputs(o.get("--gcode"), o.get("--hpgl"), planned.points, spec.machine, style);
  if (!error.empty()) {
    std::cerr << "haloplot: " << error << "\n";
    return 1;
  }
  const PathStats& p = planned.counters.path;
  const long whole = long(seconds + 0.5);
  std::fprintf(stderr,
               "haloplot: plot time about %ld min %02ld s (%.1f s by the motion planner's "
               "model); %u strokes, pen down %s mm, pen up %s mm\n",
               whole / 60, whole % 60, seconds, p.polylines,
               mm_text(int64_t(p.pen_down_length), style.steps_per_mm).c_str(),
               mm_text(int64_t(p.pen_up_length), style.steps_per_mm).c_str());
  if (o.has("--stats")) std::fprintf(stderr, "estimate_s=%.3f\n", seconds);
  return 0;
}

}  // namespace haloplot::host
