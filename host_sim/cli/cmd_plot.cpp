// haloplot plot SCENE.edges|MODEL -o OUT.svg: a scene or a model drawn in one run. Haloed lines
// here (CUT then DRAW, whole or in bands with --arena); a model's hidden lines go to
// cmd_plot_solid, a scene with Bézier edges to cmd_plot_curves, once the options common to
// all are checked.
#include <cstdio>
#include <iterator>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "cli/band_stats.h"
#include "cli/cmd_plot_curves.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/haloed_options.h"
#include "cli/haloed_outputs.h"
#include "cli/page_options.h"
#include "cli/plot_outputs.h"
#include "cli/scene_input.h"
#include "cli/stage_progress.h"
#include "io/atomic_file.h"
#include "io/cut_file.h"
#include "io/line_reader.h"
#include "io/mesh_file.h"
#include "io/substep_header.h"
#include "pipeline/host_pipeline.h"
#include "pipeline/units.h"

namespace haloplot::host {
namespace {

// plot --arena BYTES: the banded run a controller with that arena makes; the same pieces.
int plot_in_bands(const Options& o, const std::vector<Edge3>& edges, const CutParams& cp,
                  const DrawParams& dp, int32_t units) {
  if (!o.get("--cut").empty())
    return fail("--cut writes the whole CUTSET, which a banded run never holds: drop --arena");
  int64_t arena = 0;
  if (!parse_int(o.get("--arena"), 1024, int64_t{1} << 30, &arena))
    return fail("--arena needs a byte count in [1024, 2^30]");
  HostDraw d;
  BandStats bands;
  const Status s = host_banded_draw(edges, cut_in_units(cp, units), draw_in_units(dp, units),
                                    size_t(arena), &d, &bands, units);
  if (s == Status::kArenaTooSmall)
    return fail(arena_too_small("plot", uint64_t(arena), bands.need_bytes));
  if (!ok(s)) return fail_status("bands", s);
  spans_to_steps(&d.spans, units);
  const StageProgress writing("writing the files");
  if (const int rc = write_drawing(o, d, is_mesh_path(o.positional[0]))) return rc;
  if (o.has("--stats")) {
    std::fprintf(stderr, "edges=%zu\nspans=%zu\nband_ms=%.3f\n", edges.size(), d.spans.size(),
                 d.draw_ms);
    print_band_stats(bands, size_t(arena));
  }
  return 0;
}

// --pause-between-layers needs a plotter output and a drawing of more than one kind of line.
std::string layer_pause_problem(const Options& o) {
  if (!o.has("--pause-between-layers")) return "";
  if (!wants_plotter_outputs(o))
    return "--pause-between-layers stops for a pen change in the G-code or HPGL: add --gcode "
           "OUT.gcode or --hpgl OUT.hpgl";
  const std::string mode = o.get("--mode", "haloed");
  if (mode != "hidden-removed" && mode != "hidden-dashed")
    return "--pause-between-layers with --mode " + mode + ": its G-code draws one layer (" +
           (mode == "all" ? "the model's edges whole, as a job's drawing all"
                          : "the haloed edges") +
           "); the layers are --mode hidden-removed or hidden-dashed's";
  return "";
}

}  // namespace

int cmd_plot(int argc, char** argv) {
  std::set<std::string> valued = kCutValued;
  valued.insert({"--halo", "--spans", "--cut", "--mode", "--dash", "--steps-per-mm", "--method",
                 "--hatch", "--arena"});
  valued.insert(std::begin(kSceneOptions), std::end(kSceneOptions));
  valued.insert(std::begin(kPlotterOutputOptions), std::end(kPlotterOutputOptions));
  valued.insert(std::begin(kPenOptions), std::end(kPenOptions));
  valued.insert(std::begin(kPageValued), std::end(kPageValued));
  std::set<std::string> flags = {"--exact-halo", "--stats", "--outline", "--no-intersections",
                                 "--pause-between-layers"};
  flags.insert(std::begin(kPageFlags), std::end(kPageFlags));
  const Options o = parse_options(argc, argv, 2, valued, flags);
  if (!o.error.empty()) return fail(o.error);
  // The plotter's files alone need no SVG: -o is then optional.
  const bool plotter_only =
      o.get("-o").empty() && (!o.get("--gcode").empty() || !o.get("--hpgl").empty());
  if (!one_input_and_output(o) && !(plotter_only && o.positional.size() == 1))
    return bad_arguments(o, "plot", kPlotUsage);
  if (const std::string bad = svg_output_problem(o.get("-o")); !bad.empty()) return fail(bad);
  for (const char* pen : kPenOptions)
    if (!o.get(pen).empty() && o.get("--gcode").empty())
      return fail(std::string(pen) + " sets the G-code's pen or feeds: add --gcode OUT.gcode");
  if (const std::string bad = layer_pause_problem(o); !bad.empty()) return fail(bad);
  if (o.get("--mode", "haloed") != "haloed") return cmd_plot_solid(o);
  for (const char* solid_flag : {"--outline", "--no-intersections"})
    if (o.has(solid_flag))
      return fail(std::string(solid_flag) +
                  " needs the faces: use it with --mode all, hidden-removed or hidden-dashed");
  for (const char* solid_only : {"--hatch", "--dash", "--method"})
    if (!o.get(solid_only).empty())
      return fail(std::string(solid_only) +
                  " is for solid drawings: use it with --mode hidden-removed or hidden-dashed" +
                  " (haloed lines have no faces)");
  // A scene with Bézier edges takes the curve stages (docs/curves.md); any other, CUT and DRAW.
  if (edges_file_has_curves(o.positional[0])) return cmd_plot_curves(o);
  // A model plots either way: say both when neither is given.
  if (o.get("--halo").empty() && is_mesh_path(o.positional[0]))
    return fail(
        "a model needs --mode all|hidden-removed|hidden-dashed (its hidden lines) or "
        "--halo W (haloed lines, W in steps)");
  CutParams cp;
  DrawParams dp;
  std::string error;
  if (!cut_params(o, &cp, &error) || !draw_params(o, &dp, &error)) return fail(error);
  // In one process the halo width is known before CUT: let the exact halo see near misses.
  if (dp.mode == HaloMode::kExact && o.get("--reach").empty()) cp.reach = dp.halo;
  std::vector<Edge3> edges;
  int32_t units = 0;
  {
    const StageProgress stage("reading " + o.positional[0]);
    if (!load_scene(o, o.positional[0], &edges, &error, &units)) return fail(error);
  }
  if (wants_plotter_outputs(o)) {
    if (!o.get("--arena").empty())
      return fail(
          "--gcode and --hpgl plot the whole drawing's path: drop --arena, or give the "
          "job 'arena BYTES' and run `haloplot sim JOB.job --gcode ...`");
    // The job `sim` runs for this drawing: CUT and DRAW in the core's job, then its path.
    JobSpec spec;
    spec.drawing = DrawingEffect::kHaloed;
    spec.draw = dp;
    spec.cut = cp;
    spec.cut.progress = nullptr;  // CUT's counter shows once, for the drawing's own CUT below
    spec.substep_bits = units;
    ExportStyle style;
    if (!export_style_of(o, &style, &spec.machine, &error) ||
        !parse_path_clean(o, style.steps_per_mm, &spec.clean, &error))
      return fail(error);
    const StageProgress stage("the plotter's path (CUT, DRAW and the pen path, as sim's job)");
    if (const int rc = write_plot_outputs(o, spec, edges, style, is_mesh_path(o.positional[0])))
      return rc;
  }
  if (!o.get("--arena").empty()) return plot_in_bands(o, edges, cp, dp, units);
  HostCut c;
  Status s = host_cut(std::move(edges), cut_in_units(cp, units), &c);
  if (!ok(s)) return fail_status("CUT", s);
  HostDraw d;
  {
    const StageProgress stage("DRAW");
    s = host_draw(c.set, draw_in_units(dp, units), &d);
  }
  if (!ok(s)) return fail_status("DRAW", s);
  warn_reach(d, dp.halo, c.set.reach >> units);
  if (!o.get("--cut").empty()) {
    error = write_atomically(o.get("--cut"), [&](std::ostream& out) {
      write_cut(out, c.set, cut_header(c) + substep_header(units));
      return true;
    });
    if (!error.empty()) return fail(error);
  }
  spans_to_steps(&d.spans, units);
  const StageProgress writing("writing the files");
  if (const int rc = write_drawing(o, d, is_mesh_path(o.positional[0]))) return rc;
  if (o.has("--stats")) {
    print_cut_stats(c);
    print_draw_stats(d);
  }
  return 0;
}

}  // namespace haloplot::host
