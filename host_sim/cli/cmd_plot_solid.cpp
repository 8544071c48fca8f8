// haloplot plot MODEL.obj --mode all|hidden-removed|hidden-dashed [--outline] ...: hidden
// lines of a solid model (the HALO paper's Figure 1 modes), by Appel/Heger QI propagation on
// any mesh (both sides of every face where it is not a closed oriented manifold), and by the
// topology-free fallback when asked or when the QI cannot settle (said on stderr).
#include <cstdio>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/options.h"
#include "cli/page_options.h"
#include "cli/plot_outputs.h"
#include "cli/scene_input.h"
#include "cli/solid_options.h"
#include "cli/stage_progress.h"
#include "io/atomic_file.h"
#include "io/line_reader.h"
#include "io/spans_file.h"
#include "pipeline/drawing_modes.h"
#include "pipeline/host_memory.h"
#include "pipeline/units.h"
#include "render/svg.h"

namespace haloplot::host {
namespace {

void print_solid_stats(const SolidRun& r, const TriangulateStats& tri) {
  const QiStats& q = r.qi;
  const FallbackStats& f = r.fallback;
  const OutlineStats& o = r.outline_stats;
  std::fprintf(stderr,
               "method=%s\npolygons=%u\ntriangles=%u\nconcave_polygons=%u\nfront_faces=%u\n"
               "back_faces=%u\nh1=%u\nh2=%u\nh3=%u\nh4=%u\nloose_edges=%u\nboundary_edges=%u\n"
               "nonmanifold_edges=%u\nmisoriented_edges=%u\ncrossings=%llu\nincidences=%u\n"
               "coincident_vertices=%u\n",
               r.used_qi ? "qi" : "fallback", tri.polygons, tri.triangles, tri.concave,
               r.classes.front_faces, r.classes.back_faces, r.classes.h[1], r.classes.h[2],
               r.classes.h[3], r.classes.h[4], r.classes.h[0], r.check.boundary_edges,
               r.check.nonmanifold_edges, r.check.misoriented_edges,
               (unsigned long long)r.cut.crossings, r.incidences, r.coincident_vertices);
  if (r.used_qi)
    std::fprintf(stderr,
                 "qi_components=%u\nqi_ray_casts=%u\nqi_conflicts=%u\nrule_crossing=%llu\n"
                 "rule_wedge=%llu\nrule_delta=%llu\nrule_quarter=%llu\nrule_half=%llu\n"
                 "rule_occluded=%llu\nrule_degenerate=%llu\nqi_two_sided=%d\n"
                 "qi_first_conflicts=%u\nqi_pierces=%llu\nqi_pierce_tests=%llu\n",
                 q.components, q.ray_casts, q.conflicts, (unsigned long long)q.crossings,
                 (unsigned long long)q.wedge, (unsigned long long)q.delta,
                 (unsigned long long)q.quarter, (unsigned long long)q.half,
                 (unsigned long long)q.occluded, (unsigned long long)q.degenerate,
                 r.check.manifold() ? 0 : 1, q.first_conflicts, (unsigned long long)q.pierces,
                 (unsigned long long)q.pierce_tests);
  else
    std::fprintf(stderr,
                 "fallback_pieces=%llu\nfallback_tests=%llu\nfallback_face_tests=%llu\n"
                 "vc_saved=%llu\nclass_saved=%llu\npeculiar_a=%u\npeculiar_b=%u\n"
                 "pierces=%llu\npierce_tests=%llu\n",
                 (unsigned long long)f.pieces, (unsigned long long)f.tests,
                 (unsigned long long)f.face_tests, (unsigned long long)f.vc_saved,
                 (unsigned long long)f.class_saved, f.contours_end_twice, f.contours_start_twice,
                 (unsigned long long)f.pierces, (unsigned long long)f.pierce_tests);
  const IntersectionStats& x = r.intersection_stats;
  std::fprintf(stderr,
               "intersection_pairs=%llu\nintersection_segments=%llu\nintersection_pieces=%llu\n"
               "intersection_tests=%llu\n",
               (unsigned long long)x.pairs, (unsigned long long)x.segments,
               (unsigned long long)x.pieces, (unsigned long long)x.tests);
  if (o.contour_edges > 0)
    std::fprintf(stderr,
                 "outline_contour_segments=%u\noutline_circuits=%u\noutline_potential=%u\n"
                 "outlines=%u\noutline_condition_tests=%u\noutline_one_by_one=%u\n",
                 o.unit_segments, o.circuits, o.potential, o.outlines, o.condition_tests,
                 o.one_by_one);
  std::fprintf(stderr,
               "bytes_topology=%zu\nbytes_incidence=%zu\nbytes_cut=%zu\nbytes_qi=%zu\n"
               "bytes_fallback=%zu\nbytes_outline=%zu\nbytes_intersections=%zu\n"
               "hidden_ms=%.3f\nhidden_cpu_ms=%.3f\n",
               r.bytes_topology, r.bytes_incidence, r.bytes_cut, r.bytes_qi, r.bytes_fallback,
               r.bytes_outline, r.bytes_intersections, r.ms_total, r.cpu_ms_total);
}

// Everything of a run but its counts (--stats prints them), and the scene's arrays, once the
// drawing holds all the files need: the pen path's planning, whose own memory came on top of
// them, was the 1M-triangle torus plot's peak (some 90 MB of them).
void drop_pieces(SolidRun* run, SolidScene* scene) {
  *scene = SolidScene{};
  run->pieces = {};
  run->contour_diagonals = {};
  run->intersections = {};
  run->intersection_faces = {};
  run->hatch = {};
  run->hatch_faces = {};
  run->hatch_polygons = {};
  run->edges = {};
  run->outline = {};
}

// The job `sim` runs for this drawing, for --gcode and --hpgl: a hidden-line drawing's
// strokes, decided here, layer by layer (planned once, for the SVG too); in mode all the
// model's edges whole (the same lines, not split where others cross them).
struct PlotterJob {
  JobSpec spec;
  ExportStyle style;
  std::vector<Edge3> edges;
  bool planned_once = false;
  PlannedJob planned;
};

bool plotter_job(const Options& o, const SolidOptions& so, const ModeDrawing& d, PlotterJob* job,
                 std::string* error) {
  job->spec.drawing = DrawingEffect::kAllEdges;
  if (!export_style_of(o, &job->style, &job->spec.machine, error) ||
      !parse_path_clean(o, job->style.steps_per_mm, &job->spec.clean, error))
    return false;
  if (so.spec.mode != SolidMode::kAll) {
    job->edges = mode_strokes(d, &job->spec.layers);
    job->planned_once = true;
    return true;
  }
  Options edge_options = o;
  edge_options.values.erase("--dump-edges");  // written once, with the scene
  return load_scene(edge_options, o.positional[0], &job->edges, error, &job->spec.substep_bits);
}

// The pen's settings and the clean-up, checked before the hidden lines are worked out.
bool pen_settings_fit(const Options& o, const SolidOptions& so, std::string* error) {
  ExportStyle style;
  Machine machine;
  PathClean clean;
  if (wants_plotter_outputs(o) && !export_style_of(o, &style, &machine, error)) return false;
  if (!parse_path_clean(o, so.steps_per_mm, &clean, error)) return false;
  // A dash shorter than the minimum stroke is dropped whole: every hidden line would vanish.
  if (so.spec.mode == SolidMode::kHiddenDashed && clean.on && clean.min_stroke > 0 &&
      uint32_t(so.spec.dash_steps) < clean.min_stroke) {
    *error = "--dash " + o.get("--dash", "2,1") + ": a dash is shorter than the minimum stroke (" +
             (o.get("--min-stroke").empty() ? "the pen width, " + o.get("--pen-width", "0.3")
                                            : o.get("--min-stroke")) +
             " mm), so every dash would be dropped: lengthen the dashes or lower --min-stroke";
    return false;
  }
  return true;
}

}  // namespace

int cmd_plot_solid(const Options& o) {
  std::string error;
  SolidOptions so;
  if (!parse_solid_options(o, &so, &error) || !read_threads_option(o, &so.parts, &error))
    return fail(error);
  // Options the mode has no use for are refused, never ignored.
  if (so.spec.mode == SolidMode::kAll && !o.get("--hatch").empty())
    return fail(
        "--hatch shades the visible faces: use it with --mode hidden-removed or "
        "hidden-dashed (--mode all hides nothing)");
  if (so.spec.mode != SolidMode::kHiddenDashed && !o.get("--dash").empty())
    return fail("--dash sets the hidden lines' dashes: use it with --mode hidden-dashed (--mode " +
                o.get("--mode") + " draws no dashes)");
  if (!pen_settings_fit(o, so, &error)) return fail(error);
  if (!o.get("--halo").empty() || o.has("--exact-halo"))
    return fail("--halo belongs to --mode haloed (HALO needs no faces)");
  // Not silently ignored: a solid's bands are a job's (the same strokes in any arena).
  if (!o.get("--arena").empty())
    return fail("--arena with --mode " + o.get("--mode") +
                ": a solid's drawing is the same in any arena; to plot it in bands as a "
                "controller would, give its job 'arena BYTES' and run `haloplot sim JOB.job`");
  SolidScene scene;
  TriangulateStats tri;
  {
    const StageProgress stage("reading " + o.positional[0]);
    if (!load_solid_scene(o, o.positional[0], &scene, &tri, &error)) return fail(error);
  }
  // The file's model (faces, sides, the reader's text) is freed now; give its pages back before
  // the hidden lines take their own (main.cpp keeps freed memory for reuse, which the stage's
  // large buffers, fresh pages, never reuse): a 1M-triangle plot's peak is the larger of the
  // two, not their sum. A small model's are kept: the stage's smaller buffers reuse them.
  give_back_freed_memory();
  SolidRun run;
  Status s = Status::kOk;
  {
    const StageProgress stage("hidden lines");
    s = run_solid_options(scene, so, &run);
  }
  if (!ok(s)) return fail(o.positional[0] + ": hidden lines failed: " + status_name(s));
  say_repair_note(scene);
  if (!run.fallback_reason.empty() && so.method == HiddenMethod::kAuto)
    std::cerr << "haloplot: " << o.positional[0] << ": " << run.fallback_reason
              << " (--method fallback: every piece of every edge tested against the faces)\n";
  // Decided in the scene's units (dashes and hatch spacing converted), drawn in steps.
  const int32_t units = scene.substep_bits;
  ModeDrawing d = make_mode_drawing(run, mode_in_units(so.spec, units));
  drawing_to_steps(&d, units);
  const std::string repair_stats = scene.repair_stats;
  drop_pieces(&run, &scene);  // the drawing holds all the files need
  PlotSvgStyle style;
  if (!parse_plot_svg_style(o, true, so.steps_per_mm, &style, &error)) return fail(error);
  const std::vector<StrokeLayer> layers = mode_layers(d);
  std::vector<PlannedLayer> page_layers;
  PlotterJob job;
  if (wants_plotter_outputs(o)) {
    if (!plotter_job(o, so, d, &job, &error)) return fail(error);
    const StageProgress stage("planning the pen path");
    if (job.planned_once && !plan_plot_job(job.spec, job.edges, &job.planned)) return 1;
    // The SVG's layers are the job's path cut at its layers: planned once, for both.
    if (job.planned_once &&
        !cut_planned_layers(layers, job.planned.points, job.planned.layer_points, &page_layers))
      return fail("the planned path's layers do not match the drawing's (" +
                  std::to_string(job.planned.layer_points.n) + " layers)");
  }
  const StageProgress writing("writing the files");
  if (!o.get("-o").empty())  // -o is optional with --gcode or --hpgl
    error = job.planned_once ? write_planned_page(o.get("-o"), page_layers, true, &style)
                             : write_plot_page(o.get("-o"), layers, true, &style);
  if (!error.empty()) return fail(error);
  if (wants_plotter_outputs(o)) {
    const int rc = job.planned_once
                       ? write_planned_outputs(o, job.spec, std::move(job.planned), job.style, true)
                       : write_plot_outputs(o, job.spec, job.edges, job.style, true);
    if (rc != 0) return rc;
  }
  if (!error.empty()) return fail(error);
  if (!o.get("--spans").empty()) {
    error = write_atomically(o.get("--spans"), [&](std::ostream& out) {
      write_spans_qi(out, d.spans, d.qi, d.outline, d.hatch);
      return true;
    });
    if (!error.empty()) return fail(error);
  }
  if (o.has("--stats")) {
    std::fputs(repair_stats.c_str(), stderr);
    print_solid_stats(run, tri);
    // With --gcode or --hpgl the job's own plan reports its clean-up (write_planned_outputs).
    if (!wants_plotter_outputs(o)) print_clean_stats(style.path_stats, so.steps_per_mm);
    if (so.hatch) {
      const HatchLineStats& h = run.hatch_stats;
      std::fprintf(stderr,
                   "hatch_faces=%u\nhatch_lines=%llu\nhatch_pieces=%llu\nhatch_tests=%llu\n"
                   "hatch_strokes=%zu\n",
                   h.faces, (unsigned long long)h.lines, (unsigned long long)h.pieces,
                   (unsigned long long)h.tests, d.hatch.size());
    }
  }
  return 0;
}

}  // namespace haloplot::host
