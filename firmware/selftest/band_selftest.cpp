// On-target self-test of the band conductor, booted under QEMU by the CTest `firmware_bands`:
// the README's demo, the HALO paper's Figure 4 (28 x 28 cubes, 9408 edges, halo 50), plotted
// haloed on the demo's CoreXY machine in a 64 KB job arena. The scene is never stored: the
// cube array is generated edge by edge (scene/cube_array.h) each time a band reads it. The
// step trace (about 46 MB of text) is not sent: its CRC-32 and length are, and the host test
// compares them with `haloplot sim` of the demo job with `arena 65536`. Instruction counts
// come from the TIM5 counter under -icount (one count per instruction).
#include "haloplot/band/conductor.h"
#include "haloplot/job/job.h"
#include "haloplot/motion/planner.h"
#include "haloplot/motion/step_engine.h"
#include "haloplot/motion/step_prep.h"
#include "haloplot/motion/virtual_run.h"
#include "haloplot/scene/cube_array.h"
#include "haloplot/trace/traced_queue.h"
#include "platform/console.h"
#include "platform/instruction_counter.h"
#include "platform/semihosting.h"
#include "platform/trace_digest.h"
#include "selftest_support.h"

using namespace haloplot;
using namespace haloplot::fw;

extern "C" uint32_t stack_unused_bytes();

namespace {

constexpr size_t kArenaBytes = 64 * 1024;
alignas(8) uint8_t arena[kArenaBytes];
Console console;
CubeArrayEdges cubes;

[[noreturn]] void fail(const char* what, Status s) { selftest_fail(console, what, s); }

TracedQueue<SegmentQueue<64>> queue;

Status read_cubes(void*, uint32_t first, uint32_t count, Edge3* out) {
  for (uint32_t i = 0; i < count; ++i) out[i] = cubes.edge(first + i);
  return Status::kOk;
}

}  // namespace

int main() {
  counter_start();
  Status s = cubes.fit(CubeArrayParams{});
  if (!ok(s)) fail("cube array", s);
  EdgeSource source;
  source.n = cubes.size();
  source.read = &read_cubes;

  // The demo job (scenes/demo.job): halo 50, the paper's gap, CoreXY, acceleration and pen servo.
  BandSpec spec;
  spec.draw = DrawParams{50, HaloMode::kPaper};
  JobSpec job;  // the demo job's machine and effects (finish home, the default)
  job.machine.kinematics = Kinematics::kCoreXY;
  const Machine& machine = job.machine;
  const PlotterEffects& effects = job.effects;

  BandConductor conductor;
  conductor.set_clock(&counter_ticks);
  s = conductor.begin(spec, source, arena, sizeof arena);
  if (!ok(s)) fail("bands", s);
  alignas(8) static uint8_t planner_ws[MotionPlanner::workspace_bytes(PlotterEffects{})];
  MotionPlanner planner;
  PreparedJob streamed;
  streamed.feed = PointFeed{&BandConductor::feed, &conductor};
  s = init_planner(&planner, job, streamed, planner_ws, sizeof planner_ws);
  if (!ok(s)) fail("planner", s);
  StepPrep prep;
  s = prep.init(machine, effects);
  if (!ok(s)) fail("prep", s);
  TraceDigest digest;
  TraceEncoder trace(digest.sink(), machine);
  TraceHal hal;
  hal.trace = &trace;
  queue.set_encoder(&trace);
  StepEngine<TraceHal, TracedQueue<SegmentQueue<64>>> engine(hal, queue);
  const uint64_t t0 = counter_ticks();
  s = run_virtual(planner, prep, queue, hal, engine);
  const uint64_t t1 = counter_ticks();
  if (!ok(s)) fail("plot", s);
  trace.finish(hal.now);

  const BandStats& b = conductor.stats();
  console.stat("edges", source.n);
  console.stat("arena_bytes", kArenaBytes);
  console.stat("bands", b.bands);
  console.stat("margin_bands", b.margin_bands);
  console.stat("splits", b.splits);
  console.stat("margin", uint64_t(b.margin));
  console.stat("peak_bytes", b.peak_bytes);
  console.stat("most_edges", b.most_edges);
  console.stat("pieces", b.pieces);
  console.stat("records", b.records);
  console.stat("cut_instructions", ticks_to_instructions(b.cut_ticks));
  console.stat("draw_instructions", ticks_to_instructions(b.draw_ticks));
  console.stat("band_other_instructions", ticks_to_instructions(b.other_ticks));
  console.stat("margin_pass_instructions", ticks_to_instructions(b.margin_ticks));
  console.stat("wasted_attempt_instructions", ticks_to_instructions(b.wasted_ticks));
  console.stat("cut_runs", b.cut_runs);
  console.stat("plot_instructions", ticks_to_instructions(t1 - t0));
  console.stat("step_events", engine.events());
  console.stat("trace_bytes", digest.bytes);
  console.stat("trace_crc32", digest.crc);
  console.stat("stack_used_bytes", 16 * 1024 - stack_unused_bytes());
  console.flush();
  semihost_exit(0);
}
