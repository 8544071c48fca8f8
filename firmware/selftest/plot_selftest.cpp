// On-target self-test, booted under QEMU by the CTest `firmware_plot`: builds a small cube
// array on the chip, plots it haloed on a CoreXY machine with the shared core (CUT, DRAW,
// path planning, planner, step prep, the step tick) and streams the step trace over
// semihosting. The host compares the trace byte for byte with `haloplot sim` on the same job,
// and reads the instruction counts this image measures under -icount (1 instruction = 1 ns
// of virtual time, read with SYS_ELAPSED).
#include "haloplot/geometry/units.h"
#include "haloplot/haloplot.h"
#include "haloplot/job/job.h"
#include "haloplot/motion/planner.h"
#include "haloplot/motion/step_engine.h"
#include "haloplot/motion/step_prep.h"
#include "haloplot/motion/virtual_run.h"
#include "haloplot/scene/cube_array.h"
#include "haloplot/solid/hidden_lines.h"
#include "haloplot/surface/hidden_surface.h"
#include "haloplot/trace/traced_queue.h"
#include "haloplot/view/projection.h"
#include "platform/console.h"
#include "platform/instruction_counter.h"
#include "platform/semihosting.h"
#include "selftest/tick_workload.h"
#include "selftest_support.h"

using namespace haloplot;
using namespace haloplot::fw;

extern "C" uint32_t stack_unused_bytes();

