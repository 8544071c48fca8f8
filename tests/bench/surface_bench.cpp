// Franklin 1980's claims, measured on the core's implementation
// (core/include/haloplot/surface/franklin.h):
//   1. linear time: random squares and tessellated spheres, time per face flat from about
//      10^3 to 10^5 faces at a fixed depth complexity;
//   2. depth complexity does not matter: N fixed, D from 0.1 to 30, time flat or falling, and
//      how many faces and (face, cell) pairs the blocking faces removed;
//   3. perspective (far squares smaller) is faster than the same scene at one size.
// Writes docs/reports/hidden-surface.body.md and docs/reports/hidden-surface.svg (time per face
// against N, with the paper's Tables 1 and 2 normalised beside ours). Times: the core run alone,
// median of 3.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "bench/chart.h"
#include "bench/perf_common.h"
#include "pipeline/surface_pipeline.h"
#include "support/solid_scenes.h"

using namespace haloplot;
using namespace haloplot::host;

namespace {

constexpr int32_t kScreen = 1 << 19;

// n fronto-parallel squares (two triangles, four edges) of side `side(z)` at distinct depths,
// centres uniform on the screen, turned by a random angle.
template <typename Side>
SolidScene squares(uint32_t n, uint32_t seed, Side side) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  SolidScene s;
  for (uint32_t i = 0; i < n; ++i) {
    const int32_t z = int32_t((uint64_t(i) * 1000003u) % uint64_t(kCoordMax));  // distinct
    const double h = side(double(z) / kCoordMax) / 2, a = u(rng) * 6.283185307179586;
    const double r = h * 1.4143;  // corners stay on the screen whatever the turn
    const double cx = r + u(rng) * (kScreen - 2 * r), cy = r + u(rng) * (kScreen - 2 * r);
    const uint32_t base = uint32_t(s.vertices.size());
    for (int k = 0; k < 4; ++k) {
      const double ang = a + k * 1.5707963267948966;
      s.vertices.push_back(Point3{int32_t(std::lround(cx + h * std::sqrt(2.0) * std::cos(ang))),
                                  int32_t(std::lround(cy + h * std::sqrt(2.0) * std::sin(ang))),
                                  z});
    }
    for (uint32_t k = 0; k < 4; ++k)
      s.edge_pairs.insert(s.edge_pairs.end(), {base + k, base + (k + 1) % 4});
    s.triangles.push_back(Triangle{{base, base + 1, base + 2}, i});
    s.triangles.push_back(Triangle{{base, base + 2, base + 3}, i});
  }
  return s;
}

// k x k x d spheres (6 x 12 quads each) on a jittered lattice that keeps them apart, seen
// straight on: depth complexity grows with the layers d.
SolidScene spheres(int k, int d, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int32_t> jit(-2000, 2000);
  solid_scenes::Mesh m;
  const int32_t pitch = kScreen / k, r = pitch * 4 / 10;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      for (int l = 0; l < d; ++l)
        solid_scenes::sphere(&m, pitch / 2 + i * pitch + jit(rng) % (pitch / 20 + 1),
                             pitch / 2 + j * pitch + jit(rng) % (pitch / 20 + 1),
                             pitch / 2 + l * pitch, r, 6, 12);
  SolidScene s;
  // Plot coordinates directly: depth is z scaled into range.
  const int64_t zmax = int64_t(d) * pitch + pitch;
  for (Point3 p : m.v)
    s.vertices.push_back(Point3{p.x, p.y, int32_t(int64_t(p.z) * kCoordMax / zmax)});
  s.edge_pairs = solid_scenes::polygon_edges(m);
  s.triangles = triangulate(m.v, m.faces, nullptr);
  return s;
}

struct Result {
  double ms = 0;
  FranklinStats st;
  size_t faces = 0;
};

Result measure(const SolidScene& s) {
  Result r;
  r.faces = s.triangles.size();
  std::vector<double> t;
  for (int i = 0; i < 3; ++i) {
    FranklinRun fr;
    const Status st = run_franklin(s, FranklinParams{}, &fr);
    if (st != Status::kOk) {
      std::fprintf(stderr, "franklin: %s\n", status_name(st));
      std::abort();
    }
    t.push_back(fr.ms);
    r.st = fr.stats;
  }
  r.ms = bench::median(t);
  return r;
}

