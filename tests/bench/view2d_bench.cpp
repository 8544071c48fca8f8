// docs/reports/view2d.md: Freeman-Loutrel (core/view2d) against the brute-force ray caster
// (tests/reference/view2d_reference.h) for n = 10 to 10^5 vertices: median times, the growth
// from one n to the next, and the walk's counters. Usage: view2d_bench OUT_DIR
#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <vector>

#include "haloplot/view2d/polygon_view.h"
#include "perf_common.h"
#include "reference/view2d_reference.h"

using namespace haloplot;
using bench::fmt;
using bench::median;
using bench::now_ms;

namespace {

// A star-shaped island: n vertices at sorted random angles. `spiky`: radii anywhere in
// [0.6, 1] x R; otherwise a coastline, radii within 1 % of a few slow waves. Vertices whose
// rounding would break the angular order are dropped, so the polygon stays simple.
std::vector<Point2> star(int n, uint64_t seed, bool spiky) {
  std::mt19937_64 rng(seed);
  std::vector<double> ang(static_cast<size_t>(n));
  for (double& a : ang) a = std::uniform_real_distribution<double>(0, 2 * M_PI)(rng);
  std::sort(ang.begin(), ang.end());
  std::vector<Point2> p;
  for (double a : ang) {
    const double wave = 0.8 + 0.1 * std::sin(3 * a) + 0.05 * std::sin(11 * a);
    const double r =
        600000 * (spiky ? std::uniform_real_distribution<double>(0.6, 1.0)(rng)
                        : wave * std::uniform_real_distribution<double>(0.99, 1.01)(rng));
    const Point2 q{int32_t(std::lround(r * std::cos(a))), int32_t(std::lround(r * std::sin(a)))};
    if (!p.empty() && int64_t{p.back().x} * q.y - int64_t{p.back().y} * q.x <= 0) continue;
    p.push_back(q);
  }
  while (p.size() > 2 && int64_t{p.back().x} * p[0].y - int64_t{p.back().y} * p[0].x <= 0)
    p.pop_back();
  return p;
}

struct Result {
  Status status = Status::kOk;
  double ms = 0;
  View2dStats st;
  size_t pieces = 0;
};

Result run_walk(const std::vector<Point2>& p, Point2 e, int runs) {
  Result r;
  std::vector<uint8_t> scratch(view2d_scratch_bytes(uint32_t(p.size())));
  std::vector<double> t;
  for (int k = 0; k < runs; ++k) {
    size_t pieces = 0;
    const double t0 = now_ms();
    r.status = view2d(p.data(), uint32_t(p.size()), e, scratch.data(), scratch.size(),
                      VisibleSink{[](void* c, const VisibleSpan&) {
                                    ++*static_cast<size_t*>(c);
                                    return Status::kOk;
                                  },
                                  &pieces},
                      &r.st);
    t.push_back(now_ms() - t0);
    r.pieces = pieces;
  }
  r.ms = median(t);
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  std::ostringstream md;
  for (bool spiky : {false, true}) {
    md << "\n"
       << (spiky ? "**Spiky islands** (radii anywhere in [0.6, 1] R: long radial edges)"
                 : "**Coastlines** (radii within 1 % of a few slow waves)")
       << ", seen from a ship at (0, -900000); the island's radius is about 600,000.\n\n";
    md << "| n | Freeman-Loutrel ms | growth | brute force ms | growth | visible pieces | "
          "Prop. 3 edges | vertices tested (steps 15-17) "
          "|\n|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    double last_fl = 0, last_bf = 0;
    const Point2 ship{0, -900000};
    for (int n : {10, 100, 1000, 10000, 100000}) {
      const auto p = star(n, uint64_t(n), spiky);
      const int runs = n <= 1000 ? 5 : 1;
      const Result fl = run_walk(p, ship, runs);
      if (!ok(fl.status)) {
        md << "| " << p.size() << " | " << status_name(fl.status) << " | | | | | | |\n";
        continue;
      }
      double bf = 0;
      if (n <= 1000) {
        std::vector<reference::Pt> q;
        for (const Point2& v : p) q.push_back({v.x, v.y});
        std::vector<double> t;
        for (int k = 0; k < 3; ++k) {
          const double t0 = now_ms();
          const auto out = reference::visible_brute(q, {ship.x, ship.y});
          t.push_back(now_ms() - t0);
          (void)out;
        }
        bf = median(t);
      }
      md << "| " << p.size() << " | " << fmt(fl.ms, 3) << " | "
         << (last_fl > 0 ? fmt(fl.ms / last_fl, 1) + "x" : "") << " | "
         << (bf > 0 ? fmt(bf, 2) : "(not run)") << " | "
         << (bf > 0 && last_bf > 0 ? fmt(bf / last_bf, 1) + "x" : "") << " | " << fl.pieces << " | "
         << fl.st.prop3_edges << " | " << fl.st.vertex_tests << " |\n";
      last_fl = fl.ms;
      last_bf = bf;
    }
    last_fl = last_bf = 0;
  }
  std::ofstream(std::string(argv[1]) + "/view2d.body.md") << md.str();
  return 0;
}
