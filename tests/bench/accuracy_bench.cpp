// What accuracy costs in time (a first answer; the precision policies inside the core come
// with the accuracy issue). Writes OUT_DIR/accuracy.body.md and a chart.
//   1. Predicates: the same all-pairs-after-x-sort loop with the core's exact int64
//      predicates, with double, and with float, on random scenes and on hard families. Each
//      floating variant is timed and its topological errors counted against the exact answer:
//      missed or spurious crossings, and wrong front/back decisions.
//   2. Halo arithmetic: the paper's W / sin(theta) gap against the exact stadium gap, both
//      against a long-double reference: error of plotted span ends, in steps, and DRAW time.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "../support/must.h"
#include "chart.h"
#include "demo/cube_array.h"
#include "demo/random_scene.h"
#include "perf_common.h"
#include "precision_modes.h"
#include "reference/draw_reference.h"

using namespace haloplot;
using bench::fmt;
using bench::median;
using bench::now_ms;

namespace {

struct Decision {
  uint32_t behind, front;
  bool operator<(const Decision& o) const {
    return behind != o.behind ? behind < o.behind : front < o.front;
  }
  bool operator==(const Decision& o) const { return behind == o.behind && front == o.front; }
};

// The crossing test and depth decision in a floating type T, written the textbook way.
template <typename T>
bool decide(const Edge3& p, const Edge3& q, bool* p_behind) {
  const T pdx = T(p.b.x) - T(p.a.x), pdy = T(p.b.y) - T(p.a.y), qdx = T(q.b.x) - T(q.a.x),
          qdy = T(q.b.y) - T(q.a.y);
  const T s1 = pdx * (T(q.a.y) - T(p.a.y)) - pdy * (T(q.a.x) - T(p.a.x));
  const T s2 = pdx * (T(q.b.y) - T(p.a.y)) - pdy * (T(q.b.x) - T(p.a.x));
  const T s3 = qdx * (T(p.a.y) - T(q.a.y)) - qdy * (T(p.a.x) - T(q.a.x));
  const T s4 = qdx * (T(p.b.y) - T(q.a.y)) - qdy * (T(p.b.x) - T(q.a.x));
  if (!((s1 > 0 && s2 < 0) || (s1 < 0 && s2 > 0))) return false;
  if (!((s3 > 0 && s4 < 0) || (s3 < 0 && s4 > 0))) return false;
  const T t = s3 / (s3 - s4), u = s1 / (s1 - s2);
  const T zp = T(p.a.z) + (T(p.b.z) - T(p.a.z)) * t, zq = T(q.a.z) + (T(q.b.z) - T(q.a.z)) * u;
  if (zp == zq) return false;
  *p_behind = zp < zq;
  return true;
}

bool decide_exact(const Edge3& p, const Edge3& q, bool* p_behind) {
  const CrossingTest c = test_crossing(p, q);
  if (!c.crosses) return false;
  const int d = compare_depth_at_crossing(p, q, c);
  if (d == 0) return false;
  *p_behind = d < 0;
  return true;
}

// All pairs after an x-sort, with the given decision: the decisions and the time (median).
template <typename Decide>
std::vector<Decision> run(const std::vector<Edge3>& e, Decide decide_fn, int runs, double* ms) {
  std::vector<uint32_t> order(e.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  auto lo = [&](uint32_t i) { return std::min(e[i].a.x, e[i].b.x); };
  auto hi = [&](uint32_t i) { return std::max(e[i].a.x, e[i].b.x); };
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return lo(a) < lo(b); });
  std::vector<Decision> out;
  std::vector<double> t;
  for (int r = 0; r < runs; ++r) {
    out.clear();
    const double t0 = now_ms();
    for (size_t i = 0; i < order.size(); ++i)
      for (size_t j = i + 1; j < order.size() && lo(order[j]) <= hi(order[i]); ++j) {
        bool pb = false;
        const uint32_t a = order[i], b = order[j];
        if (decide_fn(e[a], e[b], &pb)) out.push_back(pb ? Decision{a, b} : Decision{b, a});
      }
    t.push_back(now_ms() - t0);
  }
  *ms = median(t);
  std::sort(out.begin(), out.end());
  return out;
}

