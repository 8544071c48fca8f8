// The performance report. Writes docs/reports/performance.md and its
// charts. Every figure is a median of several runs; comparisons are ratios within one run.
//   cut_bench OUT_DIR [--quick]
#include <time.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "chart.h"
#include "demo/cube_array.h"
#include "demo/random_scene.h"
#include "perf_common.h"
#include "pipeline/thread_parts.h"

#ifdef HALOPLOT_HAVE_CGAL
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Sweep_line_2_algorithms.h>

#include "../support/must.h"
#endif

using namespace haloplot;
using namespace haloplot::host;
using bench::fmt;
using bench::median;
using bench::now_ms;

namespace {

// CPU time of the calling thread, ms: what a method running on it used, whatever else the
// shared machine ran meanwhile.
double thread_cpu_ms() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

std::string load_average() {
  std::ifstream f("/proc/loadavg");
  std::string one;
  return f >> one ? one : std::string("?");
}

// All pairs whose x-extents overlap, after a sort by x: the simple baseline, with the same
// exact predicates as CUT so only the pairing strategy differs. Returns the crossing count.
uint64_t baseline_x_sort(const std::vector<Edge3>& e) {
  std::vector<uint32_t> order(e.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  auto lo = [&](uint32_t i) { return std::min(e[i].a.x, e[i].b.x); };
  auto hi = [&](uint32_t i) { return std::max(e[i].a.x, e[i].b.x); };
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return lo(a) < lo(b); });
  uint64_t v = 0;
  for (size_t i = 0; i < order.size(); ++i)
    for (size_t j = i + 1; j < order.size() && lo(order[j]) <= hi(order[i]); ++j) {
      const CrossingTest c = test_crossing(e[order[i]], e[order[j]]);
      if (c.crosses) v += compare_depth_at_crossing(e[order[i]], e[order[j]], c) != 0 || true;
    }
  return v;
}

#ifdef HALOPLOT_HAVE_CGAL
template <typename K>
std::pair<double, size_t> cgal_sweep(const std::vector<Edge3>& e, int runs) {
  std::vector<typename K::Segment_2> segs;
  for (const Edge3& x : e)
    if (x.a.x != x.b.x || x.a.y != x.b.y)
      segs.emplace_back(typename K::Point_2(x.a.x, x.a.y), typename K::Point_2(x.b.x, x.b.y));
  std::vector<double> t;
  size_t count = 0;
  for (int r = 0; r < runs; ++r) {
    std::vector<typename K::Point_2> pts;
    const double t0 = thread_cpu_ms();
    CGAL::compute_intersection_points(segs.begin(), segs.end(), std::back_inserter(pts), false);
    t.push_back(thread_cpu_ms() - t0);
    count = pts.size();
  }
  return {median(t), count};  // CPU time: see section 2
}
#endif

