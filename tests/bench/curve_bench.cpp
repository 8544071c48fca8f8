// The Bézier trefoil against its flattening into 10,000 straight edges: memory and time of
// finding the crossings (the curve stage against CUT) and of drawing them haloed (the curve
// DRAW against DRAW), as ratios in one run. Prints a Markdown paragraph for docs/curves.md
// (tools/bench_curves.sh).
//
// `curve_bench --accuracy`: error against time for the curve DRAW's chord tolerance (the
// flatness each chord keeps from its piece of curve), on the demo knots: the section of
// docs/reports/accuracy.md that tools/bench_curve_accuracy.sh prints.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "demo/curve_scenes.h"
#include "pipeline/curve_pipeline.h"
#include "pipeline/host_pipeline.h"

using namespace haloplot;
using namespace haloplot::host;

namespace {

// The flattening: n points at equal parameter steps per edge, in long double, rounded.
std::vector<Edge3> flatten(const CurveScene& s, int per_edge) {
  std::vector<Point3> pts;
  for (const BezierEdge3& e : s.curves)
    for (int i = 0; i < per_edge; ++i) {
      const long double t = (long double)i / per_edge, u = 1 - t;
      const long double w[4] = {u * u * u, 3 * u * u * t, 3 * u * t * t, t * t * t};
      long double x = 0, y = 0, z = 0;
      for (int k = 0; k < 4; ++k) x += w[k] * e.p[k].x, y += w[k] * e.p[k].y, z += w[k] * e.p[k].z;
      pts.push_back(
          Point3{int32_t(std::llround(x)), int32_t(std::llround(y)), int32_t(std::llround(z))});
    }
  std::vector<Edge3> edges;
  for (size_t i = 0; i < pts.size(); ++i) edges.push_back(Edge3{pts[i], pts[(i + 1) % pts.size()]});
  return edges;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// ---- --accuracy: the chord tolerance ----

Status keep_chord(void* c, const Span& s) {
  static_cast<std::vector<Span>*>(c)->push_back(s);
  return Status::kOk;
}

struct ChordError {
  double max_ink = 0, mean_ink = 0;  // the plotted chords (ends rounded to steps)
  double max_chord = 0;              // the chords between the curve's own points
};

double to_segment(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
  double f = len2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0;
  f = std::min(1.0, std::max(0.0, f));
  return std::hypot(px - (ax + f * dx), py - (ay + f * dy));
}

void eval(const BezierEdge3& e, double t, double* x, double* y) {
  const double u = 1 - t, w[4] = {u * u * u, 3 * u * u * t, 3 * u * t * t, t * t * t};
  *x = *y = 0;
  for (int k = 0; k < 4; ++k) *x += w[k] * e.p[k].x, *y += w[k] * e.p[k].y;
}

// Every chord against its piece of curve (64 points along it, in double): the distance of the
// curve from the chord as plotted and from the chord between its exact end points, in steps.
ChordError chord_error(const CurveScene& s, const std::vector<Span>& chords) {
  ChordError e;
  double sum = 0;
  size_t n = 0;
  for (const Span& c : chords) {
    const BezierEdge3& b = s.curves[c.edge];
    const double t0 = double(c.t0) / 4294967296.0, t1 = double(c.t1) / 4294967296.0;
    double ax, ay, bx, by;
    eval(b, t0, &ax, &ay);
    eval(b, t1, &bx, &by);
    for (int i = 0; i <= 64; ++i) {
      double x, y;
      eval(b, t0 + (t1 - t0) * i / 64, &x, &y);
      const double ink = to_segment(x, y, c.x0, c.y0, c.x1, c.y1);
      e.max_ink = std::max(e.max_ink, ink);
      e.max_chord = std::max(e.max_chord, to_segment(x, y, ax, ay, bx, by));
      sum += ink;
      ++n;
    }
  }
  e.mean_ink = n ? sum / double(n) : 0;
  return e;
}

struct KnotScene {
  const char* name;
  CurveScene s;
  std::vector<CurveHit> hits;
};

// The demo knots (demo-scene --curve: 180 mm at 80 steps per mm) with their crossings.
std::vector<KnotScene> knots() {
  CurveView demo;
  demo.size = 15200;
  demo.margin = 400;
  std::vector<KnotScene> out = {
      {"trefoil (demo, 24 edges)", trefoil_knot(24, demo), {}},
      {"(2,5) torus knot (demo, 42 edges)", torus_knot(2, 5, 42, demo), {}}};
  for (KnotScene& k : out) {
    CurveCrossParams cp;
    cp.segment_pairs = true;
    CurveCrossPlan plan;
    const uint32_t nc = uint32_t(k.s.curves.size());
    if (!ok(plan_curve_cross(k.s.curves.data(), nc, nullptr, 0, cp, &plan))) return {};
    std::vector<uint64_t> scratch(plan.scratch_bytes / 8 + 1);
    k.hits.resize(4096);
    uint32_t n = 0;
    CurveCrossStats cs;
    if (!ok(run_curve_cross(plan, k.s.curves.data(), nullptr, scratch.data(), scratch.size() * 8,
                            k.hits.data(), uint32_t(k.hits.size()), &n, &cs)))
      return {};
    k.hits.resize(n);
  }
  return out;
}

constexpr int32_t kKnotHalo = 80;

// One curve DRAW of k at chord tolerance tol (1/256 units): its chords, or false.
bool draw_knot(const KnotScene& k, uint32_t tol, std::vector<Span>* chords) {
  const uint32_t nc = uint32_t(k.s.curves.size()), n = uint32_t(k.hits.size());
  CurveDrawParams p;
  p.halo = kKnotHalo;
  p.chord_tol_q8 = tol;
  CurveDrawPlan dp;
  if (!ok(plan_curve_draw(k.s.curves.data(), nc, nullptr, 0, k.hits.data(), n, p, &dp)))
    return false;
  std::vector<uint64_t> ds(dp.scratch_bytes / 8 + 1);
  chords->clear();
  return ok(run_curve_draw(dp, k.s.curves.data(), nullptr, k.hits.data(), n, ds.data(),
                           ds.size() * 8, SpanSink{&keep_chord, chords}, nullptr, nullptr));
}

const uint32_t kTols[] = {16, 32, 64, 128, 256, 512, 1024, 4096};  // 1/256 units; 64 = default

// `--accuracy`: per knot and tolerance, the chords, the wall time (the tolerances take turns,
// 11 rounds, so a slow spell of the machine falls on all alike; each time the mean of 50 DRAWs,
// the table's their median), its ratio to the default's, and the errors. `--instructions`
// columns come from tools/bench_curve_accuracy.sh (callgrind on `--draw-once K TOL`).
int accuracy() {
  const std::vector<KnotScene> ks = knots();
  if (ks.empty()) return 1;
  std::printf(
      "| scene | chord tolerance, steps | chords | DRAW ms | ratio | max error | mean "
      "error | max error before rounding |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
  const size_t m = sizeof(kTols) / sizeof(kTols[0]);
  for (const KnotScene& k : ks) {
    std::vector<std::vector<double>> ms(m);
    std::vector<std::vector<Span>> chords(m);
    for (int round = 0; round < 11; ++round)
      for (size_t t = 0; t < m; ++t) {
        const auto start = std::chrono::steady_clock::now();
        for (int rep = 0; rep < 50; ++rep)
          if (!draw_knot(k, kTols[t], &chords[t])) return 1;
        const auto end = std::chrono::steady_clock::now();
        ms[t].push_back(std::chrono::duration<double, std::milli>(end - start).count() / 50);
      }
    const double base = median(ms[2]);
    for (size_t t = 0; t < m; ++t) {
      const ChordError e = chord_error(k.s, chords[t]);
      std::printf("| %s | %g%s | %zu | %.3f | %.2f× | %.3f | %.3f | %.3f |\n", k.name,
                  kTols[t] / 256.0, kTols[t] == 64 ? " **(default)**" : "", chords[t].size(),
                  median(ms[t]), median(ms[t]) / base, e.max_ink, e.mean_ink, e.max_chord);
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--accuracy") == 0) return accuracy();
  if (argc > 3 && std::strcmp(argv[1], "--draw-once") == 0) {  // for callgrind
    const std::vector<KnotScene> ks = knots();
    const size_t k = size_t(std::atoi(argv[2]));
    std::vector<Span> chords;
    return k < ks.size() && draw_knot(ks[k], uint32_t(std::atoi(argv[3])), &chords) ? 0 : 1;
  }
  const CurveScene knot = trefoil_knot(24, CurveView());
  const std::vector<Edge3> flat = flatten(knot, 10000 / 24 + 1);
  const int32_t W = 64;
  std::vector<double> cross_ms, cdraw_ms, cut_ms, draw_ms;
  size_t curve_bytes = 0, straight_bytes = 0, cross_scratch = 0, cut_scratch = 0, cutset = 0;
  uint64_t curve_gaps = 0, flat_gaps = 0, chords = 0, spans = 0;
  for (int run = 0; run < 5; ++run) {
    HostCurveDraw d;
    CurveDrawParams p;
    p.halo = W;
    if (!ok(host_curve_draw(knot.curves, knot.segments, CurveCrossParams{}, p, &d))) return 1;
    cross_ms.push_back(d.cross_ms);
    cdraw_ms.push_back(d.draw_ms);
    cross_scratch = d.cross_scratch_bytes;
    curve_bytes = knot.curves.size() * sizeof(BezierEdge3) + d.cross_scratch_bytes +
                  d.hits.size() * sizeof(CurveHit) + d.draw_scratch_bytes;
    curve_gaps = d.stats.gaps;
    chords = d.chords.size();
    HostCut c;
    if (!ok(host_cut(flat, CutParams(), &c))) return 1;
    HostDraw hd;
    if (!ok(host_draw(c.set, DrawParams{W, HaloMode::kPaper}, &hd))) return 1;
    cut_ms.push_back(c.cut_ms);
    draw_ms.push_back(hd.draw_ms);
    cut_scratch = c.scratch_bytes;
    cutset = cutset_bytes(c.set.n_edges, c.set.n_crossings);
    // What the run needs (the host's first CUTSET guess holds more records than it uses).
    straight_bytes = flat.size() * sizeof(Edge3) + cut_scratch + cutset + hd.scratch_bytes;
    flat_gaps = hd.stats.gaps;
    spans = hd.spans.size();
  }
  std::printf(
      "The trefoil as 24 Bézier edges against its flattening into %zu straight edges (halo %d "
      "units, median of 5 runs in one process): finding the crossings takes %.2f ms and %.0f KB "
      "(the curves %zu bytes, the pieces' scratch %zu bytes at the default 1/4-unit pieces) "
      "against CUT's %.2f ms and %.0f KB (the edges %zu KB, CUT's scratch %zu KB, the CUTSET "
      "%zu KB): %.2fx the time, %.2fx the memory. Drawing: %.2f ms for %llu chords against "
      "DRAW's %.2f ms for %llu spans; both cut %llu and %llu gaps.\n",
      flat.size(), W, median(cross_ms), double(curve_bytes) / 1024,
      knot.curves.size() * sizeof(BezierEdge3), cross_scratch, median(cut_ms),
      double(straight_bytes) / 1024, flat.size() * sizeof(Edge3) / 1024, cut_scratch / 1024,
      cutset / 1024, median(cross_ms) / median(cut_ms),
      double(curve_bytes) / double(straight_bytes), median(cdraw_ms), (unsigned long long)chords,
      median(draw_ms), (unsigned long long)spans, (unsigned long long)curve_gaps,
      (unsigned long long)flat_gaps);
  return 0;
}
