// Cortex-M4 instruction counts for CUT on the HALO paper's EDGE scenes that fit in SRAM beside
// the Edge3 array (N <= 1000), built on the chip from the same seeds as the host uses. Prints
// one "fw row N L_MILLIONTHS SEED CROSSINGS CUT_INSTRUCTIONS CELL_PAIRS" line per row; the CTest
// firmware_cut_bench checks CROSSINGS against the host, tools/bench_performance.sh reports.
#include "haloplot/haloplot.h"
#include "haloplot/scene/random_edges.h"
#include "platform/instruction_counter.h"
#include "platform/semihosting.h"

using namespace haloplot;
using namespace haloplot::fw;

namespace {

constexpr uint32_t kMaxEdges = 1000;
Edge3 edges[kMaxEdges];
alignas(8) uint8_t arena[72 * 1024];

void print_row(uint32_t n, int64_t l, uint64_t seed, uint32_t crossings, uint64_t instructions,
               uint32_t cell_pairs) {
  char line[160];
  char* p = append(line, "fw row ");
  p = append_u64(p, n);
  p = append(p, " ");
  p = append_i64(p, l);
  p = append(p, " ");
  p = append_u64(p, seed);
  p = append(p, " ");
  p = append_u64(p, crossings);
  p = append(p, " ");
  p = append_u64(p, instructions);
  p = append(p, " ");
  p = append_u64(p, cell_pairs);
  append(p, "\n");
  semihost_print(line);
}

}  // namespace

int main() {
  counter_start();
  struct Row {
    uint32_t n;
    int64_t l_millionths;
  };
  const Row rows[] = {{100, 100000}, {300, 100000}, {1000, 10000}, {1000, 30000}, {1000, 100000}};
  uint64_t seed = 500;
  for (const Row& r : rows) {
    random_edges(r.n, r.l_millionths, seed, edges);
    CutParams p;
    p.compact_cells = false;  // 4 bytes per (cell, edge) pair on the chip
    CutPlan plan;
    Status s = plan_cut(edges, r.n, p, &plan);
    const size_t cutset = (cutset_bytes(r.n, 4 * r.n) + 7) & ~size_t{7};
    if (!ok(s) || cutset + plan.scratch_bytes > sizeof arena) {
      semihost_print("fw FAILED: row does not fit\n");
      semihost_exit(1);
    }
    CutSet set;
    CutStats st;
    const uint64_t t0 = counter_ticks();
    s = plan_cut(edges, r.n, p, &plan);
    if (ok(s))
      s = run_cut(plan, edges, arena + cutset, sizeof arena - cutset, arena, cutset, &set, &st);
    const uint64_t t1 = counter_ticks();
    if (!ok(s)) {
      semihost_print("fw FAILED: ");
      semihost_print(status_name(s));
      semihost_print("\n");
      semihost_exit(1);
    }
    print_row(r.n, r.l_millionths, seed, uint32_t(st.crossings + st.equal_depth),
              ticks_to_instructions(t1 - t0), st.cell_pairs);
    ++seed;
  }
  semihost_exit(0);
}
