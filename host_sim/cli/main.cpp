// haloplot: the host tool. Runs the same freestanding core as the firmware.
//   haloplot demo-scene [--cubes N] -o SCENE.edges
//   haloplot cut SCENE.edges -o SCENE.cut [cut options] [--stats]
//   haloplot draw SCENE.cut --halo W [--exact-halo] -o OUT.svg [--spans OUT.spans] [--stats]
//   haloplot plot SCENE.edges --halo W [--exact-halo] -o OUT.svg [--spans F] [--cut F] [--stats]
#include <unistd.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "cli/cmd_plot_curves.h"
#include "cli/options.h"
#include "cli/page_options.h"
#include "cli/plot_outputs.h"
#include "cli/stage_progress.h"
#include "demo/cube_array.h"
#include "demo/random_scene.h"
#include "export/exporters.h"
#include "export/plotter_outputs.h"
#include "io/atomic_file.h"
#include "io/cut_file.h"
#include "io/edges_file.h"
#include "io/job_file.h"
#include "io/line_reader.h"
#include "io/mesh_file.h"
#include "io/spans_file.h"
#include "io/substep_header.h"
#include "pipeline/host_pipeline.h"
#include "pipeline/scene_input.h"
#include "pipeline/units.h"
#include "render/svg.h"
#include "sim/replay.h"
#include "sim/simulator.h"
#include "sim/trace.h"

using namespace haloplot;
using namespace haloplot::host;

namespace haloplot::host {
int cmd_plot_solid(const Options& o);  // cli/cmd_plot_solid.cpp
}  // namespace haloplot::host