std::string row(const std::string& name, const Result& r) {
  char b[512];
  std::snprintf(b, sizeof b, "| %s | %zu | %u | %.1f | %.3f | %llu | %u | %llu | %u |\n",
                name.c_str(), r.faces, r.st.b, r.ms, r.ms * 1000.0 / double(r.faces),
                (unsigned long long)r.st.face_cells_culled, r.st.faces_deleted,
                (unsigned long long)r.st.edge_cells_culled, r.st.edges_deleted);
  return b;
}

const char* kHeader =
    "| scene | faces (triangles) | B | ms | us per face | (face, cell) culled | faces deleted | "
    "(edge, cell) culled | edges deleted |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  std::ofstream out(dir + "/hidden-surface.body.md");
  bench::Series sq{"random squares, D = 4 (ours)", "#1f77b4", {}},
      sp{"spheres, 3 layers (ours)", "#2ca02c", {}},
      pt1{"paper Table 1 (spheres, D = 10)", "#ff7f0e", {}},
      pt2{"paper Table 2 (squares)", "#d62728", {}};

  out << "\n### 1. Linear time\n\nRandom squares at depth complexity D = 4 (side = sqrt(D / N) of "
         "the screen):\n\n"
      << kHeader;
  double first_sq = 0;
  for (uint32_t n : {1000u, 3000u, 10000u, 30000u, 100000u}) {
    const double side = std::sqrt(4.0 / n) * kScreen;
    const Result r = measure(squares(n, n, [&](double) { return side; }));
    out << row(std::to_string(n) + " squares", r);
    const double per = r.ms * 1000.0 / double(r.faces);
    if (first_sq == 0) first_sq = per;
    sq.points.push_back({double(n), per / first_sq});
    std::fprintf(stderr, "squares %u: %.1f ms\n", n, r.ms);
  }
  out << "\nTessellated spheres (72 quads each, 144 triangles), k x k x 3 on a lattice:\n\n"
      << kHeader;
  double first_sp = 0;
  for (int k : {4, 8, 14, 26}) {
    const Result r = measure(spheres(k, 3, uint32_t(k)));
    out << row(std::to_string(k * k * 3) + " spheres", r);
    const double per = r.ms * 1000.0 / double(r.faces);
    if (first_sp == 0) first_sp = per;
    sp.points.push_back({double(r.faces), per / first_sp});
    std::fprintf(stderr, "spheres %d: %.1f ms\n", k * k * 3, r.ms);
  }
  // The paper's tables, as time per object normalised to their first row.
  const double t1n[] = {30, 100, 300, 1000, 3000, 10000}, t1t[] = {4.1, 5.6, 10.3, 31.1, 97.5, 383};
  for (int i = 0; i < 6; ++i) pt1.points.push_back({t1n[i], (t1t[i] / t1n[i]) / (t1t[0] / t1n[0])});
  pt2.points.push_back({1000, 1.0});
  pt2.points.push_back({3000, (1792.0 / 3000) / (527.0 / 1000)});

  out << "\n### 2. Depth complexity\n\n10,000 random squares, D from 0.1 to 30:\n\n" << kHeader;
  for (double d : {0.1, 0.3, 1.0, 3.0, 10.0, 30.0}) {
    const double side = std::sqrt(d / 10000) * kScreen;
    const Result r = measure(squares(10000, 77, [&](double) { return side; }));
    char name[64];
    std::snprintf(name, sizeof name, "D = %.1f", d);
    out << row(name, r);
    std::fprintf(stderr, "D %.1f: %.1f ms\n", d, r.ms);
  }

  out << "\nThe grid's fineness c (the paper's tuning constant) at D = 1, 10 and 30, 10,000 "
         "squares:"
         "\n\n| c | D = 1 ms | D = 10 ms | D = 30 ms | faces deleted at D = 30 |\n"
         "|---:|---:|---:|---:|---:|\n";
  for (uint32_t c : {256u, 512u, 1024u, 2048u}) {
    double ms[3];
    uint32_t deleted = 0;
    int i = 0;
    for (double d : {1.0, 10.0, 30.0}) {
      const double side = std::sqrt(d / 10000) * kScreen;
      const SolidScene sc = squares(10000, 77, [&](double) { return side; });
      std::vector<double> t;
      FranklinRun fr;
      for (int r = 0; r < 3; ++r) {
        FranklinParams fp;
        fp.c_q8 = c;
        if (run_franklin(sc, fp, &fr) != Status::kOk) std::abort();
        t.push_back(fr.ms);
      }
      ms[i++] = bench::median(t);
      deleted = fr.stats.faces_deleted;
    }
    char b[200];
    std::snprintf(b, sizeof b, "| %.0f | %.1f | %.1f | %.1f | %u |\n", c / 256.0, ms[0], ms[1],
                  ms[2], deleted);
    out << b;
  }

  out << "\n### 3. Perspective\n\n10,000 squares at D = 10 in total area: all one size, against "
         "far squares smaller (side proportional to 0.25 + depth, scaled to the same total area):"
         "\n\n"
      << kHeader;
  {
    const double side = std::sqrt(10.0 / 10000) * kScreen;
    const Result flat = measure(squares(10000, 5, [&](double) { return side; }));
    // Mean of (0.25 + z)^2 over z uniform in [0, 1): 0.25^2 + 0.25 + 1/3.
    const double k = side / std::sqrt(0.0625 + 0.25 + 1.0 / 3.0);
    const Result persp = measure(squares(10000, 5, [&](double z) { return k * (0.25 + z); }));
    out << row("one size", flat) << row("perspective (near larger)", persp);
    char b[160];
    std::snprintf(b, sizeof b, "\nPerspective / one size: **%.2f** of the time.\n",
                  persp.ms / flat.ms);
    out << b;
  }
  out << "\n### 4. Regions and hatching (steps 10-11)\n\nRandom squares at D = 4, each hatched "
         "with about 8 lines: the hidden lines alone (steps 2-9) against the whole hidden-surface "
         "run (every piece kept, the planar graph, its cycles, the face of each, the hatching). "
         "Medians of 3.\n\n| squares | hidden lines ms | hidden surface ms | ratio | us per face "
         "| visible segments | cycles | bounded | holes | face tests per cycle | hatch strokes |\n"
         "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (uint32_t n : {1000u, 10000u, 100000u}) {
    const double side = std::sqrt(4.0 / n) * kScreen;
    const SolidScene sc = squares(n, n + 1, [&](double) { return side; });
    const Result lines = measure(sc);
    std::vector<double> t;
    HatchRun hr;
    HatchParams hp;
    hp.spacing = std::max(1, int32_t(side / 8));
    hp.mdeg_per_depth = 90000;
    for (int r = 0; r < 3; ++r) {
      if (run_hatch(sc, hp, &hr) != Status::kOk) std::abort();
      t.push_back(hr.ms);
    }
    const double ms = bench::median(t);
    const RegionStats& rs = hr.surface.regions;
    char b[400];
    std::snprintf(
        b, sizeof b, "| %u | %.1f | %.1f | %.2f | %.3f | %u | %u | %u | %u | %.2f | %llu |\n", n,
        lines.ms, ms, ms / lines.ms, ms * 1000.0 / double(lines.faces), rs.segments, rs.cycles,
        rs.bounded, rs.holes, rs.cycles ? double(rs.face_tests) / rs.cycles : 0.0,
        (unsigned long long)hr.surface.hatch.strokes);
    out << b;
    std::fprintf(stderr, "regions %u: %.1f ms (lines %.1f)\n", n, ms, lines.ms);
  }

  bench::write_chart(dir + "/hidden-surface.svg",
                     "Franklin 1980: time per face, normalised to the smallest scene",
                     "faces (squares; triangles for our spheres; objects for the paper)",
                     "time per face / first row", {sq, sp, pt1, pt2}, true, 0);
  return 0;
}
