// Shared pieces of the host benchmarks: a steady clock, medians, and CUT/DRAW runs on
// preallocated buffers so allocation never lands inside a timed region.
#pragma once
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "../support/must.h"
#include "haloplot/haloplot.h"

namespace bench {

inline double now_ms() {
  using namespace std::chrono;
  return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

// A number with a fixed count of decimals, for the reports' tables.
inline std::string fmt(double v, int places = 2) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", places, v);
  return b;
}

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

struct CutTiming {
  double t1 = 0, t2 = 0, group = 0, total = 0;  // ms: preprocessing, pairs, grouping, all
  haloplot::CutStats stats;
  haloplot::CutPlan plan;
};

struct PhaseClock {
  double cells_filled = 0, pairs_tested = 0;
  static void mark(void* ctx, haloplot::CutPhase p) {
    auto* c = static_cast<PhaseClock*>(ctx);
    (p == haloplot::CutPhase::kCellsFilled ? c->cells_filled : c->pairs_tested) = now_ms();
  }
};

// Median of `runs` CUTs. Buffers are sized once from the core's own queries.
inline CutTiming time_cut(const std::vector<haloplot::Edge3>& edges, haloplot::CutParams params,
                          int runs, std::vector<uint64_t>* keep_storage = nullptr,
                          haloplot::CutSet* keep_set = nullptr) {
  using namespace haloplot;
  const uint32_t n = uint32_t(edges.size());
  PhaseClock clock;
  params.phase = &PhaseClock::mark;
  params.phase_context = &clock;
  CutPlan plan;
  must(plan_cut(edges.data(), n, params, &plan));
  std::vector<uint64_t> scratch(plan.scratch_bytes / 8 + 1);
  uint32_t capacity = 4 * n + 1024;
  std::vector<uint64_t> storage(cutset_bytes(n, capacity) / 8 + 1);
  CutSet set;
  CutStats st;
  if (run_cut(plan, edges.data(), scratch.data(), scratch.size() * 8, storage.data(),
              storage.size() * 8, &set, &st) == Status::kCrossingCapacity) {
    capacity = uint32_t(st.crossings + st.near_misses);
    storage.assign(cutset_bytes(n, capacity) / 8 + 1, 0);
  }
  std::vector<double> t1, t2, tg, tt;
  for (int r = 0; r < runs; ++r) {
    const double t0 = now_ms();
    must(plan_cut(edges.data(), n, params, &plan));
    must(run_cut(plan, edges.data(), scratch.data(), scratch.size() * 8, storage.data(),
                 storage.size() * 8, &set, &st));
    const double end = now_ms();
    t1.push_back(clock.cells_filled - t0);
    t2.push_back(clock.pairs_tested - clock.cells_filled);
    tg.push_back(end - clock.pairs_tested);
    tt.push_back(end - t0);
  }
  CutTiming out{median(t1), median(t2), median(tg), median(tt), st, plan};
  if (keep_storage) {
    keep_storage->swap(storage);
    *keep_set = set;
  }
  return out;
}

}  // namespace bench
