// The per-CPU benchmark (tools/bench_cpus.sh), one workload per image:
//   BENCH_CUT:  CUT on the HALO paper's EDGE rows that fit beside the edge array (N <= 1000),
//               the scenes, seeds and parameters of firmware/selftest/cut_bench.cpp. Prints
//               "fw row N L_MILLIONTHS SEED CROSSINGS INSTRUCTIONS CELL_PAIRS" per row.
//   BENCH_FIG4: the paper's Figure 4 (28 x 28 cubes, 9408 edges, halo 50, the paper's gap) in
//               bands in a 64 KB arena, as firmware/selftest/band_selftest.cpp plots it, the
//               points drained without a motion run. Prints "fw fig4 BANDS PIECES RECORDS
//               CUT_INSTRUCTIONS DRAW_INSTRUCTIONS MARGIN_PASS_INSTRUCTIONS".
//   BENCH_DRAW: 20 x 20 cubes as Figure 4 shows its 28 x 28, in one piece (no bands, halo 50,
//               the paper's gap): CUT, then DRAW alone between the histogram's marks. Prints "fw
//               draw CROSSINGS SPANS CUT_INSTRUCTIONS DRAW_INSTRUCTIONS".
// The crossings, pieces and records are the same on every CPU (the script checks); the
// instruction counts are the CPU's (counter.cpp).
#include "haloplot/haloplot.h"
#include "platform/console.h"
#include "platform/instruction_counter.h"
#include "platform/semihosting.h"

#if defined(BENCH_CUT)
#include "haloplot/scene/random_edges.h"
#elif defined(BENCH_DRAW)
#include "haloplot/memory/sized_stage.h"
#include "haloplot/scene/cube_array.h"
#else
#include "haloplot/band/conductor.h"
#include "haloplot/scene/cube_array.h"
#endif

using namespace haloplot;
using namespace haloplot::fw;

// Marks of the measured spans for the histogram of tools/bench_cpus.sh, which counts only the
// instructions executed between a call of the first and one of the second (by their names in
// QEMU's exec log); empty otherwise.
extern "C" __attribute__((noinline)) void bench_span_begin() { __asm__ volatile(""); }
extern "C" __attribute__((noinline)) void bench_span_end() { __asm__ volatile(""); }