struct Errors {
  size_t missed = 0, spurious = 0, flipped = 0;
  size_t total() const { return missed + spurious + flipped; }
};

Errors compare(const std::vector<Decision>& exact, const std::vector<Decision>& got) {
  Errors err;
  std::set<std::pair<uint32_t, uint32_t>> ex, gt;
  std::set<Decision> exd(exact.begin(), exact.end());
  for (const auto& d : exact) ex.insert({std::min(d.behind, d.front), std::max(d.behind, d.front)});
  for (const auto& d : got) gt.insert({std::min(d.behind, d.front), std::max(d.behind, d.front)});
  for (const auto& p : ex) err.missed += !gt.count(p);
  for (const auto& p : gt) err.spurious += !ex.count(p);
  for (const auto& d : got)
    if (ex.count({std::min(d.behind, d.front), std::max(d.behind, d.front)}) && !exd.count(d))
      ++err.flipped;
  return err;
}

// Hard scenes: pairs of long edges whose direction vectors (a, b) and offset (c, d) satisfy
// a d - b c = 1 (extended Euclid), so each orientation test is a difference of two ~2^38
// products that equals +-1 or +-2: exact integers decide it, a 24-bit float mantissa cannot.
int64_t egcd(int64_t a, int64_t b, int64_t* x, int64_t* y) {
  if (b == 0) {
    *x = 1;
    *y = 0;
    return a;
  }
  int64_t x1, y1;
  const int64_t g = egcd(b, a % b, &x1, &y1);
  *x = y1;
  *y = x1 - (a / b) * y1;
  return g;
}