struct Report {
  std::ostringstream md;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: cut_bench OUT_DIR [--quick]\n");
    return 2;
  }
  const std::string dir = argv[1];
  const bool quick = argc > 2 && std::string(argv[2]) == "--quick";
  const int runs = quick ? 1 : 5;
  std::ostringstream md;

  // 1. The paper's EDGE table.
  struct Row {
    uint32_t n;
    double l, g;
    uint32_t v;
    double t1, t2, t;
  };
  const Row paper[] = {{100, 0.100, 0.100, 15, 0.17, 0.26, 0.43},
                       {300, 0.100, 0.100, 153, 0.54, 0.93, 1.47},
                       {1000, 0.010, 0.010, 11, 1.73, 3.62, 5.35},
                       {1000, 0.030, 0.030, 163, 1.72, 2.54, 4.25},
                       {1000, 0.100, 0.100, 1720, 1.71, 4.46, 6.18},
                       {3000, 0.010, 0.010, 149, 5.24, 8.05, 13.29},
                       {3000, 0.030, 0.030, 1487, 5.41, 8.82, 14.22},
                       {3000, 0.100, 0.100, 15656, 5.19, 27.93, 33.12},
                       {10000, 0.003, 0.010, 156, 16.36, 16.45, 32.82},
                       {10000, 0.010, 0.010, 1813, 17.38, 26.02, 43.40},
                       {10000, 0.030, 0.030, 16633, 17.68, 44.78, 67.45},
                       {30000, 0.001, 0.010, 149, 48.33, 43.95, 92.28},
                       {30000, 0.003, 0.010, 1797, 48.46, 54.21, 102.66},
                       {30000, 0.010, 0.010, 16859, 52.85, 98.93, 151.78},
                       {50000, 0.001, 0.010, 315, 77.71, 75.75, 153.46},
                       {50000, 0.003, 0.010, 4953, 79.49, 92.37, 171.87},
                       {50000, 0.010, 0.010, 47222, 86.23, 278.49, 364.72}};
  md << "## 1. The paper's EDGE table, reproduced\n\n"
     << "Scenes in the paper's distribution (dx, dy uniform in [−L, L] on a 1 × 1 screen, scaled "
        "to "
        "2^20 steps), cell side G as printed. V counts crossings (proper, any depth). Paper times "
        "are "
        "CPU seconds on a Prime 750; ours are host milliseconds, median of "
     << runs
     << " runs. T1 = choosing the grid and filling the cell lists, T2 = testing the pairs in "
        "every cell (grouping the CUTSET by edge is listed apart).\n\n"
     << "| N | L | G | V (paper) | V (ours) | ΔV | T1 paper s | T2 paper s | T1 ms | T2 ms | group "
        "ms | T ms | (C,E) pairs |\n"
     << "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  uint64_t seed = 1;
  std::vector<double> ours;
  for (const Row& r : paper) {
    // Several scenes per row: V in the paper is one sample; the mean of a few is steadier.
    const int scenes_per_row = quick ? 1 : 3;
    double v_sum = 0;
    bench::CutTiming last;
    for (int k = 0; k < scenes_per_row; ++k) {
      const auto edges = paper_random(r.n, int64_t(r.l * 1e6 + 0.5), seed++);
      CutParams p;
      p.grid.cell = int32_t(r.g * kCoordLimit + 0.5);
      p.grid.max_cells = 1u << 24;
      last = bench::time_cut(edges, p, runs);
      v_sum += double(last.stats.crossings + last.stats.equal_depth);
    }
    const double v = v_sum / scenes_per_row;
    ours.push_back(v);
    md << "| " << r.n << " | " << r.l << " | " << r.g << " | " << r.v << " | " << fmt(v, 0) << " | "
       << fmt(100.0 * (v - r.v) / std::max<double>(r.v, 1), 1) << "% | " << r.t1 << " | " << r.t2
       << " | " << fmt(last.t1, 3) << " | " << fmt(last.t2, 3) << " | " << fmt(last.group, 3)
       << " | " << fmt(last.total, 3) << " | " << last.stats.cell_pairs << " |\n";
  }
  // Random crossings follow V = k N^2 L^2. Fit k on the largest row, then flag the rows whose
  // printed V falls outside a 3-sigma Poisson band around the model.
  const Row& big = paper[sizeof(paper) / sizeof(paper[0]) - 1];
  const double k = ours.back() / (double(big.n) * big.n * big.l * big.l);
  std::string flagged;
  for (size_t i = 0; i < ours.size(); ++i) {
    const Row& r = paper[i];
    const double model = k * double(r.n) * r.n * r.l * r.l;
    const bool ours_ok = std::abs(ours[i] - model) <= 3 * std::sqrt(model / (quick ? 1 : 3)) + 1;
    const bool paper_ok = std::abs(r.v - model) <= 3 * std::sqrt(model) + 1;
    if (!paper_ok || !ours_ok)
      flagged += "- N = " + std::to_string(r.n) + ", L = " + fmt(r.l, 3) + ": model " +
                 fmt(model, 0) + ", paper " + std::to_string(r.v) + (paper_ok ? "" : " (outside)") +
                 ", ours " + fmt(ours[i], 0) + (ours_ok ? "" : " (outside)") + "\n";
  }
  md << "\n**Where V differs, and why.** Crossings of random segments follow V = k N² L². Fitting "
        "k on "
        "the largest row (k = "
     << fmt(k, 4) << "), every one of our rows lies within 3σ of the model"
     << (flagged.find("ours") != std::string::npos &&
                 flagged.find("(outside)\n") != std::string::npos
             ? " except as marked"
             : "")
     << ". Rows where a count leaves the band:\n\n"
     << (flagged.empty() ? "- none\n" : flagged)
     << "\nThe paper's L = 0.003 rows sit about 19% above the model, which is what L = 1/300 = "
        "0.0033 "
        "gives (the printed L looks rounded); its N = 50,000, L = 0.001 row sits about a third "
        "below "
        "the model, more than sampling noise explains, and we cannot reproduce it.\n";
  md << "\nV is the mean over " << (quick ? 1 : 3)
     << " scenes per row. Rows with a few dozen crossings swing by tens of percent from scene to "
        "scene "
        "(Poisson noise: the paper's V is a single sample); the large rows land within a few "
        "percent. "
        "The paper's biggest row also reports 98,753 (C,E) pairs; ours, with the exact cell cover, "
        "is in "
        "the last column.\n\n";

  // 2. Peers on N = 50,000, L = 0.01: CUT on one thread and on all the machine's.
  {
    const std::string load_before = load_average();
    const auto edges = paper_random(50000, 10000, 777);
    const uint32_t n = uint32_t(edges.size());
    const uint32_t threads = machine_threads();
    CutParams all;
    all.parts = thread_parts(threads);
    // One thread: the median CPU time of plan_cut + run_cut, buffers sized once.
    std::vector<double> cpu_one;
    {
      CutPlan plan;
      must(plan_cut(edges.data(), n, CutParams{}, &plan));
      std::vector<uint64_t> scratch(plan.scratch_bytes / 8 + 1);
      std::vector<uint64_t> storage(cutset_bytes(n, 4 * n) / 8 + 1);
      CutSet set;
      CutStats st;
      for (int r = 0; r < 5 * runs + 1; ++r) {
        const double t0 = thread_cpu_ms();
        must(plan_cut(edges.data(), n, CutParams{}, &plan));
        must(run_cut(plan, edges.data(), scratch.data(), scratch.size() * 8, storage.data(),
                     storage.size() * 8, &set, &st));
        if (r > 0) cpu_one.push_back(thread_cpu_ms() - t0);  // the first warms the caches
      }
    }
    const double cut_cpu = median(cpu_one);
    // Wall time (and the phases) for one thread and all, alternated, so a busy spell on the
    // machine touches both alike; the fastest round of each.
    const int rounds = quick ? 1 : 9;
    std::vector<bench::CutTiming> one_runs, all_runs;
    for (int r = 0; r < rounds; ++r) {
      one_runs.push_back(bench::time_cut(edges, CutParams{}, 3));
      all_runs.push_back(bench::time_cut(edges, all, 3));
    }
    auto fastest = [](const std::vector<bench::CutTiming>& v) {
      return *std::min_element(
          v.begin(), v.end(),
          [](const bench::CutTiming& a, const bench::CutTiming& b) { return a.total < b.total; });
    };
    const bench::CutTiming cut = fastest(one_runs), cut_all = fastest(all_runs);
    const uint64_t v = cut.stats.crossings + cut.stats.equal_depth;
    const uint64_t v_all = cut_all.stats.crossings + cut_all.stats.equal_depth;
    std::vector<double> tb;
    uint64_t vb = 0;
    for (int r = 0; r < std::max(1, runs / 2); ++r) {
      const double t0 = thread_cpu_ms();
      vb = baseline_x_sort(edges);
      tb.push_back(thread_cpu_ms() - t0);
    }
    const double base = median(tb);
    const std::string all_label = "all " + std::to_string(threads) + " threads";
    auto faster = [&](double t) {
      return fmt(t / cut_cpu, 1) + "× | " + fmt(t / cut_all.total, 1) + "× |";
    };
    // The threads' gain, like against like: both by the wall clock, each its fastest round.
    const double gain = cut.total / cut_all.total;
    md << "## 2. Against the peers (N = 50,000, L = 0.01, seed 777, one run of this report)\n\n"
       << "| method | crossings | ms | CUT on one thread is faster by | CUT on " << all_label
       << " is faster by |\n|---|---:|---:|---:|---:|\n"
       << "| haloplot CUT, one thread (default grid, exact predicates; CPU time) | " << v << " | "
       << fmt(cut_cpu, 2) << " | 1× | " << fmt(cut_cpu / cut_all.total, 2) << "× |\n"
       << "| haloplot CUT, one thread (wall time, as the next row) | " << v << " | "
       << fmt(cut.total, 2) << " | " << fmt(cut.total / cut_cpu, 2) << "× | " << fmt(gain, 2)
       << "× |\n"
       << "| haloplot CUT, " << all_label << " (`--threads " << threads << "`; wall time) | "
       << v_all << " | " << fmt(cut_all.total, 2) << " | " << fmt(cut_all.total / cut_cpu, 2)
       << "× | 1× |\n"
       << "| all pairs after an x-sort (same predicates; CPU time) | " << vb << " | "
       << fmt(base, 1) << " | " << faster(base) << "\n";
#ifdef HALOPLOT_HAVE_CGAL
    const auto epeck =
        cgal_sweep<CGAL::Exact_predicates_exact_constructions_kernel>(edges, quick ? 1 : 3);
    const auto epick =
        cgal_sweep<CGAL::Exact_predicates_inexact_constructions_kernel>(edges, quick ? 1 : 3);
    md << "| CGAL `compute_intersection_points`, exact constructions (Epeck; CPU time) | "
       << epeck.second << " | " << fmt(epeck.first, 1) << " | " << faster(epeck.first) << "\n"
       << "| CGAL `compute_intersection_points`, inexact constructions (Epick; CPU time) | "
       << epick.second << " | " << fmt(epick.first, 1) << " | " << faster(epick.first) << "\n";
    md << "\n**CUT against CGAL's sweep with exact constructions (the aim: at least 50×): "
       << fmt(epeck.first / cut_cpu, 1) << "× on one thread, "
       << fmt(epeck.first / cut_all.total, 1) << "× on " << all_label << ".** "
       << (epeck.first / cut_cpu < 1.7 * 50
               ? "With CGAL's own spread between runs (below), the one-thread figure may fall "
                 "under 50× in another run. "
               : "")
       << "CGAL runs on one thread either way. CGAL counts "
          "intersection points, so a point where k segments meet counts once; in random scenes "
          "that never happens and the counts agree exactly"
       << (epeck.second == v && v_all == v ? " (they do here)"
                                           : " (**here they differ: see the note**)")
       << ".\n\n";
#else
    md << "\nCGAL was not installed when this report was made (Debian: libcgal-dev; "
          "tools/bench_performance.sh installs it when it runs as root with apt); the benchmark "
          "builds and runs without it.\n\n";
#endif
    if (vb != v) md << "**The baseline's count differs from CUT's: a bug.**\n\n";
    if (v_all != v) md << "**CUT's count on threads differs from one thread's: a bug.**\n\n";
    md << "How it is timed. These machines are shared (load average " << load_before
       << " as this "
          "section began, "
       << load_average() << " as it ended, on " << threads
       << " cores). A single-threaded method is timed by its thread's CPU time, the median of "
          "its runs (CUT's "
       << cpu_one.size() << ", the x-sort's " << tb.size() << ", CGAL's " << (quick ? 1 : 3)
       << " each): wall time would charge a long run (CGAL's take a quarter of a second and "
          "more) with other jobs' bursts that a few-millisecond CUT run mostly escapes. CUT on "
       << all_label
       << " is timed by the wall clock, as CPU time adds its threads up: the fastest "
          "of "
       << rounds
       << " rounds (each the median of 3 runs), one thread and all threads alternating; the "
          "load makes this figure, and the ratios against it, the less steady ones. What the "
          "threads gain is measured like against like: one thread's wall time in the same "
          "alternating rounds (the second row, its fastest round) against all threads' (**"
       << fmt(gain, 2) << "×** on " << all_label
       << "); the first row's ratio in the last column sets one thread's CPU median against "
          "the threads' wall time, a figure for the peers' columns, not for the threads. Where "
          "CUT's time goes on one thread (phase clock, wall, its fastest round): T1 "
       << fmt(cut.t1, 2)
       << " ms (the plan: the range check with the scene's extent in one pass, the grid chosen "
          "from sampled lengths, and the bound on (cell, edge) pairs; then one walk per edge that "
          "counts its cells and logs them; then the fill: each logged visit drops its edge's "
          "index, 4 bytes, where its entry goes, and the entries, a copy of each edge of 28 "
          "bytes, are written in list order from those indices), T2 "
       << fmt(cut.t2, 2) << " ms (" << cut.stats.pairs_tested
       << " pairs sharing a cell, every one decided by its four side values without a branch "
          "into a mask of the pairs that cross; only those "
       << (cut.stats.crossings + cut.stats.equal_depth + cut.stats.rejected)
       << " take the branches after it: which cell owns the crossing, depth, position), grouping "
       << fmt(cut.group, 2) << " ms. On " << all_label << ": T1 " << fmt(cut_all.t1, 2)
       << " ms, T2 " << fmt(cut_all.t2, 2) << " ms, grouping " << fmt(cut_all.group, 2)
       << " ms (the plan, the fill, the pairs, the grouping and the sorting each run in parts; "
          "the sums and the split between the parts on one thread). CGAL's own time varies "
          "by about 1.7x between runs on these machines, so read its ratio with that margin.\n\n";
  }

  // 3. Scaling at about one crossing per edge: L = 2.236 / sqrt(N).
  {
    md << "## 3. Scaling: time per (N + K)\n\n"
       << "N from 10^3 to 10^6 with L = 2.236 / √N, which keeps about one crossing per edge. "
          "Default grid.\n\n"
       << "| N | L | K | CUT ms | ns per (N + K) |\n|---:|---:|---:|---:|---:|\n";
    std::vector<uint32_t> ns = {1000, 3000, 10000, 30000, 100000, 300000, 1000000};
    if (quick) ns = {1000, 10000, 100000};
    bench::Series s{"CUT, ns per (N + K)", "#1f77b4", {}};
    double lo = 1e300, hi = 0;
    for (uint32_t n : ns) {
      const int64_t l = int64_t(2236000.0 / std::sqrt(double(n)) + 0.5);
      const auto edges = paper_random(n, l, 4000 + n);
      const bench::CutTiming t = bench::time_cut(edges, CutParams{}, runs);
      const double crossings = double(t.stats.crossings + t.stats.equal_depth);
      const double per = t.total * 1e6 / (double(n) + crossings);
      lo = std::min(lo, per), hi = std::max(hi, per);
      s.points.push_back({double(n), per});
      md << "| " << n << " | " << fmt(double(l) / 1e6, 5) << " | " << fmt(crossings, 0) << " | "
         << fmt(t.total, 2) << " | " << fmt(per, 1) << " |\n";
    }
    md << "\nLargest over smallest time per (N + K): **" << fmt(hi / lo, 2)
       << "×** (goal: at most 1.5×" << (hi / lo <= 1.5 ? ", met" : ", **not met**") << ").\n\n"
       << "![scaling](perf_scaling.png)\n\n";
    bench::write_chart(dir + "/perf_scaling.svg", "CUT: time per (N + K)", "N (edges)",
                       "ns per (N + K)", {s}, true);
  }

  // 4. Grid size: sweep lambda on a uniform and a clustered scene.
  {
    md << "## 4. Grid size\n\n"
       << "Cell side G = λ × (average projected length). Uniform: the paper's N = 50,000, L = "
          "0.01. "
          "Clustered: 45,000 of 50,000 edges in a square of 1/10 the page side, the rest spread "
          "out.\n\n"
       << "| λ | uniform ms | uniform B | clustered ms | clustered B "
          "|\n|---:|---:|---:|---:|---:|\n";
    const auto uniform = paper_random(50000, 10000, 99);
    std::vector<Edge3> clustered = paper_random(5000, 10000, 98);
    for (Edge3 e : paper_random(45000, 1000, 97)) {
      const int32_t off = kCoordLimit / 2;
      e.a.x = e.a.x / 10 + off, e.b.x = e.b.x / 10 + off, e.a.y = e.a.y / 10 + off,
      e.b.y = e.b.y / 10 + off;
      clustered.push_back(e);
    }
    const double lambdas[] = {0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 3.0, 4.0, 8.0};
    bench::Series su{"uniform", "#1f77b4", {}}, sc{"clustered", "#d62728", {}};
    double best_u = 1e300, best_c = 1e300, def_u = 0, def_c = 0;
    for (double lam : lambdas) {
      CutParams p;
      p.grid.lambda_q8 = uint32_t(lam * 256 + 0.5);
      const bench::CutTiming u = bench::time_cut(uniform, p, runs),
                             c = bench::time_cut(clustered, p, runs);
      su.points.push_back({lam, u.total});
      sc.points.push_back({lam, c.total});
      best_u = std::min(best_u, u.total), best_c = std::min(best_c, c.total);
      if (lam == 1.0) def_u = u.total, def_c = c.total;
      md << "| " << lam << " | " << fmt(u.total, 2) << " | " << u.plan.grid.nx << " | "
         << fmt(c.total, 2) << " | " << c.plan.grid.nx << " |\n";
    }
    md << "\nThe default (λ = 1) against the best λ in this sweep: uniform **"
       << fmt(def_u / best_u, 2) << "×**, clustered **" << fmt(def_c / best_c, 2)
       << "×** (the paper: within a factor of 2).\n\n"
       << "![grid](perf_grid.png)\n\n";
    bench::write_chart(dir + "/perf_grid.svg", "CUT time against the grid size", "lambda", "ms",
                       {su, sc}, true);
  }

  // 5. DRAW alone against CUT + DRAW, and 6. memory.
  {
    CubeArrayParams cp;
    const auto demo = cube_array(cp);
    const auto rnd = paper_random(50000, 10000, 55);
    md << "## 5. Re-drawing with a new halo width\n\n"
       << "| scene | CUT ms | DRAW ms (paper halo) | DRAW ms (exact halo) | CUT + DRAW over DRAW "
          "|\n|---|---:|---:|---:|---:|\n";
    std::string mem;
    for (const auto* scene : {&demo, &rnd}) {
      std::vector<uint64_t> storage;
      CutSet set;
      const bench::CutTiming t = bench::time_cut(*scene, CutParams{}, runs, &storage, &set);
      std::vector<Gap> scratch(draw_scratch_bytes(set) / sizeof(Gap) + 1);
      uint64_t spans = 0;
      auto sink = SpanSink{[](void* c, const Span&) {
                             ++*static_cast<uint64_t*>(c);
                             return Status::kOk;
                           },
                           &spans};
      auto time_draw = [&](HaloMode mode) {
        std::vector<double> v;
        for (int r = 0; r < runs; ++r) {
          const double t0 = now_ms();
          must(draw(set, DrawParams{50, mode}, scratch.data(), scratch.size() * sizeof(Gap), sink,
                    nullptr));
          v.push_back(now_ms() - t0);
        }
        return median(v);
      };
      const double dp = time_draw(HaloMode::kPaper), de = time_draw(HaloMode::kExact);
      const char* name =
          scene == &demo ? "demo, 28 × 28 cubes (9408 edges)" : "random, N = 50,000, L = 0.01";
      md << "| " << name << " | " << fmt(t.total, 2) << " | " << fmt(dp, 2) << " | " << fmt(de, 2)
         << " | " << fmt((t.total + dp) / dp, 1) << "× |\n";
      const uint32_t n = uint32_t(scene->size());
      const double per_edge = 1.0 / double(n);
      mem += "| " + std::string(name) + " | " + fmt(double(t.plan.scratch_bytes) * per_edge, 1) +
             " | 4 + 12 per crossing (" +
             fmt(double(cutset_bytes(n, set.n_crossings)) * per_edge, 1) + " per edge here) | " +
             fmt(double(draw_scratch_bytes(set)), 0) + " bytes in all |\n";
    }
    md << "\nDRAW reads only the CUTSET, so a new halo width costs the DRAW column alone.\n\n"
       << "## 6. Memory\n\n"
       << "| scene | CUT scratch, bytes per edge (freed after CUT) | CUTSET, bytes per edge | DRAW "
          "scratch |\n|---|---:|---|---:|\n"
       << mem
       << "\nCUT's scratch holds the cell index (4 bytes per cell, at most 2N + 64 cells), the "
          "(cell, edge) lists (28 bytes per pair on a 64-bit host, as here: a copy of the edge "
          "beside its index; 20 on a 32-bit controller, the projection only; 4 with "
          "`compact_cells` off) and, on a host, the log of the cell walk (8 bytes per pair), all "
          "sized by the bound from the edges' boxes. The CUTSET "
          "keeps 4 bytes per edge plus 12 per crossing. "
          "DRAW needs 16 bytes per crossing on the busiest edge only.\n\n";
  }

  std::ofstream out(dir + "/performance.body.md");
  out << md.str();
  return 0;
}
