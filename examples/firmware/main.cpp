// A plotter firmware built on haloplot's installed package: a 2 x 2 cube array plotted haloed
// on a CoreXY machine by haloplot::MotionRunner, stepped from the timer's interrupt. Under
// QEMU it also writes its step trace over semihosting (the trace format of docs/formats.md),
// which `haloplot sim` of the same job (job.job beside this file) writes byte for byte.
#include <haloplot/controller/motion_runner.h>
#include <haloplot/job/job.h>
#include <haloplot/scene/cube_array.h>
#include <haloplot/trace/traced_queue.h>

#include "board.h"
#include "semihosting.h"

using namespace haloplot;

namespace {

example::Console console;

// The step HAL: the board's pins, and each event into the trace. `now` is the plot's time in
// ticks, which the runner keeps (the sum of the delays the plan asked for).
struct TracingHal {
  uint64_t now = 0;
  bool backward[2] = {false, false};
  TraceEncoder* trace = nullptr;
  void set_direction(uint8_t m, bool b) {
    backward[m] = b;
    example::Mps2Board::set_dir(m, b);
  }
  void step(uint8_t m) {
    example::Mps2Board::step_high(m);
    if (trace != nullptr) trace->step(now, m, backward[m]);
  }
  void pen(bool down) {
    example::Mps2Board::pen_set(down);
    if (trace != nullptr) trace->pen(now, down);
  }
};

// The runner's queue shows the trace each segment as the step tick takes it.
using Queue = TracedQueue<SegmentQueue<64>>;
MotionRunner<example::Mps2Board, TracingHal, Queue> motion;

// The job: what job.job says, key by key.
JobSpec the_job() {
  JobSpec spec;
  spec.drawing = DrawingEffect::kHaloed;          // drawing haloed
  spec.draw.halo = 50;                            // halo 50
  spec.draw.mode = HaloMode::kPaper;              // halo-mode paper
  spec.machine.kinematics = Kinematics::kCoreXY;  // kinematics corexy
  // steps 1/16: a motor step per 16 plot steps (0.2 mm), coarse so that the run under QEMU,
  // where each step interrupt costs time, stays short.
  spec.machine.steps_num = 1;
  spec.machine.steps_den = 16;
  return spec;
}

constexpr uint32_t kCubes = 2, kEdges = 12 * kCubes * kCubes;
Edge3 edges[kEdges];
alignas(8) uint8_t job_memory[32 * 1024];  // CUT, DRAW and the pen path, all in here

void print(const char* key, uint32_t value) {
  console.print("example ");
  console.print(key);
  console.print("=");
  console.print(value);
  console.print("\n");
}

[[noreturn]] void fail(const char* what, Status s) {
  console.print("example: ");
  console.print(what);
  console.print(" failed: ");
  console.print(status_name(s));
  console.print("\n");
  console.flush();
  example::semihost_exit(1);
}

}  // namespace

// The step clock's interrupt: acknowledge it (the line stays high until cleared), then step.
extern "C" void timer0_irq_handler() {
  example::reg(example::kTimerIntClear) = 1;
  motion.on_timer();
}

int main() {
  example::Mps2Board::init();
  example::Mps2Board::pen_init();

  // The scene (the demo's cubes, projected on the chip) and the job's strokes.
  CubeArrayParams scene;
  scene.cubes = kCubes;
  Status s = cube_array(scene, edges, kEdges);
  if (!ok(s)) fail("cube_array", s);
  const JobSpec spec = the_job();
  PreparedJob job;
  JobCounters counters;
  // The records CUT will store, counted first in the same memory (28 for these cubes): a guess
  // costs 12 bytes a record too many, or a kCrossingCapacity.
  uint32_t crossings = 0;
  s = job_crossings(spec, Edges{edges, kEdges}, job_memory, sizeof job_memory, &crossings);
  if (!ok(s)) fail("job_crossings", s);
  s = job_prepare(spec, Edges{edges, kEdges}, crossings, job_memory, sizeof job_memory, &job,
                  &counters);
  if (!ok(s)) fail("job_prepare", s);
  print("crossing_capacity", crossings);

  // The trace's header now, its events from the interrupt, its end after the plot.
  TraceEncoder trace(
      CharSink{[](void*, const char* text, uint32_t n) { console.write(text, n); }, nullptr},
      spec.machine);
  motion.hal().trace = &trace;
  motion.queue().set_encoder(&trace);

  s = motion.begin(spec, job);
  if (!ok(s)) fail("begin", s);
  while (motion.running()) {
    motion.service();  // refill the step queue; restart the timer if it ran dry
    // Sleep until the next interrupt. Interrupts are masked across the check, so one that
    // stops the timer in between still ends the WFI (and runs at cpsie).
    __asm__ volatile("cpsid i" ::: "memory");
    if (motion.stepping()) __asm__ volatile("wfi");
    __asm__ volatile("cpsie i" ::: "memory");
  }
  trace.finish(motion.hal().now);
  if (!ok(motion.result())) fail("the plot", motion.result());

  print("step_events", motion.events());
  print("underruns", motion.underruns());
  print("cpacr", example::reg(0xE000ED88u));  // 0: the FPU was never switched on
  console.flush();
  example::semihost_exit(0);
}