std::vector<Edge3> hard_scene(uint64_t seed) {
  SplitMix64 r(seed);
  std::vector<Edge3> e;
  while (e.size() < 600) {
    const int64_t a = r.uniform(1 << 18, (1 << 19) - 1), b = r.uniform(1 << 18, (1 << 19) - 1);
    int64_t x, y;
    if (egcd(a, b, &x, &y) != 1) continue;
    // a x + b y = 1: d = x, c = -y gives a d - b c = 1; shift c into [0, a).
    int64_t c = -y, d = x;
    const int64_t k = (c >= 0 ? -(c / a) : (-c + a - 1) / a);
    c += k * a;
    d += k * b;
    if (d < 0 || a + c > kCoordMax || b + d > kCoordMax) continue;
    const int64_t px = r.uniform(0, kCoordMax - a - c), py = r.uniform(2, kCoordMax - b - d);
    // P: p0 -> p0 + (a, b). Q: starts 1/|dp| to the left of P's line, ends to its right.
    e.push_back(Edge3{{int32_t(px), int32_t(py), int32_t(r.uniform(0, kCoordMax))},
                      {int32_t(px + a), int32_t(py + b), int32_t(r.uniform(0, kCoordMax))}});
    e.push_back(
        Edge3{{int32_t(px + c), int32_t(py + d), int32_t(r.uniform(0, kCoordMax))},
              {int32_t(px + c + a), int32_t(py + d + b - 2), int32_t(r.uniform(0, kCoordMax))}});
  }
  return e;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) return 2;
  if (std::string(argv[1]) == "--draw-mode" && argc == 3)  // one DRAW, for callgrind
    return bench::draw_once_in_mode(std::atoi(argv[2])) > 0 ? 0 : 1;
  const std::string dir = argv[1];
  const int runs = 5;
  std::ostringstream md;
  md << "## 1. Exact predicates against floating point\n\n"
     << "The same pairing loop (all pairs whose x-extents overlap, after an x-sort), deciding each "
        "pair "
        "three ways: the core's exact int64 predicates, double, and float. Errors are counted "
        "against "
        "the exact answer: crossings missed, crossings invented, and front/back decisions flipped. "
        "Time "
        "is the median of "
     << runs << " runs; the ratio is to the exact run on the same scene.\n\n"
     << "| scene | exact ms | double ms (ratio) | double errors | float ms (ratio) | float errors "
        "(missed / invented / flipped) |\n"
     << "|---|---:|---:|---:|---:|---:|\n";
  struct Scene {
    std::string name;
    std::vector<Edge3> edges;
  };
  std::vector<Scene> scenes = {
      {"random, N = 50,000, L = 0.01", host::paper_random(50000, 10000, 3)},
      {"random, N = 3,000, L = 0.1", host::paper_random(3000, 100000, 4)},
      {"hard: 300 pairs of long edges a hair apart (a d - b c = 1)", hard_scene(5)}};
  bench::Series pts_exact{"exact int64", "#2ca02c", {}}, pts_double{"double", "#1f77b4", {}},
      pts_float{"float", "#d62728", {}};
  double ratio_lo = 1e300, ratio_hi = 0;
  for (const Scene& s : scenes) {
    double te, td, tf, warm;
    run(s.edges, decide_exact, 1, &warm);  // warm caches and clocks before timing anything
    const auto ex = run(s.edges, decide_exact, runs, &te);
    const auto dd = run(s.edges, decide<double>, runs, &td);
    const auto ff = run(s.edges, decide<float>, runs, &tf);
    const Errors ed = compare(ex, dd), ef = compare(ex, ff);
    ratio_lo = std::min({ratio_lo, td / te, tf / te});
    ratio_hi = std::max({ratio_hi, td / te, tf / te});
    md << "| " << s.name << " (" << ex.size() << " crossings) | " << fmt(te, 1) << " | "
       << fmt(td, 1) << " (" << fmt(td / te, 2) << "×) | " << ed.total() << " | " << fmt(tf, 1)
       << " (" << fmt(tf / te, 2) << "×) | " << ef.missed << " / " << ef.spurious << " / "
       << ef.flipped << " |\n";
    if (&s == &scenes.back()) {
      pts_exact.points.push_back({1.0, 0.0});
      pts_double.points.push_back({td / te, double(ed.total())});
      pts_float.points.push_back({tf / te, double(ef.total())});
    }
  }
  md << "\nIn this run double and float took " << fmt(ratio_lo, 2) << "–" << fmt(ratio_hi, 2)
     << "× the exact time: exactness costs nothing measurable. The integer predicates are a few "
        "64-bit multiplies with no conversions, and they are exact by construction (checked "
        "against "
        "an independent 128-bit reference in the tests). "
        "Single precision holds 24 bits, so the ~2^38 products of the hard pairs lose their last "
        "14 "
        "bits and their +-1 differences become noise. Double precision holds 53 bits: for 20-bit "
        "coordinates every orientation product (< 2^42) is exact, so it decides these scenes "
        "correctly "
        "too. Its remaining risk is the depth comparison at near-ties (the exact difference can be "
        "2^-41 of a step, below double's rounding of a 2^20 depth), which random scenes do not hit "
        "and "
        "20-bit integer depths make impractical to construct; the core's exact comparison has no "
        "such "
        "case to worry about.\n\n"
     << "![error against time](accuracy_predicates.png)\n\n";
  bench::write_chart(dir + "/accuracy_predicates.svg",
                     "Hard scene: topological errors against time", "time / exact time",
                     "wrong decisions", {pts_exact, pts_double, pts_float}, false);

  // 2. Halo arithmetic.
  md << "## 2. Halo arithmetic: the paper's gap against the exact gap\n\n"
     << "DRAW on the demo scene and on a random scene, W = 50, each mode against a long-double "
        "reference of its own definition (tests/reference/draw_reference.h). Error is the largest "
        "and "
        "mean distance, in steps, between a plotted span end and the reference's.\n\n"
     << "| scene | mode | DRAW ms | max error | mean error | spans "
        "|\n|---|---|---:|---:|---:|---:|\n";
  CubeArrayParams cp;
  const std::vector<std::pair<std::string, std::vector<Edge3>>> draw_scenes = {
      {"demo, 28 × 28 cubes", host::cube_array(cp)},
      {"random, N = 20,000, L = 0.02", host::paper_random(20000, 20000, 8)}};
  for (const auto& [name, edges] : draw_scenes) {
    std::vector<uint64_t> storage;
    CutSet set;
    bench::time_cut(edges, CutParams{}, 1, &storage, &set);
    std::vector<reference::RefGapInput> cuts;
    for (uint32_t e = 0; e < set.n_edges; ++e)
      for (uint32_t k = 0; k < set.count(e); ++k) {
        const Crossing& c = set.begin(e)[k];
        const CrossingTest x = test_crossing(edges[c.behind], edges[c.front_edge()]);
        const bool forward =
            c.behind < c.front_edge();  // test_crossing's t is along its first edge
        const CrossingTest y = forward ? x : test_crossing(edges[c.front_edge()], edges[c.behind]);
        const auto t = forward ? reference::ld(y.tn) / reference::ld(y.den)
                               : reference::ld(y.un) / reference::ld(y.den);
        cuts.push_back({c.behind, c.front_edge(), t});
      }
    for (HaloMode mode : {HaloMode::kPaper, HaloMode::kExact}) {
      std::vector<Gap> scratch(draw_scratch_bytes(set) / sizeof(Gap) + 1);
      std::vector<Span> spans;
      std::vector<double> t;
      for (int r = 0; r < runs; ++r) {
        spans.clear();
        const double t0 = now_ms();
        must(draw(set, DrawParams{50, mode}, scratch.data(), scratch.size() * sizeof(Gap),
                  SpanSink{[](void* c, const Span& s) {
                             static_cast<std::vector<Span>*>(c)->push_back(s);
                             return Status::kOk;
                           },
                           &spans},
                  nullptr));
        t.push_back(now_ms() - t0);
      }
      const auto ref = reference::draw_ref(edges, cuts, 50, mode == HaloMode::kExact);
      std::map<uint32_t, std::vector<reference::RefSpan>> by_edge;
      for (const auto& r : ref) by_edge[r.edge].push_back(r);
      std::map<uint32_t, size_t> seen;
      double worst = 0, sum = 0;
      size_t n = 0;
      for (const Span& s : spans) {
        const auto& list = by_edge[s.edge];
        const size_t k = seen[s.edge]++;
        if (k >= list.size()) continue;
        const auto& r = list[k];
        for (double err : {double(std::fabs(s.x0 - r.x0)), double(std::fabs(s.y0 - r.y0)),
                           double(std::fabs(s.x1 - r.x1)), double(std::fabs(s.y1 - r.y1))}) {
          worst = std::max(worst, err);
          sum += err;
          ++n;
        }
      }
      md << "| " << name << " | "
         << (mode == HaloMode::kPaper ? "paper (W / sin θ)" : "exact (stadium)") << " | "
         << fmt(median(t), 2) << " | " << fmt(worst, 3) << " | " << fmt(n ? sum / double(n) : 0, 3)
         << " | " << spans.size() << " |\n";
    }
  }
  md << "\nBoth modes stay within the half step that rounding to the plotter grid costs: the Q0.32 "
        "positions and the outward-rounded integer square roots add less than a hundredth of a "
        "step. "
        "The exact halo costs more time (a disc and a strip per crossing, with 128-bit "
        "discriminants) "
        "and buys bounded gaps for near-parallel edges and the near misses the paper's gap cannot "
        "see.\n\n";
  bench::precision_modes_section(dir, runs, md);
  std::ofstream(dir + "/accuracy.body.md") << md.str();
  return 0;
}
