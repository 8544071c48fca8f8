// A bare-metal image that runs CUT from the installed package on a fixed buffer, and plots
// through the installed motion runner on a board of its own (registers at made-up addresses):
// no heap, no startup code beyond an entry point. It is linked, not run: the test checks its
// symbols.
#include <haloplot/controller/motion_runner.h>
#include <haloplot/cut/cut.h>
#include <haloplot/memory/sized_stage.h>
#include <haloplot/scene/cube_array.h>

using namespace haloplot;

namespace {
alignas(8) Edge3 edges[48];
alignas(8) uint8_t arena[16384];

volatile uint32_t& reg(uint32_t address) { return *reinterpret_cast<volatile uint32_t*>(address); }

// A board as hal/include/haloplot/hal/board_hal.h states it: STEP/DIR/ENABLE on a GPIO port, a pen
// pin, a one-shot timer, end stops, a watchdog and a serial link.
struct Board {
  static void init() { reg(0x40000000) = 1; }
  static void step_high(uint8_t m) { reg(0x40000010) = 1u << m; }
  static void steps_low() { reg(0x40000014) = 3; }
  static void set_dir(uint8_t m, bool b) { reg(b ? 0x40000010 : 0x40000014) = 4u << m; }
  static void enable_drivers(bool on) { reg(on ? 0x40000010 : 0x40000014) = 16; }
  static void pen_init() {}
  static void pen_set(bool down) { reg(down ? 0x40000010 : 0x40000014) = 32; }
  static Status timer_init(TickRate, TimeScale) { return Status::kOk; }
  static void timer_start(uint32_t d) { reg(0x40001000) = d; }
  static void timer_next(uint32_t d) { reg(0x40001000) = d; }
  static void timer_stop() { reg(0x40001004) = 0; }
  static bool timer_chunk_pending() { return false; }
  static void serial_init(uint32_t) {}
  static bool serial_read(uint8_t*) { return false; }
  static void serial_write(const uint8_t*, uint32_t) {}
  static uint32_t serial_overruns() { return 0; }
  static constexpr uint32_t kSerialBaud = 115200;
  static void limits_init(void (*)(uint8_t)) {}
  static void watchdog_start() {}
  static void watchdog_kick() {}
};
static_assert(hal::check_board<Board>(), "the consumer's board");

MotionRunner<Board> motion;
}  // namespace

template class haloplot::MotionRunner<Board>;  // every member compiles from the package

extern "C" void step_timer_irq() { motion.on_timer(); }

int main() {
  CubeArrayParams p;
  p.cubes = 2;
  if (!ok(cube_array(p, edges, 48))) return 1;
  CutPlan plan;
  if (!ok(plan_cut(edges, 48, CutParams{}, &plan))) return 1;
  CutSet set;
  CutStats stats;
  CutStage stage{&plan, edges, &set, &stats};
  StageNeeds needs;
  needs.crossings = 64;
  FixedMemory memory{arena, sizeof arena};
  if (!ok(run_sized(stage, memory.memory(), &needs))) return -1;
  // Every edge whole, plotted through the runner: the interrupt above steps it.
  JobSpec job;
  job.drawing = DrawingEffect::kAllEdges;
  PreparedJob prepared;
  JobCounters counters;
  if (!ok(job_prepare(job, Edges{edges, 48}, 0, arena, sizeof arena, &prepared, &counters)))
    return -1;
  if (!ok(motion.begin(job, prepared))) return -1;
  while (motion.running()) {  // no vector table here: the timer's pending flag is polled
    motion.service();
    if (reg(0x40001008) != 0) step_timer_irq();
  }
  return ok(motion.result()) ? int(set.n_crossings) : -1;
}

extern "C" [[noreturn]] void _start() {
  main();
  for (;;) {
  }
}
