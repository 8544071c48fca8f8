#include "cli/cmd_plot_curves.h"

#include <cstdio>
#include <fstream>
#include <iostream>

#include "cli/band_stats.h"
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/page_options.h"
#include "cli/plot_outputs.h"
#include "demo/curve_scenes.h"
#include "export/plotter_outputs.h"
#include "haloplot/geometry/units.h"
#include "io/atomic_file.h"
#include "io/edges_file.h"
#include "io/line_reader.h"
#include "io/spans_file.h"
#include "pipeline/curve_pipeline.h"
#include "pipeline/units.h"

namespace haloplot::host {

namespace {

// The scene's curve drawing, the chords numbered by the file's data lines, in its units. The
// stages' settings are a job's (job/job.h curve_job_params): `plot` draws what `sim` and the
// controller plot.
// With an arena (> 0) in bands, as a controller with that arena draws it (chords in steps).
bool draw_scene(const std::string& path, int32_t halo_steps, bool exact, uint32_t arena,
                HostCurveDraw* d, BandStats* bands, int32_t* substep_bits, std::string* error) {
  EdgesWithCurves scene;
  const InputError ie = read_edges_with_curves_file(path, &scene, substep_bits);
  if (ie.failed()) {
    *error = ie.message();
    return false;
  }
  JobSpec spec;
  spec.draw.halo = halo_steps;
  spec.substep_bits = *substep_bits;
  CurveCrossParams cp;
  CurveDrawParams p;
  curve_job_params(spec, &cp, &p);
  CurveBandSpec band;
  Status s = arena > 0 ? curve_band_spec(spec, &band) : Status::kOk;
  if (ok(s))
    s = arena > 0 ? host_banded_curve_draw(scene.curves, scene.edges, band, arena, d, bands)
                  : host_curve_draw(scene.curves, scene.edges, cp, p, d, exact);
  if (s == Status::kArenaTooSmall) {
    *error = arena_too_small("plot", arena, bands->need_bytes);
    return false;
  }
  if (!ok(s)) {
    *error = path + ": curve drawing failed: " + status_name(s);
    return false;
  }
  const uint32_t nc = uint32_t(scene.curves.size());
  for (Span& c : d->chords)
    c.edge = c.edge < nc ? scene.curve_index[c.edge] : scene.edge_index[c.edge - nc];
  return true;
}

std::vector<Edge3> chord_edges(const std::vector<Span>& chords) {
  std::vector<Edge3> edges;
  edges.reserve(chords.size());
  for (const Span& c : chords) edges.push_back(Edge3{{c.x0, c.y0, 0}, {c.x1, c.y1, 0}});
  return edges;
}

void print_stats(const HostCurveDraw& d) {
  std::fprintf(
      stderr,
      "curves_cross_ms=%.3f\ncurve_pieces=%u\ncrossings=%u\ntouches=%u\n"
      "cross_scratch_bytes=%zu\ncurve_draw_ms=%.3f\ngaps=%llu\njoint_crossings=%llu\n"
      "carried=%llu\nundecided=%llu\njoints=%u\nintervals=%llu\nchords=%llu\nhidden_edges=%llu\n"
      "draw_scratch_bytes=%zu\n",
      d.cross_ms, d.cross_stats.pieces, d.cross_stats.crossings, d.cross_stats.touches,
      d.cross_scratch_bytes, d.draw_ms, (unsigned long long)d.stats.gaps,
      (unsigned long long)d.stats.joint_crossings, (unsigned long long)d.stats.carried,
      (unsigned long long)d.stats.undecided, d.stats.joints, (unsigned long long)d.stats.intervals,
      (unsigned long long)d.stats.chords, (unsigned long long)d.stats.hidden, d.draw_scratch_bytes);
}

// CUT's options and the other ways of drawing have no meaning for a curve scene: refused by
// name rather than ignored.
std::string refused_option(const Options& o) {
  for (const char* cut : {"--lambda", "--cell", "--cover", "--reach"})
    if (!o.get(cut).empty())
      return std::string(cut) +
             " is CUT's grid option: a scene with Bézier edges finds its crossings by "
             "subdividing the curves (docs/curves.md)";
  // As load_scene() says for any .edges file: projected already, in steps or its header's units.
  for (const char* model : {"--view", "--perspective", "--up", "--crease", "--dump-edges", "--eye",
                            "--look-at", "--fov", "--roll", "--substep", "--weld"})
    if (!o.get(model).empty())
      return std::string(model) +
             " is for models (.obj, .stl, .ply): an .edges file is a scene projected already, "
             "drawn as it is";
  if (!o.get("--arena").empty() && o.has("--exact-halo"))
    return "--arena with --exact-halo: the exact halo is drawn whole, on the host only";
  if (!o.get("--arena").empty() && wants_plotter_outputs(o))
    return "--gcode and --hpgl plot the whole drawing's path: drop --arena, or give the job "
           "'arena BYTES' and run `haloplot sim JOB.job --gcode ...`";
  if (!o.get("--cut").empty()) return "--cut: a scene with Bézier edges has no CUTSET to write";
  if (o.get("--halo").empty()) return "--halo W (steps) is required";
  return "";
}

}  // namespace

bool edges_file_has_curves(const std::string& path) {
  if (path.size() < 6 || path.compare(path.size() - 6, 6, ".edges") != 0) return false;
  // A scan for the record's word, not a parse: a straight scene is parsed once, by the straight
  // path; a curve scene's errors are reported by the curve path's parse.
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    const size_t first = line.find_first_not_of(" \t");
    if (first != std::string::npos && line.compare(first, 6, "bezier") == 0) return true;
  }
  return false;
}