namespace {

void print_numbers(const char* tag, const uint64_t* v, int n) {
  char line[200];
  char* p = append(line, tag);
  for (int i = 0; i < n; ++i) {
    p = append(p, " ");
    p = append_u64(p, v[i]);
  }
  append(p, "\n");
  semihost_print(line);
}

[[noreturn]] void fail(const char* what, Status s) {
  semihost_print("fw FAILED: ");
  semihost_print(what);
  semihost_print(": ");
  semihost_print(status_name(s));
  semihost_print("\n");
  semihost_exit(1);
}

#if defined(BENCH_CUT)
constexpr uint32_t kMaxEdges = 1000;
Edge3 edges[kMaxEdges];
alignas(8) uint8_t arena[72 * 1024];

void run() {
  struct Row {
    uint32_t n;
    int64_t l_millionths;
  };
  const Row rows[] = {{100, 100000}, {300, 100000}, {1000, 10000}, {1000, 30000}, {1000, 100000}};
  uint64_t seed = 500;
  for (const Row& r : rows) {
    random_edges(r.n, r.l_millionths, seed, edges);
    CutParams p;
    p.compact_cells = false;  // 4 bytes per (cell, edge) pair, as on the M4
    CutPlan plan;
    Status s = plan_cut(edges, r.n, p, &plan);
    const size_t cutset = (cutset_bytes(r.n, 4 * r.n) + 7) & ~size_t{7};
    if (!ok(s) || cutset + plan.scratch_bytes > sizeof arena) fail("row does not fit", s);
    CutSet set;
    CutStats st;
    bench_span_begin();
    const uint64_t t0 = counter_ticks();
    s = plan_cut(edges, r.n, p, &plan);
    if (ok(s))
      s = run_cut(plan, edges, arena + cutset, sizeof arena - cutset, arena, cutset, &set, &st);
    const uint64_t t1 = counter_ticks();
    bench_span_end();
    if (!ok(s)) fail("cut", s);
    const uint64_t v[] = {r.n,
                          uint64_t(r.l_millionths),
                          seed,
                          st.crossings + st.equal_depth,
                          ticks_to_instructions(t1 - t0),
                          st.cell_pairs};
    print_numbers("fw row", v, 6);
    ++seed;
  }
}
#elif defined(BENCH_DRAW)
constexpr int32_t kCubes = 20;  // Figure 4's view of 20 x 20 cubes: all of it fits the SRAM map
constexpr uint32_t kEdges = 12 * kCubes * kCubes;
Edge3 edges[kEdges];
alignas(8) uint8_t arena[300 * 1024];   // the CUTSET and CUT's scratch
alignas(8) uint8_t scratch[16 * 1024];  // DRAW's

Status count_span(void* count, const Span&) {
  ++*static_cast<uint64_t*>(count);
  return Status::kOk;
}

void run() {
  CubeArrayParams cubes;
  cubes.cubes = kCubes;
  Status s = cube_array(cubes, edges, kEdges);
  if (!ok(s)) fail("cube array", s);
  CutParams params;
  params.compact_cells = false;  // 4 bytes per (cell, edge) pair, as the other parts
  CutPlan plan;
  s = plan_cut(edges, kEdges, params, &plan);
  if (!ok(s)) fail("plan_cut", s);
  CutSet crossings;
  CutStats cut_stats;
  CutStage cut{&plan, edges, &crossings, &cut_stats};
  StageNeeds needs;
  needs.crossings = 16 * 1024;
  FixedMemory memory{arena, sizeof arena};
  const uint64_t t0 = counter_ticks();
  s = run_sized(cut, memory.memory(), &needs);
  const uint64_t t1 = counter_ticks();
  if (!ok(s)) fail("cut", s);
  if (draw_scratch_bytes(crossings) > sizeof scratch) fail("draw scratch", Status::kBadParameter);
  DrawStats st;
  uint64_t spans = 0;
  bench_span_begin();
  const uint64_t t2 = counter_ticks();
  s = draw(crossings, DrawParams{50, HaloMode::kPaper}, scratch, sizeof scratch,
           SpanSink{count_span, &spans}, &st);
  const uint64_t t3 = counter_ticks();
  bench_span_end();
  if (!ok(s)) fail("draw", s);
  const uint64_t v[] = {crossings.n_crossings, spans, ticks_to_instructions(t1 - t0),
                        ticks_to_instructions(t3 - t2)};
  print_numbers("fw draw", v, 4);
}
#else
constexpr uint32_t kEdges = 9408;  // cube_array_edges of the default 28 x 28
Edge3 edges[kEdges];
alignas(8) uint8_t arena[64 * 1024];
BandConductor conductor;

void run() {
  const CubeArrayParams cubes;
  if (cube_array_edges(cubes) != kEdges) fail("cube array size", Status::kBadParameter);
  Status s = cube_array(cubes, edges, kEdges);
  if (!ok(s)) fail("cube array", s);
  BandSpec spec;
  spec.draw = DrawParams{50, HaloMode::kPaper};  // the demo job's
  conductor.set_clock(&counter_ticks);
  bench_span_begin();  // the whole banded run: the margin pass and the bands' rest too
  s = conductor.begin(spec, array_edge_source(edges, kEdges), arena, sizeof arena);
  if (!ok(s)) fail("bands", s);
  for (;;) {
    const PathPoint* points = nullptr;
    uint32_t n = 0;
    s = conductor.next(&points, &n);
    if (!ok(s)) fail("next", s);
    if (n == 0) break;
  }
  bench_span_end();
  const BandStats& b = conductor.stats();
  const uint64_t v[] = {b.bands,
                        b.pieces,
                        b.records,
                        ticks_to_instructions(b.cut_ticks),
                        ticks_to_instructions(b.draw_ticks),
                        ticks_to_instructions(b.margin_ticks)};
  print_numbers("fw fig4", v, 6);
}
#endif

}  // namespace

int main() {
  counter_start();
  run();
  return 0;
}