namespace {

constexpr int32_t kCubes = 6;
constexpr uint32_t kEdges = 12 * kCubes * kCubes;
constexpr uint32_t kCrossingCapacity = kEdges + 128;  // this scene has 412 crossings

Edge3 edges[kEdges];
alignas(8) uint8_t job_buffer[84 * 1024];

// Output through semihosting in 1 KB chunks: each call traps to the host, so batch them.
Console console;
void stat(const char* key, uint64_t value) { console.stat(key, value); }

[[noreturn]] void fail(const char* what, Status s) { selftest_fail(console, what, s); }

// A HAL like a GPIO port: one store per call. For the step-event instruction count.
struct GpioHal {
  uint64_t now = 0;
  volatile uint32_t bsrr = 0;
  void set_direction(uint8_t m, bool b) { bsrr = b ? (1u << (m + 16)) : (1u << (m + 8)); }
  void step(uint8_t m) { bsrr = 1u << m; }
  void pen(bool down) { bsrr = down ? 1u << 4 : 1u << 20; }
};

TracedQueue<SegmentQueue<64>> queue;

// Hidden lines of 3 x 3 solid cubes (the demo's geometry, view 30,40) on the chip: the whole
// core/solid run in the job buffer. The host test compares the visible pieces with
// `haloplot plot` of the same model.
struct PieceCount {
  uint32_t visible = 0, hidden = 0, hatch = 0;  // hatch: visible hatch pieces (strokes)
  static Status piece(void* ctx, const HiddenPiece& p) {
    auto* self = static_cast<PieceCount*>(ctx);
    if (p.hatch)
      self->hatch += p.hidden ? 0 : 1;
    else
      ++(p.hidden ? self->hidden : self->visible);
    return Status::kOk;
  }
};

// The cubes projected in units of 2^-s steps, and their hidden-line run's instruction count
// (with the intersection lines a job draws by default when `intersections`, and hatching
// when `hatch` is not null).
uint64_t hidden_lines_run(const Point3* world, uint32_t nv, Point3* screen, int32_t substep_bits,
                          const SolidInput& in, PieceCount* count, HiddenReport* report,
                          bool intersections = false, const HatchParams* hatch = nullptr) {
  View view;
  view.substep_bits = substep_bits;
  const Status ps = project_points(view, world, nv, screen);
  if (!ok(ps)) fail("solid projection", ps);
  HiddenParams hp;
  hp.crossing_capacity = 600;
  hp.incidence_capacity = 64;
  hp.outline = true;
  hp.intersections = intersections;
  hp.hatch = hatch != nullptr;
  if (hatch != nullptr) hp.hatch_params = *hatch;
  const uint64_t a = counter_ticks();
  const Status hs = hidden_lines(in, hp, job_buffer, sizeof job_buffer,
                                 HiddenSink{nullptr, &PieceCount::piece, nullptr, count}, report);
  const uint64_t b = counter_ticks();
  if (!ok(hs)) fail("hidden lines", hs);
  return ticks_to_instructions(b - a);
}

// 3 x 3 solid cubes (the demo's geometry, view 30,40): each cube's 8 corners in world, its 12
// edges as corner index pairs, its 6 faces as two triangles each. The input's vertices are
// `screen`, where each hidden-line run projects the corners first.
struct SolidCubes {
  Point3* world;
  Point3* screen;
  uint32_t nv;
  SolidInput in;
};

SolidCubes solid_cubes() {
  constexpr int32_t n = 3;
  static Point3 world[8 * n * n], screen[8 * n * n];
  static uint32_t pairs[2 * 12 * n * n];
  static Triangle tris[12 * n * n];
  static const int kQuads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                   {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  uint32_t nv = 0, ne = 0, nt = 0;
  for (int32_t i = 0; i < n; ++i)
    for (int32_t j = 0; j < n; ++j) {
      const uint32_t base = nv;
      for (int k = 0; k < 8; ++k)
        world[nv++] =
            Point3{i * 125 + (k & 1) * 100, j * 125 + ((k >> 1) & 1) * 100, ((k >> 2) & 1) * 100};
      for (int q = 0; q < 6; ++q) {
        const uint32_t v0 = base + uint32_t(kQuads[q][0]), v1 = base + uint32_t(kQuads[q][1]),
                       v2 = base + uint32_t(kQuads[q][2]), v3 = base + uint32_t(kQuads[q][3]);
        const uint32_t poly = nt / 2;
        tris[nt++] = Triangle{{v0, v1, v2}, poly};
        tris[nt++] = Triangle{{v0, v2, v3}, poly};
      }
      // The 12 edges: corner pairs that differ in one bit.
      for (uint32_t a = 0; a < 8; ++a)
        for (uint32_t bit = 1; bit < 8; bit <<= 1)
          if (!(a & bit)) {
            pairs[ne++] = base + a;
            pairs[ne++] = base + (a | bit);
          }
    }
  SolidCubes c{world, screen, nv, SolidInput{}};
  c.in.vertices = screen;
  c.in.n_vertices = nv;
  c.in.edge_pairs = pairs;
  c.in.n_edges = ne / 2;
  c.in.triangles = tris;
  c.in.n_triangles = nt;
  return c;
}

// The hatching of the cubes (3 mm at 80 steps/mm, 45 degrees turning 90 across the depth
// range) as a job draws it, in the hidden-line run: the host test counts `haloplot plot
// --hatch`'s strokes for the same model.
void hatch_lines_on_chip(const SolidCubes& c, const HatchParams& hatch) {
  PieceCount hatched;
  HiddenReport hatch_report;
  stat("hidden_lines_instructions_with_hatching",
       hidden_lines_run(c.world, c.nv, c.screen, kDefaultSubstepBits, c.in, &hatched, &hatch_report,
                        false, &hatch));
  stat("solid_hatch_strokes", hatched.hatch);
}

// Franklin's hidden surfaces (steps 10-11: the regions, each hatched as the face it shows),
// the reference the hatch lines are tested against on the host, run on the chip too.
void hidden_surfaces_on_chip(const SolidInput& in, const HatchParams& hatch) {
  uint32_t strokes = 0;
  HiddenSurfaceStats hst;
  const uint64_t c = counter_ticks();
  const Status ss = hidden_surface(in, FranklinParams{}, hatch, 600, 64, 4 * in.n_edges + 64,
                                   job_buffer, sizeof job_buffer, FranklinSink{nullptr, nullptr},
                                   HatchSink{[](void* ctx, const HatchStroke&) {
                                               ++*static_cast<uint32_t*>(ctx);
                                               return Status::kOk;
                                             },
                                             &strokes},
                                   &hst);
  const uint64_t d = counter_ticks();
  if (!ok(ss)) fail("hidden surfaces", ss);
  stat("solid_regions_cycles", hst.regions.cycles);
  stat("solid_region_hatch_strokes", strokes);
  stat("hidden_surface_instructions", ticks_to_instructions(d - c));
}

void hidden_lines_on_chip() {
  const SolidCubes c = solid_cubes();
  // Whole steps first, for the resolution axis's cost on the chip (docs/reports/accuracy.md); then
  // the host's default units, which the host test compares with `haloplot plot`.
  PieceCount whole_count;
  HiddenReport whole_report;
  stat("hidden_lines_instructions_whole_steps",
       hidden_lines_run(c.world, c.nv, c.screen, 0, c.in, &whole_count, &whole_report));
  PieceCount count;
  HiddenReport report;
  const uint64_t instructions =
      hidden_lines_run(c.world, c.nv, c.screen, kDefaultSubstepBits, c.in, &count, &report);
  stat("solid_edges", c.in.n_edges);
  stat("solid_triangles", c.in.n_triangles);
  stat("solid_crossings", report.cut.crossings);
  stat("solid_visible_pieces", count.visible);
  stat("solid_hidden_pieces", count.hidden);
  stat("solid_used_qi", report.used_qi ? 1 : 0);
  stat("solid_bytes_used", report.bytes_used);
  stat("hidden_lines_instructions", instructions);
  PieceCount with_lines;
  HiddenReport lines_report;
  stat("hidden_lines_instructions_with_intersections",
       hidden_lines_run(c.world, c.nv, c.screen, kDefaultSubstepBits, c.in, &with_lines,
                        &lines_report, true));
  stat("solid_intersection_pairs", lines_report.intersections.pairs);
  HatchParams hatch;
  hatch.spacing = steps_to_units(240, kDefaultSubstepBits);
  hatch.min_length = steps_to_units(1, kDefaultSubstepBits);
  hatch.angle_mdeg = 45000;
  hatch.mdeg_per_depth = 90000;
  hatch_lines_on_chip(c, hatch);
  hidden_surfaces_on_chip(c.in, hatch);
}

// A loop of exactly 2 instructions per pass (subs, bne), 2,000,000 passes: what the counter
// reads for a known count.
void calibrate() {
  const uint64_t a = counter_ticks();
  uint32_t n = 2000000;
  __asm__ volatile("1: subs %0, %0, #1\n bne 1b" : "+r"(n) : : "cc");
  stat("calibration_4000000_instructions", ticks_to_instructions(counter_ticks() - a));
}

// Every DRAW precision mode (draw/precision.h) on the same CUTSET: what each costs on the
// Cortex-M4, where a 64-bit division is a library call (docs/reports/accuracy.md quotes these).
void draw_modes(const CutSet& set, uint8_t* scratch, size_t scratch_size, const SpanSink& count) {
  auto mode = [&](const char* name, auto tag) {
    using P = decltype(tag);
    const uint64_t a = counter_ticks();
    const Status ms =
        draw_with<P>(set, DrawParams{50, HaloMode::kPaper}, scratch, scratch_size, count, nullptr);
    const uint64_t b = counter_ticks();
    if (!ok(ms)) fail(name, ms);
    stat(name, ticks_to_instructions(b - a));
  };
  mode("draw_mode_exact_q32", DrawPrecision<SqrtExact, PositionBits<32>>{});
  mode("draw_mode_newton_q32", DrawPrecision<SqrtNewton, PositionBits<32>>{});
  mode("draw_mode_table_q32", DrawPrecision<SqrtTable, PositionBits<32>>{});
  mode("draw_mode_exact_q16", DrawPrecision<SqrtExact, PositionBits<16>>{});
  mode("draw_mode_newton_q16", DrawPrecision<SqrtNewton, PositionBits<16>>{});
  mode("draw_mode_table_q16", DrawPrecision<SqrtTable, PositionBits<16>>{});
}

// CUT and DRAW alone, for their instruction counts, then DRAW in every precision mode.
void cut_and_draw_alone() {
  CutPlan plan;
  CutParams tight;
  tight.compact_cells = false;  // 4 bytes per (cell, edge) pair: RAM is tight here
  Status s = plan_cut(edges, kEdges, tight, &plan);
  if (!ok(s)) fail("plan_cut", s);
  // Borrow the job buffer (the job has not started): CUTSET first, then CUT's scratch,
  // which DRAW reuses once CUT is done.
  uint8_t* cutset_mem = job_buffer;
  const size_t cutset_size = (cutset_bytes(kEdges, kCrossingCapacity) + 7) & ~size_t{7};
  uint8_t* scratch = job_buffer + cutset_size;
  const size_t scratch_size = sizeof job_buffer - cutset_size;
  CutSet set;
  CutStats st;
  const uint64_t t0 = counter_ticks();
  s = run_cut(plan, edges, scratch, scratch_size, cutset_mem, cutset_size, &set, &st);
  const uint64_t t1 = counter_ticks();
  if (!ok(s)) fail("run_cut", s);
  uint64_t spans = 0;
  const SpanSink count{[](void* c, const Span&) {
                         ++*static_cast<uint64_t*>(c);
                         return Status::kOk;
                       },
                       &spans};
  s = draw(set, DrawParams{50, HaloMode::kPaper}, scratch, scratch_size, count, nullptr);
  const uint64_t t2 = counter_ticks();
  if (!ok(s)) fail("draw", s);
  stat("edges", kEdges);
  stat("crossings", set.n_crossings);
  stat("spans", spans);
  stat("cut_scratch_bytes", plan.scratch_bytes);
  stat("cut_instructions", ticks_to_instructions(t1 - t0));
  stat("draw_instructions", ticks_to_instructions(t2 - t1));
  draw_modes(set, scratch, scratch_size, count);
}

// The view transform, both fixed-point modes, on the cube array's 288 world corners.
void projection_on_chip() {
  static Point3 world[8 * kCubes * kCubes], screen[8 * kCubes * kCubes];
  uint32_t nv = 0;
  for (int32_t i = 0; i < kCubes; ++i)
    for (int32_t j = 0; j < kCubes; ++j)
      for (int k = 0; k < 8; ++k)
        world[nv++] =
            Point3{i * 125 + (k & 1) * 100, j * 125 + ((k >> 1) & 1) * 100, ((k >> 2) & 1) * 100};
  const View view;
  const uint64_t a = counter_ticks();
  Status ps = project_points_with<16>(view, world, nv, screen);
  const uint64_t b = counter_ticks();
  if (ok(ps)) ps = project_points_with<30>(view, world, nv, screen);
  const uint64_t c = counter_ticks();
  if (!ok(ps)) fail("projection", ps);
  stat("project_q16_instructions_per_vertex", ticks_to_instructions(b - a) / nv);
  stat("project_q30_instructions_per_vertex", ticks_to_instructions(c - b) / nv);
}

// The plot: the same job as scenes/ of the host test (see tests/firmware/), prepared in the
// job buffer and run through the planner, step prep and the step engine, its trace streamed.
void plot_on_chip() {
  JobSpec spec;
  spec.drawing = DrawingEffect::kHaloed;
  spec.draw = DrawParams{50, HaloMode::kPaper};
  spec.machine.kinematics = Kinematics::kCoreXY;
  spec.cut.compact_cells = false;  // the same crossings, a quarter of the cell-list bytes
  JobBytes bytes;
  Status s = job_bytes(spec, Edges{edges, kEdges}, kCrossingCapacity, &bytes);
  if (!ok(s)) fail("job_bytes", s);
  stat("job_bytes", bytes.total());
  PreparedJob job;
  JobCounters counters;
  const uint64_t t3 = counter_ticks();
  s = job_prepare(spec, Edges{edges, kEdges}, kCrossingCapacity, job_buffer, sizeof job_buffer,
                  &job, &counters);
  const uint64_t t4 = counter_ticks();
  if (!ok(s)) fail("job_prepare", s);
  stat("prepare_instructions", ticks_to_instructions(t4 - t3));

  alignas(8) static uint8_t planner_ws[MotionPlanner::workspace_bytes(PlotterEffects{})];
  MotionPlanner planner;
  s = init_planner(&planner, spec, job, planner_ws, sizeof planner_ws);
  if (!ok(s)) fail("planner", s);
  StepPrep prep;
  s = prep.init(spec.machine, spec.effects);
  if (!ok(s)) fail("prep", s);
  TraceEncoder trace(console.sink(), spec.machine);
  TraceHal hal;
  hal.trace = &trace;
  queue.set_encoder(&trace);
  StepEngine<TraceHal, TracedQueue<SegmentQueue<64>>> engine(hal, queue);
  const uint64_t t5 = counter_ticks();
  s = run_virtual(planner, prep, queue, hal, engine);
  const uint64_t t6 = counter_ticks();
  if (!ok(s)) fail("motion", s);
  trace.finish(hal.now);
  stat("step_events", engine.events());
  stat("motion_instructions_with_trace", ticks_to_instructions(t6 - t5));
}

// One step event alone: the host benchmark's workload (firmware/selftest/tick_workload.h) on a
// GPIO-like HAL.
void step_event_alone() {
  GpioHal gpio;
  SegmentQueue<64> q;
  StepEngine<GpioHal, SegmentQueue<64>> e(gpio, q);
  uint64_t spent = 0;
  uint32_t delay = 0;
  bool first = true;
  while (e.events() < 200000) {
    bench::fill_tick_workload(q, &first);
    if (delay == 0) delay = e.start();
    const uint64_t a = counter_ticks();
    for (int k = 0; k < 800; ++k) delay = e.tick();  // 50 segments: the queue holds 64
    spent += counter_ticks() - a;
  }
  stat("tick_events", e.events());
  stat("tick_instructions_x100_per_event", ticks_to_instructions(spent * 100) / e.events());
}

}  // namespace

int main() {
  counter_start();
  calibrate();
  CubeArrayParams cp;
  cp.cubes = kCubes;
  const Status s = cube_array(cp, edges, kEdges);
  if (!ok(s)) fail("cube array", s);
  cut_and_draw_alone();
  projection_on_chip();
  hidden_lines_on_chip();
  plot_on_chip();
  step_event_alone();
  stat("stack_used_bytes", 16 * 1024 - stack_unused_bytes());
  console.flush();
  semihost_exit(0);
}