int cmd_plot_curves(const Options& o) {
  if (const std::string why = refused_option(o); !why.empty()) return fail(why);
  int64_t halo = 0;
  if (!parse_int(o.get("--halo"), 0, kCoordMax, &halo))
    return fail("--halo '" + o.get("--halo") + "' must be an integer in [0, " +
                std::to_string(kCoordMax) + "]");
  int64_t arena = 0;
  if (!o.get("--arena").empty() && !parse_int(o.get("--arena"), 1024, int64_t{1} << 30, &arena))
    return fail("--arena needs a byte count in [1024, 2^30]");
  HostCurveDraw d;
  BandStats bands;
  int32_t units = 0;
  std::string error;
  if (!draw_scene(o.positional[0], int32_t(halo), o.has("--exact-halo"), uint32_t(arena), &d,
                  &bands, &units, &error))
    return fail(error);
  if (wants_plotter_outputs(o)) {
    JobSpec spec;
    spec.drawing = DrawingEffect::kAllEdges;  // the chords, drawn whole
    spec.substep_bits = units;
    ExportStyle style;
    if (!export_style_of(o, &style, &spec.machine, &error) ||
        !parse_path_clean(o, style.steps_per_mm, &spec.clean, &error))
      return fail(error);
    if (const int rc = write_plot_outputs(o, spec, chord_edges(d.chords), style, false)) return rc;
  }
  std::vector<Span> spans = d.chords;
  if (arena == 0) spans_to_steps(&spans, units);  // the bands' chords are in steps already
  int64_t per_mm = 80;
  if (!o.get("--steps-per-mm").empty() && !parse_int(o.get("--steps-per-mm"), 1, 10000, &per_mm))
    return fail("--steps-per-mm '" + o.get("--steps-per-mm") +
                "' must be an integer in [1, 10000]");
  PlotSvgStyle style;
  if (!parse_plot_svg_style(o, false, uint32_t(per_mm), &style, &error)) return fail(error);
  if (!o.get("-o").empty())  // -o is optional with --gcode or --hpgl
    error = write_plot_page(o.get("-o"), {StrokeLayer{"1 visible", spans, 1}}, false, &style);
  if (!error.empty()) return fail(error);
  if (!o.get("--spans").empty()) {
    error = write_atomically(o.get("--spans"), [&](std::ostream& out) {
      write_spans(out, spans);
      return true;
    });
    if (!error.empty()) return fail(error);
  }
  if (o.has("--stats")) {
    print_stats(d);
    if (arena > 0) print_band_stats(bands, size_t(arena));
  }
  return 0;
}

