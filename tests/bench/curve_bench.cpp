// The Bézier trefoil against its flattening into 10,000 straight edges: memory and time of
// finding the crossings (the curve stage against CUT) and of drawing them haloed (the curve
// DRAW against DRAW), as ratios in one run. Prints a Markdown paragraph for docs/curves.md
// (tools/bench_curves.sh).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
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

}  // namespace

int main() {
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
