// haloplot sim JOB.job -o OUT.trace: a job plotted by the controller's own code on a simulated
// machine, step by step, to a trace (and the plotter's files from the same path), with feed
// holds and a resume for testing a stopped plot.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli/band_stats.h"
#include "cli/cmd_plot_curves.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/haloed_options.h"
#include "cli/job_file.h"
#include "cli/page_options.h"
#include "cli/scene_input.h"
#include "cli/stage_progress.h"
#include "export/page.h"
#include "export/plotter_outputs.h"
#include "io/atomic_file.h"
#include "io/edges_file.h"
#include "io/line_reader.h"
#include "io/mesh_file.h"
#include "sim/simulator.h"
#include "sim/trace.h"

namespace haloplot::host {
namespace {

// A plot far slower than its speeds allow (accel 1 plans hours of ramps) is legal but almost
// surely not meant: say so, with the time the speeds alone would take.
void warn_if_slow(const JobSpec& spec, const SimReport& r) {
  const Machine& m = spec.machine;
  const double hz = m.tick_hz, plotted = double(r.end_tick) / hz;
  const double at_speed = double(r.job.path.pen_down_length) / m.draw_speed +
                          double(r.job.path.pen_up_length) / m.travel_speed +
                          double(r.planner.dwell_ticks) / hz;
  if (plotted > 60 && plotted > 3 * at_speed)
    std::fprintf(stderr,
                 "haloplot: warning: the plot takes %.0f s, %.0f times what its speeds alone "
                 "would take (%.0f s): is accel %u steps/s^2 meant?\n",
                 plotted, plotted / std::max(at_speed, 1e-9), at_speed, m.accel);
}

// --pause-at E1,E2,...: a feed hold once the plot has made E step events, resumed at rest.
bool parse_pause_at(const std::string& list_text, std::vector<uint32_t>* pause_at) {
  std::stringstream list(list_text);
  std::string item;
  while (std::getline(list, item, ',')) {
    int64_t v = 0;
    if (!parse_int(item, 0, UINT32_MAX, &v) || (!pause_at->empty() && v < pause_at->back()))
      return false;
    pause_at->push_back(uint32_t(v));
  }
  return true;
}

// The plot as a G-code and an HPGL file too, when asked for: a model's drawing centred on the
// job's page as `plot` centres it (export/page.h); the travel home ends at the paper's origin.
int write_exports(const Options& o, const SimReport& r, const JobSpec& spec, JobFile jf) {
  if (o.get("--gcode").empty() && o.get("--hpgl").empty()) return 0;
  std::vector<PathPoint> points = r.points;
  if (is_mesh_path(jf.scene_path)) {
    Options page_options;
    page_options.values = jf.solid_options;
    if (jf.landscape) page_options.flags.insert("--landscape");
    Page page;
    std::string error;
    if (!parse_page(page_options, &page, &error)) return fail(error);
    centre_on_page(page, spec.finish_home, &points, &jf.style);
  }
  const std::string error = write_plotter_outputs(o.get("--gcode"), o.get("--hpgl"), points,
                                                  spec.machine, jf.style, r.layer_points);
  if (!error.empty()) return fail(error);
  // What the files draw, as `plot` says it (whole or in bands).
  std::cerr << written_summary(spec, points, jf.style) << "\n";
  return 0;
}

void print_sim_stats(const JobSpec& spec, const SimReport& r, size_t edges) {
  const Machine& m = spec.machine;
  auto rate = [&](int k) { return r.min_gap[k] == UINT64_MAX ? 0 : m.tick_hz / r.min_gap[k]; };
  std::fprintf(
      stderr,
      "edges=%zu\nspans=%u\npolylines=%u\npen_down_length=%llu\npen_up_length=%llu\n"
      "naive_pen_up_length=%llu\nplot_s=%s\nsteps_0=%llu\nsteps_1=%llu\n"
      "peak_step_rate_0=%llu\npeak_step_rate_1=%llu\npen_lifts=%u\n"
      "cut_runs=%u\ndraw_runs=%u\nplanner_replans=%llu\njunctions=%llu\n"
      "dwell_ticks=%llu\nbacklash_takeups=%llu\nsegments=%llu\n"
      "bytes_cut=%zu\nbytes_draw=%zu\nbytes_path=%zu\nbytes_planner=%zu\n",
      edges, (unsigned)r.spans.size(), r.job.path.polylines,
      (unsigned long long)r.job.path.pen_down_length, (unsigned long long)r.job.path.pen_up_length,
      (unsigned long long)r.job.path.naive_pen_up_length,
      thousandths(r.end_tick * 1000 / m.tick_hz).c_str(), (unsigned long long)r.steps[0],
      (unsigned long long)r.steps[1], (unsigned long long)rate(0), (unsigned long long)rate(1),
      r.pen_lifts, r.job.cut_runs, r.job.draw_runs, (unsigned long long)r.planner.replans,
      (unsigned long long)r.planner.junctions, (unsigned long long)r.planner.dwell_ticks,
      (unsigned long long)r.prep.backlash_takeups, (unsigned long long)r.prep.segments,
      r.bytes.cut_scratch + r.bytes.cutset, r.bytes.draw_scratch, r.bytes.path + r.bytes.points,
      r.planner_bytes);
}

}  // namespace

int cmd_sim(int argc, char** argv) {
  const Options o = parse_options(
      argc, argv, 2,
      {"-o", "--gcode", "--hpgl", "--arena", "--pause-at", "--resume-at", "--threads"},
      {"--stats", "--binary"});
  if (!o.error.empty()) return fail(o.error);
  if (!one_input_and_output(o)) return bad_arguments(o, "sim", kSimUsage);
  std::vector<uint32_t> pause_at;
  if (!o.get("--pause-at").empty() && !parse_pause_at(o.get("--pause-at"), &pause_at))
    return fail("--pause-at needs ascending step-event counts, comma-separated: '" +
                o.get("--pause-at") + "'");
  const TraceForm form = o.has("--binary") ? TraceForm::kBinary : TraceForm::kText;
  JobFile jf;
  InputError ie = read_job_file(o.positional[0], &jf);
  if (ie.failed()) return fail(ie.message());
  if (!o.get("--arena").empty()) {
    int64_t v = 0;
    if (!parse_int(o.get("--arena"), 1024, int64_t{1} << 30, &v))
      return fail("--arena needs a byte count in [1024, 2^30]");
    jf.arena = uint32_t(v);
  }
  if (jf.style.pause_between_layers && jf.arena > 0)
    return fail(o.positional[0] +
                ": pause-between-layers with an arena: a plot in bands draws band after band, "
                "not layer after layer (leave out the arena)");
  // --resume-at E: go on from where a plot of this job stopped after E step events.
  int64_t resume_at = 0;
  if (!o.get("--resume-at").empty() && !parse_int(o.get("--resume-at"), 0, UINT32_MAX, &resume_at))
    return fail("--resume-at needs a step-event count: '" + o.get("--resume-at") + "'");
  std::vector<Edge3> edges;
  std::string error;
  // A hidden-line drawing with an arena is worked out in bands, as the controller does; without
  // one the host decides it whole and plots the chosen strokes.
  const bool solid_bands = jf.arena > 0 && (jf.spec.drawing == DrawingEffect::kHiddenRemoved ||
                                            jf.spec.drawing == DrawingEffect::kHiddenDashed);
  SolidScene solid;
  // A scene with Bézier edges goes to the core's curve job (crossings, the curve DRAW, the
  // path), the one the controller runs on a curve scene from `send`.
  const bool curves = !solid_bands && edges_file_has_curves(jf.scene_path);
  EdgesWithCurves curve_scene;
  std::optional<StageProgress> stage;
  const bool hidden_on_host = !solid_bands && (jf.spec.drawing == DrawingEffect::kHiddenRemoved ||
                                               jf.spec.drawing == DrawingEffect::kHiddenDashed);
  stage.emplace("reading " + jf.scene_path + (hidden_on_host ? " and its hidden lines" : ""));
  if (curves) {
    if (!load_curve_job(jf.scene_path, jf.spec, &curve_scene, &jf.spec.substep_bits, &error))
      return fail(error);
    edges = curve_scene.edges;
  } else if (solid_bands) {
    if (!load_solid_job_scene(jf, &solid, &jf.spec.hidden, &error)) return fail(error);
    jf.spec.substep_bits = solid.substep_bits;
  } else if (!load_job_scene(jf, &edges, &error, &jf.spec.substep_bits, &jf.spec.layers)) {
    return fail(error);
  }
  stage.reset();
  if (isatty(2)) jf.spec.cut.progress = &cut_progress;
  // The job's CUT, in every band too, on the host's threads: the same records, so the same plot.
  if (!read_threads_option(o, &jf.spec.cut.parts, &error)) return fail(error);
  JobSpec spec = jf.spec;
  // Hidden-line drawings are decided on the host; the controller's job then draws the chosen
  // strokes whole (their z no longer matters).
  if (!solid_bands && (spec.drawing == DrawingEffect::kHiddenRemoved ||
                       spec.drawing == DrawingEffect::kHiddenDashed))
    spec.drawing = DrawingEffect::kAllEdges;
  if (!spec.effects.backlash)
    spec.machine.backlash[0] = spec.machine.backlash[1] = 0;  // not simulated
  SimReport r;
  Status s = Status::kOk;
  // A haloed job's CUT shows its own counter (the same line would be overwritten).
  if (spec.drawing != DrawingEffect::kHaloed) stage.emplace("simulating the plotter");
  error = write_atomically(o.get("-o"), [&](std::ostream& out) {
    s = solid_bands ? simulate_solid(spec, solid_input(solid), model_closed(solid), &out, &r,
                                     jf.arena, form, pause_at, uint32_t(resume_at))
                    : simulate(spec, edges, &out, &r, jf.arena, form, pause_at, uint32_t(resume_at),
                               curves ? &curve_scene.curves : nullptr);
    return ok(s);
  });
  stage.reset();
  if (s == Status::kArenaTooSmall)
    return fail(arena_too_small("sim", jf.arena, r.bands.need_bytes));
  if (!ok(s)) return fail_status("sim", s);
  warn_if_slow(spec, r);
  if (!error.empty()) return fail(error);
  if (const int rc = write_exports(o, r, spec, jf)) return rc;
  if (o.has("--stats")) {
    print_sim_stats(spec, r, edges.size() + curve_scene.curves.size());
    print_clean_stats(r.job.path, jf.style.steps_per_mm);
    if (curves && jf.arena > 0)  // in bands: each band's crossings are its own, chords once
      std::fprintf(stderr, "chords=%llu\n", (unsigned long long)r.bands.pieces);
    else if (curves)  // the curve job's stages (job/job.h job_prepare_curves)
      std::fprintf(stderr, "curve_pieces=%u\ncrossings=%u\ngaps=%llu\nchords=%llu\n",
                   r.job.curve_cross.pieces, r.job.curve_cross.crossings,
                   (unsigned long long)r.job.curve_draw.gaps,
                   (unsigned long long)r.job.curve_draw.chords);
    if (!pause_at.empty()) std::fprintf(stderr, "holds=%llu\n", (unsigned long long)r.holds);
    if (jf.arena > 0) print_band_stats(r.bands, jf.arena);
  }
  return 0;
}

}  // namespace haloplot::host