int cmd_demo_curve(const Options& o) {
  const std::string name = o.get("--curve");
  if (o.get("-o").empty() || !o.positional.empty() || name.empty() || !o.get("--cubes").empty())
    return fail("demo-scene --curve NAME [--edges N] -o SCENE.edges: " +
                std::string(name.empty()            ? "--edges needs --curve"
                            : o.get("-o").empty()   ? "missing -o OUTPUT"
                            : !o.positional.empty() ? "takes no input file"
                                                    : "--cubes is for the cube array"));
  int p = 0, q = 0;
  const bool torus = std::sscanf(name.c_str(), "torus-%d-%d", &p, &q) == 2 && p > 0 && q > 0 &&
                     p <= 16 && q <= 16 &&
                     name == "torus-" + std::to_string(p) + "-" + std::to_string(q);
  if (name != "trefoil" && name != "helix" && !torus)
    return fail("--curve '" + name + "' must be trefoil, torus-P-Q (P, Q in 1..16) or helix");
  // The test scenes' edge counts (tests/unit/test_curves.cpp): with 40 edges every crossing of
  // the (2,5) knot falls on a joint, which no stage counts as a crossing.
  int64_t edges = name == "trefoil" ? 24 : name == "helix" ? 24 : 42;
  if (!o.get("--edges").empty() && !parse_int(o.get("--edges"), 2, 10000, &edges))
    return fail("--edges '" + o.get("--edges") + "' must be an integer in [2, 10000]");
  // 180 mm square at 80 steps per mm: inside an A4 page's drawable area either way round.
  CurveView view;
  view.size = 15200;
  view.margin = 400;
  // Perspective: the eye D world units from the knot's centre (its largest extent 2^19 units),
  // outside it; the image fitted within kPerspectiveFitSteps (demo/curve_scenes.h).
  if (!o.get("--perspective").empty()) {
    int64_t d = 0;
    if (name == "helix" || !parse_int(o.get("--perspective"), 262145, 2097152, &d))
      return fail(name == "helix" ? "--perspective is for the knots (trefoil, torus-P-Q)"
                                  : "--perspective '" + o.get("--perspective") +
                                        "' must be an integer in [262145, 2097152] (world "
                                        "units, the knot 2^19 across: the eye outside it)");
    view.perspective = double(d);
  }
  CurveScene scene;
  if (name == "trefoil") {
    scene = trefoil_knot(int(edges), view);
  } else if (torus) {
    scene = torus_knot(p, q, int(edges), view);
  } else {
    view.tilt = 1.0;  // seen from the side enough for its turns to cross
    scene = helix(4, 1.0, int(edges), true, view);
  }
  const std::string header =
      "# haloplot demo: " + name + ", " + std::to_string(scene.curves.size()) +
      " cubic Bézier edges (docs/curves.md)" +
      (view.perspective > 0 ? ", in perspective from " + o.get("--perspective") : std::string()) +
      "; x y z in steps, z larger = nearer\n";
  const std::string error = write_atomically(o.get("-o"), [&](std::ostream& out) {
    write_edges_with_curves(out, scene.curves, scene.segments, header);
    return true;
  });
  return error.empty() ? 0 : fail(error);
}

bool load_curve_job(const std::string& scene_path, const JobSpec& spec, EdgesWithCurves* scene,
                    int32_t* substep_bits, std::string* error) {
  if (spec.drawing != DrawingEffect::kHaloed || spec.draw.mode != HaloMode::kPaper) {
    *error = scene_path +
             ": a job of a scene with Bézier edges is drawn haloed with the paper's gap (the "
             "exact halo: `haloplot plot --exact-halo`, on the host)";
    return false;
  }
  const InputError ie = read_edges_with_curves_file(scene_path, scene, substep_bits);
  if (ie.failed()) *error = ie.message();
  return !ie.failed();
}

}  // namespace haloplot::host