namespace {

const char* kUsage =
    "usage:\n"
    "  haloplot demo-scene [--cubes N] -o SCENE.edges|MODEL.obj   (.obj: the cubes as solids)\n"
    "               [--curve trefoil|torus-P-Q|helix [--edges N] [--perspective D]]   (a knot\n"
    "               or a helix as cubic Bézier edges, N of them, for plot's curve path; a knot\n"
    "               seen in perspective from D world units: docs/curves.md)\n"
    "  haloplot random-scene --edges N --length L [--seed S] -o SCENE.edges\n"
    "  haloplot cut SCENE.edges -o SCENE.cut [--lambda X] [--cell G] [--cover exact|bbox]\n"
    "               [--reach R] [--stats]\n"
    "  haloplot draw SCENE.cut --halo W [--exact-halo] -o OUT.svg [--spans OUT.spans] [--stats]\n"
    "               [--steps-per-mm N]   (plot steps per mm on the page; default 80)\n"
    "               [page options: --page, --landscape, --margin, --pen-width, --background,\n"
    "               --min-stroke, --simplify, --no-cleanup;\n"
    "               --fit and --scale place a model, and a .cut scene is in steps: refused]\n"
    "  haloplot plot SCENE.edges|MODEL --halo W [--exact-halo] -o OUT.svg [--spans OUT.spans]\n"
    "               [--cut OUT.cut] [--arena BYTES] [--steps-per-mm N] [--stats]\n"
    "               [--lambda X] [--cell G] [--cover exact|bbox] [--reach R]   (as cut's)\n"
    "               [--view AZ,EL] [--perspective D] [--up AXIS] [--dump-edges OUT.edges]\n"
    "               [--substep S] [--weld EPS|0|off] [--crease DEG|exact|off]   (MODEL: .obj,\n"
    "               .stl or .ply; --up x|y|z|-x|-y|-z: the file's up axis, default z for STL\n"
    "               as 3-D printing writes it, y for OBJ and PLY; --substep: decide in units\n"
    "               of 2^-S steps; by default corners within the file's rounding are welded\n"
    "               and edges between faces flat but for it left out: docs/cli.md)\n"
    "  camera (any MODEL form): [--eye X,Y,Z --look-at X,Y,Z [--fov DEG]] [--roll DEG]\n"
    "               (instead of --view/--perspective: look from the eye (file coordinates)\n"
    "               toward the look-at point; --fov: in perspective, the eye backed off until\n"
    "               the model fills the field of view; --roll: the picture turned\n"
    "               counterclockwise about the view axis)\n"
    "  haloplot plot MODEL --mode all|hidden-removed|hidden-dashed -o OUT.svg [--outline]\n"
    "               [--no-intersections]   (the lines where faces cross are drawn by default)\n"
    "               [--dash LEN,GAP (mm)] [--steps-per-mm N] [--method auto|qi|fallback]\n"
    "               [--hatch SPACING[,ANGLE[,TURN]]] [--spans OUT.spans] [--view AZ,EL]\n"
    "               [--perspective D] [--up AXIS] [--substep S] [--weld EPS|0|off]\n"
    "               [--crease DEG|exact|off] [--stats]\n"
    "  haloplot plot SCENE.edges|MODEL ... [--gcode OUT.gcode] [--hpgl OUT.hpgl]   (either form\n"
    "               above: the plotter's files from the planned path, no step simulation, and\n"
    "               the plot time on stderr; the same bytes `sim` writes for the same job;\n"
    "               -o may then be left out: no SVG)\n"
    "               [--pen servo|z|custom] [--servo-down S] [--z-up MM] [--z-down MM]\n"
    "               [--z-feed MM/MIN] [--pen-up-gcode TEXT] [--pen-down-gcode TEXT]\n"
    "               [--draw-feed MM/MIN] [--travel-feed MM/MIN] [--pen-dwell SECONDS]\n"
    "               [--gcode-flavor grbl|marlin] [--servo-up ANGLE] [--gcode-header TEXT]\n"
    "               [--gcode-footer TEXT]\n"
    "               (the G-code's pen commands and feeds; TEXT: G-code, \\n between lines)\n"
    "               [--pause-between-layers]   (hidden-line modes draw layer by layer, as the\n"
    "               SVG's layers; this adds a pen change between layers: M0 in the G-code,\n"
    "               the layer's pen SP1..SP5 in the HPGL)\n"
    "  page options (plot, draw): [--page a4|a3|a5|letter|legal|tabloid|WxH] [--landscape]\n"
    "               [--margin MM] [--fit | --scale S] [--pen-width MM] [--background]\n"
    "               [--min-stroke MM] [--no-cleanup]   (strokes shorter than MM, default\n"
    "               the pen width, are not drawn, 0 keeps all; dots are never drawn and\n"
    "               collinear overlaps once; --no-cleanup: the strokes as found, for tests)\n"
    "               [--simplify MM]   (points of a stroke within MM of the line drawn\n"
    "               instead are left out: fewer, longer moves on a dense mesh; default 0)\n"
    "               (the SVG is the page, default A4 landscape, 10 mm margins; a model is\n"
    "               fitted and centred, or drawn at S mm per model unit; named pages are\n"
    "               portrait; --pen-width: stroke width, default 0.3; --background: a white\n"
    "               page rectangle, for viewing only)\n"
    "  haloplot sim JOB.job -o OUT.trace [--gcode OUT.gcode] [--hpgl OUT.hpgl] [--arena BYTES]\n"
    "               [--binary] [--stats]   (--binary: the compact binary trace)\n"
    "               [--pause-at E1,E2,...] [--resume-at E]   (feed holds; go on from event E)\n"
    "  haloplot replay IN.trace -o OUT.svg [--stats]\n"
    "  haloplot send JOB.job --port PATH [--replot W] [--corrupt-every K] [--truncate-every K]\n"
    "               [--test-exit]   (upload to a controller over its serial port or socket)\n"
    "               [--pause-after EVENTS] [--stop-after EVENTS [--stop abort|limit]]\n"
    "               [--resume EVENTS] [--seed S] [--trace-digest]\n"
    "               [--reply-timeout MS]   (how long to wait for each reply before resending,\n"
    "               20 tries in all; default 3000, ample on a serial link: raise it for a\n"
    "               slow emulated controller)\n"
    "  haloplot view2d POLYGON.txt --from X,Y -o OUT.svg [--spans OUT.spans] [--trace OUT.trace]\n"
    "               [--stats]   (which parts of a polygon are visible from a point)\n";

// After "a band one row high needs N": N is the band where the plot stopped, not the job's
// least arena (what a band needs depends on what the band below hands it).
const char* const kFurtherBands = " where the plot stopped (bands further on may need more)";

int fail(const std::string& message) {
  std::cerr << "haloplot: " << message << "\n";
  return 1;
}

// Commands that take one input file and an -o output.
bool one_input_and_output(const Options& o) {
  return o.positional.size() == 1 && !o.get("-o").empty();
}

// The usage lines of one command (its line in kUsage and the lines that continue it).
std::string usage_of(const std::string& cmd) {
  std::istringstream in(kUsage);
  std::string line, out;
  bool in_cmd = false;
  while (std::getline(in, line)) {
    if (line.rfind("  haloplot ", 0) == 0) in_cmd = line.rfind("  haloplot " + cmd + " ", 0) == 0;
    if (in_cmd) out += line + "\n";
  }
  return out.empty() ? std::string(kUsage) : "usage:\n" + out;
}

// What is missing or extra among the input and -o, named, then the command's usage.
int bad_arguments(const Options& o, const std::string& cmd) {
  std::string what;
  if (o.positional.empty())
    what = "missing the input file";
  else if (o.positional.size() > 1)
    what = "one input file expected, got " + std::to_string(o.positional.size()) + " ('" +
           o.positional[0] + "', '" + o.positional[1] + "'" +
           (o.positional.size() > 2 ? ", ..." : "") + ")";
  else
    what = "missing -o OUTPUT";
  return fail(cmd + ": " + what + "\n" + usage_of(cmd));
}

int fail_status(const char* stage, Status s) {
  return fail(std::string(stage) + " failed: " + status_name(s));
}

void progress(void*, uint32_t done, uint32_t total) {
  static uint32_t last_pct = 101;
  const uint32_t pct = total ? uint32_t(uint64_t(done) * 100 / total) : 100;
  if (pct == last_pct) return;
  last_pct = pct;
  std::fprintf(stderr, "\rCUT: %3u%% of %u cells%s", pct, total, pct == 100 ? "\n" : "");
}

bool read_int_option(const Options& o, const std::string& name, int64_t lo, int64_t hi,
                     int64_t* out, std::string* error) {
  const std::string v = o.get(name);
  if (v.empty()) return true;
  if (!parse_int(v, lo, hi, out)) {
    *error = name + " '" + v + "' must be an integer in [" + std::to_string(lo) + ", " +
             std::to_string(hi) + "]";
    return false;
  }
  return true;
}

// --lambda accepts a decimal like 1.5; stored as Q8.8 without floating point.
bool parse_lambda(const std::string& s, uint32_t* q8) {
  const size_t dot = s.find('.');
  int64_t whole = 0, frac = 0;
  const std::string w = s.substr(0, dot);
  if (!parse_int(w.empty() ? "0" : w, 0, 1000, &whole)) return false;
  uint64_t scale = 1;
  if (dot != std::string::npos) {
    const std::string f = s.substr(dot + 1);
    if (f.empty() || f.size() > 6 || !parse_int(f, 0, 999999, &frac)) return false;
    for (size_t i = 0; i < f.size(); ++i) scale *= 10;
  }
  const uint64_t v = uint64_t(whole) * 256 + (uint64_t(frac) * 256 + scale / 2) / scale;
  if (v == 0) return false;
  *q8 = uint32_t(v);
  return true;
}

bool cut_params(const Options& o, CutParams* p, std::string* error) {
  if (!o.get("--lambda").empty() && !parse_lambda(o.get("--lambda"), &p->grid.lambda_q8)) {
    *error = "--lambda '" + o.get("--lambda") + "' must be a positive decimal up to 1000";
    return false;
  }
  int64_t cell = 0, reach = 0;
  if (!read_int_option(o, "--cell", 1, kCoordLimit, &cell, error)) return false;
  if (!read_int_option(o, "--reach", 0, kCoordMax, &reach, error)) return false;
  p->grid.cell = int32_t(cell);
  p->reach = int32_t(reach);
  const std::string cover = o.get("--cover", "exact");
  if (cover == "exact")
    p->cover = CellCover::kExact;
  else if (cover == "bbox")
    p->cover = CellCover::kBoundingBox;
  else {
    *error = "--cover must be 'exact' or 'bbox'";
    return false;
  }
  if (isatty(2)) p->progress = &progress;
  return true;
}

bool draw_params(const Options& o, DrawParams* p, std::string* error) {
  if (o.get("--halo").empty()) {
    *error = "--halo W (steps) is required";
    return false;
  }
  int64_t halo = 0;
  if (!read_int_option(o, "--halo", 0, kCoordMax, &halo, error)) return false;
  p->halo = int32_t(halo);
  p->mode = o.has("--exact-halo") ? HaloMode::kExact : HaloMode::kPaper;
  return true;
}

std::string grid_text(const CutPlan& plan) {
  return std::to_string(plan.grid.nx) + "x" + std::to_string(plan.grid.ny);
}

// The CUT statistics that do not depend on the machine, so a .cut file stays deterministic.
std::string cut_header(const HostCut& c) {
  std::ostringstream h;
  h << "# stats edges=" << c.set.n_edges << " crossings=" << c.stats.crossings
    << " near=" << c.stats.near_misses << " grid=" << grid_text(c.plan)
    << " cell=" << c.plan.grid.cell << " cell_pairs=" << c.stats.cell_pairs
    << " pairs_tested=" << c.stats.pairs_tested << " rejected=" << c.stats.rejected
    << " equal_depth=" << c.stats.equal_depth << "\n";
  return h.str();
}

void print_cut_stats(const HostCut& c) {
  std::fprintf(stderr,
               "edges=%u\ncrossings=%llu\nnear=%llu\ngrid=%s\ncell=%d\ncell_pairs=%u\n"
               "pairs_tested=%llu\nrejected=%llu\nequal_depth=%llu\ncut_ms=%.3f\n"
               "cut_retries=%d\ncut_scratch_bytes=%zu\ncutset_bytes=%zu\n",
               c.set.n_edges, (unsigned long long)c.stats.crossings,
               (unsigned long long)c.stats.near_misses, grid_text(c.plan).c_str(), c.plan.grid.cell,
               c.stats.cell_pairs, (unsigned long long)c.stats.pairs_tested,
               (unsigned long long)c.stats.rejected, (unsigned long long)c.stats.equal_depth,
               c.cut_ms, c.retries, c.scratch_bytes,
               cutset_bytes(c.set.n_edges, c.set.n_crossings));
}

void print_draw_stats(const HostDraw& d) {
  std::fprintf(stderr,
               "draw_ms=%.3f\nspans=%llu\ngaps=%llu\nhidden_edges=%llu\ndraw_scratch_bytes=%zu\n",
               d.draw_ms, (unsigned long long)d.stats.spans, (unsigned long long)d.stats.gaps,
               (unsigned long long)d.stats.hidden_edges, d.scratch_bytes);
}

// Writes the SVG and, if asked, the spans. `model`: the scene was a model the projection
// fitted (centred on the page). Returns 0 or 1 after reporting.
int write_drawing(const Options& o, const HostDraw& d, bool model) {
  int64_t per_mm = 80;
  if (!o.get("--steps-per-mm").empty() && !parse_int(o.get("--steps-per-mm"), 1, 10000, &per_mm))
    return fail("--steps-per-mm '" + o.get("--steps-per-mm") +
                "' must be an integer in [1, 10000]");
  PlotSvgStyle style;
  std::string err;
  if (!parse_plot_svg_style(o, model, uint32_t(per_mm), &style, &err)) return fail(err);
  if (!o.get("-o").empty())
    err = write_plot_page(o.get("-o"), {StrokeLayer{"1 visible", d.spans, 1}}, model, &style);
  if (!err.empty()) return fail(err);
  // With --gcode or --hpgl the job's own plan reports its clean-up (write_planned_outputs).
  if (o.has("--stats") && !wants_plotter_outputs(o))
    print_clean_stats(style.path_stats, style.placement.steps_per_mm);
  if (!o.get("--spans").empty()) {
    err = write_atomically(o.get("--spans"), [&](std::ostream& out) {
      write_spans(out, d.spans);
      return true;
    });
    if (!err.empty()) return fail(err);
  }
  return 0;
}

void warn_reach(const HostDraw& d, int32_t halo, int32_t reach) {
  if (d.stats.reach_short)
    std::cerr << "haloplot: warning: exact halo " << halo << " exceeds the near-miss reach "
              << reach << " CUT used; near misses between " << reach << " and " << halo
              << " steps are not haloed (rerun cut with --reach " << halo << ")\n";
}

const std::set<std::string> kCutValued = {"-o", "--lambda", "--cell", "--cover", "--reach"};

int cmd_demo_scene(int argc, char** argv) {
  const Options o =
      parse_options(argc, argv, 2, {"-o", "--cubes", "--curve", "--edges", "--perspective"}, {});
  if (!o.error.empty()) return fail(o.error);
  if (!o.get("--curve").empty() || !o.get("--edges").empty() || !o.get("--perspective").empty())
    return cmd_demo_curve(o);
  if (o.get("-o").empty() || !o.positional.empty())
    return fail(std::string(o.get("-o").empty() ? "demo-scene: missing -o OUTPUT"
                                                : "demo-scene: takes no input file") +
                "\n" + usage_of("demo-scene"));
  int64_t cubes = 28;
  std::string error;
  if (!read_int_option(o, "--cubes", 1, 200, &cubes, &error)) return fail(error);
  const std::string path = o.get("-o");
  if (path.size() > 4 && path.compare(path.size() - 4, 4, ".obj") == 0) {
    // The same array as a solid model in world units (side 100, pitch 125), for the
    // hidden-line modes: six quads per cube, counter-clockwise seen from outside. Written
    // Y-up, as most OBJ files are (read back with the default --up y, the cubes stand on the
    // ground plane as the chip's own cube arrays do): world (x, y, z) is file (x, z, -y).
    error = write_atomically(path, [&](std::ostream& out) {
      out << "# haloplot demo: " << cubes << " x " << cubes
          << " cubes (HALO paper, Figure 4) as a solid model\n";
      for (int64_t i = 0; i < cubes; ++i)
        for (int64_t j = 0; j < cubes; ++j)
          for (int k = 0; k < 8; ++k)
            out << "v " << i * 125 + (k & 1) * 100 << ' ' << ((k >> 2) & 1) * 100 << ' '
                << -(j * 125 + ((k >> 1) & 1) * 100) << '\n';
      static const int kFaces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                       {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
      for (int64_t c = 0; c < cubes * cubes; ++c)
        for (const auto& f : kFaces)
          out << "f " << c * 8 + f[0] + 1 << ' ' << c * 8 + f[1] + 1 << ' ' << c * 8 + f[2] + 1
              << ' ' << c * 8 + f[3] + 1 << '\n';
      return true;
    });
    return error.empty() ? 0 : fail(error);
  }
  CubeArrayParams p;
  p.cubes = int(cubes);
  const std::vector<Edge3> edges = cube_array(p);
  const std::string header = "# haloplot demo: " + std::to_string(cubes) + " x " +
                             std::to_string(cubes) +
                             " cubes, azimuth 30, elevation 40 (HALO paper, Figure 4)\n"
                             "# x1 y1 z1 x2 y2 z2 in steps; z larger = nearer\n";
  error = write_atomically(o.get("-o"), [&](std::ostream& out) {
    write_edges(out, edges, header);
    return true;
  });
  return error.empty() ? 0 : fail(error);
}

// "0.01" -> 10000 millionths, without floating point.
bool parse_millionths(const std::string& s, int64_t* out) {
  const size_t dot = s.find('.');
  int64_t whole = 0, frac = 0;
  const std::string w = s.substr(0, dot);
  if (!parse_int(w.empty() ? "0" : w, 0, 1, &whole)) return false;
  std::string f = dot == std::string::npos ? "" : s.substr(dot + 1);
  if (f.size() > 6) return false;
  f.append(6 - f.size(), '0');
  if (!parse_int(f, 0, 999999, &frac)) return false;
  *out = whole * 1000000 + frac;
  return *out > 0 && *out <= 1000000;
}

int cmd_random_scene(int argc, char** argv) {
  const Options o = parse_options(argc, argv, 2, {"-o", "--edges", "--length", "--seed"}, {});
  if (!o.error.empty()) return fail(o.error);
  for (const char* need : {"-o", "--edges", "--length"})
    if (o.get(need).empty())
      return fail(std::string("random-scene: missing ") + need + "\n" + usage_of("random-scene"));
  if (!o.positional.empty())
    return fail("random-scene: takes no input file\n" + usage_of("random-scene"));
  int64_t n = 0, seed = 1, l = 0;
  std::string error;
  if (!read_int_option(o, "--edges", 1, 100000000, &n, &error) ||
      !read_int_option(o, "--seed", 0, INT64_MAX, &seed, &error))
    return fail(error);
  if (!parse_millionths(o.get("--length"), &l))
    return fail("--length '" + o.get("--length") +
                "' must be a decimal in (0, 1], at most 6 places");
  const std::vector<Edge3> edges = paper_random(uint32_t(n), l, uint64_t(seed));
  const std::string header =
      "# haloplot random scene (HALO paper EDGE distribution): N=" + o.get("--edges") +
      " L=" + o.get("--length") + " seed=" + std::to_string(seed) + "\n";
  error = write_atomically(o.get("-o"), [&](std::ostream& out) {
    write_edges(out, edges, header);
    return true;
  });
  return error.empty() ? 0 : fail(error);
}

int cmd_cut(int argc, char** argv) {
  std::set<std::string> valued = kCutValued;
  const Options o = parse_options(argc, argv, 2, valued, {"--stats"});
  if (!o.error.empty()) return fail(o.error);
  if (!one_input_and_output(o)) return bad_arguments(o, "cut");
  CutParams cp;
  std::string error;
  if (!cut_params(o, &cp, &error)) return fail(error);
  std::vector<Edge3> edges;
  int32_t units = 0;
  if (!load_scene(o, o.positional[0], &edges, &error, &units)) return fail(error);
  HostCut c;
  const Status s = host_cut(std::move(edges), cut_in_units(cp, units), &c);
  if (!ok(s)) return fail_status("CUT", s);
  error = write_atomically(o.get("-o"), [&](std::ostream& out) {
    write_cut(out, c.set, cut_header(c) + substep_header(units));
    return true;
  });
  if (!error.empty()) return fail(error);
  if (o.has("--stats")) print_cut_stats(c);
  return 0;
}

int cmd_draw(int argc, char** argv) {
  std::set<std::string> valued = {"-o", "--halo", "--spans", "--steps-per-mm"},
                        flags = {"--exact-halo", "--stats"};
  valued.insert(std::begin(kPageValued), std::end(kPageValued));
  flags.insert(std::begin(kPageFlags), std::end(kPageFlags));
  const Options o = parse_options(argc, argv, 2, valued, flags);
  if (!o.error.empty()) return fail(o.error);
  if (!one_input_and_output(o)) return bad_arguments(o, "draw");
  if (const std::string bad = svg_output_problem(o.get("-o")); !bad.empty()) return fail(bad);
  DrawParams dp;
  std::string error;
  if (!draw_params(o, &dp, &error)) return fail(error);
  LoadedCut lc;
  const InputError ie = read_cut_file(o.positional[0], &lc);
  if (ie.failed()) return fail(ie.message());
  HostDraw d;
  const Status s = host_draw(lc.set, draw_in_units(dp, lc.substep_bits), &d);
  if (!ok(s)) return fail_status("DRAW", s);
  warn_reach(d, dp.halo, lc.set.reach >> lc.substep_bits);
  spans_to_steps(&d.spans, lc.substep_bits);
  if (const int rc = write_drawing(o, d, false)) return rc;
  if (o.has("--stats")) {
    std::fprintf(stderr, "edges=%u\ncrossings=%u\ncut_ran=0\ncut_ms=0\n", lc.set.n_edges,
                 lc.set.n_crossings);
    print_draw_stats(d);
  }
  return 0;
}

void print_band_stats(const BandStats& b, size_t arena);

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
    return fail("plot: arena of " + std::to_string(arena) + " bytes too small: a band one row " +
                "high needs " + std::to_string(bands.need_bytes) + kFurtherBands);
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
    return bad_arguments(o, "plot");
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

void print_band_stats(const BandStats& b, size_t arena) {
  std::fprintf(stderr,
               "arena=%zu\nbands=%u\nband_splits=%u\nmargin_bands=%u\nband_margin=%d\n"
               "band_peak_bytes=%zu\nband_most_edges=%u\nband_most_pieces=%u\n"
               "band_most_carry=%u\nband_edge_reads=%llu\nband_cut_runs=%llu\nband_edges=%llu\n"
               "band_deferred=%llu\nband_turned=%d\n",
               arena, b.bands, b.splits, b.margin_bands, b.margin, b.peak_bytes, b.most_edges,
               b.most_pieces, b.most_carry, (unsigned long long)b.edge_reads,
               (unsigned long long)b.cut_runs, (unsigned long long)b.band_edges,
               (unsigned long long)b.deferred, b.turned ? 1 : 0);
}

// "12.345" from a count of thousandths.
std::string thousandths(uint64_t v) {
  std::string f = std::to_string(v % 1000);
  return std::to_string(v / 1000) + "." + std::string(3 - f.size(), '0') + f;
}

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

int cmd_sim(int argc, char** argv) {
  const Options o = parse_options(
      argc, argv, 2, {"-o", "--gcode", "--hpgl", "--arena", "--pause-at", "--resume-at"},
      {"--stats", "--binary"});
  if (!o.error.empty()) return fail(o.error);
  if (!one_input_and_output(o)) return bad_arguments(o, "sim");
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
    if (!load_curve_job(jf.scene_path, jf.spec, jf.arena, &curve_scene, &jf.spec.substep_bits,
                        &error))
      return fail(error);
    edges = curve_scene.edges;
  } else if (solid_bands) {
    if (!load_solid_job_scene(jf, &solid, &jf.spec.hidden, &error)) return fail(error);
    jf.spec.substep_bits = solid.substep_bits;
  } else if (!load_job_scene(jf, &edges, &error, &jf.spec.substep_bits, &jf.spec.layers)) {
    return fail(error);
  }
  stage.reset();
  if (isatty(2)) jf.spec.cut.progress = &progress;
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
    return fail("sim: arena of " + std::to_string(jf.arena) + " bytes too small: a band one row " +
                "high needs " + std::to_string(r.bands.need_bytes) + kFurtherBands);
  if (!ok(s)) return fail_status("sim", s);
  warn_if_slow(spec, r);
  if (!error.empty()) return fail(error);
  if (const int rc = write_exports(o, r, spec, jf)) return rc;
  if (o.has("--stats")) {
    print_sim_stats(spec, r, edges.size() + curve_scene.curves.size());
    print_clean_stats(r.job.path, jf.style.steps_per_mm);
    if (curves)  // the curve job's stages (job/job.h job_prepare_curves)
      std::fprintf(stderr, "curve_pieces=%u\ncrossings=%u\ngaps=%llu\nchords=%llu\n",
                   r.job.curve_cross.pieces, r.job.curve_cross.crossings,
                   (unsigned long long)r.job.curve_draw.gaps,
                   (unsigned long long)r.job.curve_draw.chords);
    if (!pause_at.empty()) std::fprintf(stderr, "holds=%llu\n", (unsigned long long)r.holds);
    if (jf.arena > 0) print_band_stats(r.bands, jf.arena);
  }
  return 0;
}

int cmd_replay(int argc, char** argv) {
  const Options o = parse_options(argc, argv, 2, {"-o"}, {"--stats"});
  if (!o.error.empty()) return fail(o.error);
  if (!one_input_and_output(o)) return bad_arguments(o, "replay");
  if (const std::string bad = svg_output_problem(o.get("-o")); !bad.empty()) return fail(bad);
  std::ifstream in(o.positional[0]);
  if (const InputError e = open_problem(o.positional[0], in); e.failed()) return fail(e.message());
  Trace t;
  const InputError ie = read_trace(in, o.positional[0], &t);
  if (ie.failed()) return fail(ie.message());
  const Replay rep = replay(t);
  const auto& strokes = rep.strokes;
  std::vector<Span> spans;
  uint64_t down_length = 0;
  for (const auto& stroke : strokes) {
    const auto pts = simplify(stroke, rep.scale, 1);
    for (size_t i = 1; i < pts.size(); ++i)
      down_length += length_floor(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
    if (pts.size() == 1) spans.push_back(Span{0, 0, 0, pts[0].x, pts[0].y, pts[0].x, pts[0].y});
    for (size_t i = 1; i < pts.size(); ++i)
      spans.push_back(Span{0, 0, 0, pts[i - 1].x, pts[i - 1].y, pts[i].x, pts[i].y});
  }
  const std::string error = write_atomically(o.get("-o"), [&](std::ostream& out) {
    write_svg(out, spans, SvgStyle{});
    return true;
  });
  if (!error.empty()) return fail(error);
  if (o.has("--stats"))
    std::fprintf(
        stderr, "strokes=%zu\npen_down_length=%llu\npen_up_length=%llu\nplot_s=%s\npen_lifts=%u\n",
        strokes.size(), (unsigned long long)down_length, (unsigned long long)rep.pen_up_length,
        thousandths(t.end_tick * 1000 / t.machine.tick_hz).c_str(), rep.pen_lifts);
  return 0;
}

}  // namespace

namespace haloplot::host {
int cmd_send(int argc, char** argv);    // cli/cmd_send.cpp
int cmd_view2d(int argc, char** argv);  // cli/cmd_view2d.cpp
}  // namespace haloplot::host

namespace {

int run_command(int argc, char** argv) {
  const std::string cmd = argv[1];
  if (cmd == "--help" || cmd == "-h" || cmd == "help") {
    std::cout << kUsage;
    return 0;
  }
  if (cmd == "--version" || cmd == "version") {
    std::cout << "haloplot " HALOPLOT_VERSION "\n";
    return 0;
  }
  for (int i = 2; i < argc; ++i)
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
      std::cout << usage_of(cmd);
      return 0;
    }
  // Every output the command will write, checked before any work: a missing folder is said
  // at once, not after a long plot. These names are outputs in every command that has them.
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    for (const char* name :
         {"-o", "--gcode", "--hpgl", "--spans", "--cut", "--trace", "--dump-edges"}) {
      const std::string n = name;
      std::string path;
      if (arg == n && i + 1 < argc)
        path = argv[i + 1];
      else if (arg.compare(0, n.size() + 1, n + "=") == 0)
        path = arg.substr(n.size() + 1);
      const std::string problem = path.empty() ? "" : output_problem(path);
      if (!problem.empty()) return fail(problem);
    }
  }
  if (cmd == "demo-scene") return cmd_demo_scene(argc, argv);
  if (cmd == "random-scene") return cmd_random_scene(argc, argv);
  if (cmd == "cut") return cmd_cut(argc, argv);
  if (cmd == "draw") return cmd_draw(argc, argv);
  if (cmd == "plot") return cmd_plot(argc, argv);
  if (cmd == "sim") return cmd_sim(argc, argv);
  if (cmd == "replay") return cmd_replay(argc, argv);
  if (cmd == "send") return haloplot::host::cmd_send(argc, argv);
  if (cmd == "view2d") return haloplot::host::cmd_view2d(argc, argv);
  const std::string near = nearest(cmd, {"demo-scene", "random-scene", "cut", "draw", "plot", "sim",
                                         "replay", "send", "view2d"});
  return fail("unknown command '" + cmd + "'" +
              (near.empty() ? "" : " (did you mean " + near + "?)") + "\n" + kUsage);
}

}  // namespace

// The tool is one command that builds and drops many large arrays (a big model's vertices,
// faces, sides, pieces, path): glibc would give each one back to the system when it is
// freed and take fresh pages for the next, a page fault per 4 KB every time. Keeping freed
// memory for reuse instead (as much as glibc allows in the heap: 32 MB per block) cut a
// 200,000-triangle plot's time by a fifth; the largest buffers come from HostMemory.
static void keep_freed_memory() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_TOP_PAD, 16 << 20);
#endif
}

int main(int argc, char** argv) {
  keep_freed_memory();
  if (argc < 2) return fail(kUsage);
  // Every output of the command is staged here and put in place only when the command
  // succeeds, all together (io/atomic_file.h); a failed command leaves none behind.
  haloplot::host::OutputSet outputs;
  const int rc = run_command(argc, argv);
  if (rc != 0) return rc;
  const std::string error = outputs.commit();
  return error.empty() ? 0 : fail(error);
}
