// Hidden lines of solid models, measured: Appel/Heger QI propagation against the topology-free
// fallback (Franklin's midpoint tests) with and without Kira's shortcuts, on the test scenes
// at growing sizes. Both methods give the same picture (tests/unit/test_solid_qi.cpp checks
// it); this says what each costs, and counts the rules and the V.C. savings. Writes the
// markdown table body docs/hidden-lines.body.md; times are medians of 5 runs of the whole
// core pipeline (topology, classes, CUT, incidences, then the method), no I/O.
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "bench/perf_common.h"
#include "support/solid_scenes.h"

using namespace haloplot;
using namespace haloplot::host;
using namespace solid_scenes;

namespace {

struct Row {
  std::string name;
  size_t edges = 0, triangles = 0;
  double qi_ms = 0, fb_ms = 0, kira_ms = 0;
  SolidRun qi, fb, kira;
};

double time_run(const SolidScene& s, HiddenMethod m, bool kira_on, SolidRun* out) {
  FallbackParams k;
  k.use_classes = k.use_vc = kira_on;
  std::vector<double> t;
  for (int i = 0; i < 5; ++i) {
    const double t0 = bench::now_ms();
    if (run_hidden_lines(s, m, k, out, m == HiddenMethod::kQi) != Status::kOk) return -1;
    t.push_back(bench::now_ms() - t0);
  }
  return bench::median(t);
}

Row measure(const std::string& name, const Mesh& m, const View& v) {
  Row r;
  r.name = name;
  SolidScene s;
  project(m, v, &s);
  r.edges = s.edge_pairs.size() / 2;
  r.triangles = s.triangles.size();
  r.qi_ms = time_run(s, HiddenMethod::kQi, false, &r.qi);
  r.fb_ms = time_run(s, HiddenMethod::kFallback, false, &r.fb);
  r.kira_ms = time_run(s, HiddenMethod::kFallback, true, &r.kira);
  std::fprintf(stderr, "%-28s %7zu edges  QI %8.2f ms  fallback %8.2f ms  with Kira %8.2f ms\n",
               name.c_str(), r.edges, r.qi_ms, r.fb_ms, r.kira_ms);
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  std::vector<Row> rows;
  for (int n : {7, 14, 28, 56}) {
    Mesh m;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) box(&m, i * 125, j * 125, 0, i * 125 + 100, j * 125 + 100, 100);
    rows.push_back(
        measure(std::to_string(n) + " x " + std::to_string(n) + " cubes", m, view(30000, 40000)));
  }
  for (int res : {16, 32, 64}) {
    Mesh m;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        sphere(&m, i * 50000, j * 50000, (i + j) * 8000, 20000, res, 2 * res);
    rows.push_back(measure("9 spheres " + std::to_string(res) + "x" + std::to_string(2 * res), m,
                           view(30000, 25000)));
  }
  for (int res : {12, 24, 48}) {
    Mesh m;
    torus(&m, 0, 0, 0, 20000, 7000, 2 * res, res);
    torus(&m, 20000, 0, 0, 20000, 7000, 2 * res, res, true);
    rows.push_back(measure("2 linked tori " + std::to_string(2 * res) + "x" + std::to_string(res),
                           m, view(30000, 25000)));
  }
  {
    Mesh m;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        frame(&m, i * 14000, j * 14000, 10000, 4000, (i * j % 3) * 2000, 3000 + (i * j % 3) * 2000);
    rows.push_back(measure("6 x 6 frames (holes)", m, view(30000, 35000)));
  }
  std::ofstream out(dir + "/hidden-lines.body.md");
  out << "\n| scene | edges | triangles | QI ms | fallback ms | fallback + Kira ms | fallback / QI "
         "|\n"
         "|---|---:|---:|---:|---:|---:|---:|\n";
  char buf[512];
  for (const Row& r : rows) {
    std::snprintf(buf, sizeof buf, "| %s | %zu | %zu | %.2f | %.2f | %.2f | %.2f |\n",
                  r.name.c_str(), r.edges, r.triangles, r.qi_ms, r.fb_ms, r.kira_ms,
                  r.fb_ms / r.qi_ms);
    out << buf;
  }
  out << "\nRules fired in the QI propagation (each counts an event whose contribution was not "
         "zero):\n\n| scene | components (ray casts) | crossings | wedge | delta | quarter | half "
         "| "
         "occluded pieces | end-on edges | conflicts "
         "|\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Row& r : rows) {
    const QiStats& q = r.qi.qi;
    std::snprintf(buf, sizeof buf,
                  "| %s | %u (%u) | %llu | %llu | %llu | %llu | %llu | %llu | %llu | %u |\n",
                  r.name.c_str(), q.components, q.ray_casts, (unsigned long long)q.crossings,
                  (unsigned long long)q.wedge, (unsigned long long)q.delta,
                  (unsigned long long)q.quarter, (unsigned long long)q.half,
                  (unsigned long long)q.occluded, (unsigned long long)q.degenerate, q.conflicts);
    out << buf;
  }
  out << "\nKira's savings in the fallback (midpoint tests made, pieces decided by the V.C. table "
         "and by class), and his outlines (contour unit segments, circuits, condition tests):\n\n"
         "| scene | pieces | tests without Kira | tests with | V.C. saved | H1/H2 pieces saved | "
         "contour segments | circuits | outlines | condition tests | asked one by one |\n"
         "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Row& r : rows) {
    const OutlineStats& o = r.qi.outline_stats;
    std::snprintf(
        buf, sizeof buf, "| %s | %llu | %llu | %llu | %llu | %llu | %u | %u | %u | %u | %u |\n",
        r.name.c_str(), (unsigned long long)r.fb.fallback.pieces,
        (unsigned long long)r.fb.fallback.tests, (unsigned long long)r.kira.fallback.tests,
        (unsigned long long)r.kira.fallback.vc_saved,
        (unsigned long long)r.kira.fallback.class_saved, o.unit_segments, o.circuits, o.outlines,
        o.condition_tests, o.one_by_one);
    out << buf;
  }
  out << "\nMemory per stage (bytes, the core's own queries) for the largest cube array: ";
  const SolidRun& big = rows[3].qi;
  std::snprintf(buf, sizeof buf,
                "topology %zu, incidences %zu, CUT scratch + CUTSET %zu, QI %zu, outlines %zu "
                "(fallback instead of QI: %zu).\n",
                big.bytes_topology, big.bytes_incidence, big.bytes_cut, big.bytes_qi,
                big.bytes_outline, rows[3].fb.bytes_fallback);
  out << buf;
  return 0;
}
