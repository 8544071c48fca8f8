// What an integrator puts in static storage, each object constant-initialised: its initial value
// is fixed at compile time (in .bss or .data), and no constructor runs for it at start-up, so a
// C start-up that skips the static constructors (.init_array) gets it right. GCC's __constinit
// (clang's require_constant_initialization) refuses to compile an object that would need one.
// Built by tests/rules/static_init_test.sh for the host, the M0+ and RV32, which also reads the
// objects' sections; -DPLANT_CONSTINIT and -DPLANT_CONSTRUCTOR are its bad cases.
#include <haloplot/haloplot.h>

#if defined(__clang__)
#define STATIC_INIT [[clang::require_constant_initialization]]
#else
#define STATIC_INIT __constinit
#endif

using namespace haloplot;

namespace static_init {  // named, so the objects below keep external linkage

// A board with what the motion runner needs (hal/include/haloplot/hal/board_hal.h), doing nothing.
struct Board {
  static void init() {}
  static void step_high(uint8_t) {}
  static void steps_low() {}
  static void set_dir(uint8_t, bool) {}
  static void enable_drivers(bool) {}
  static void pen_init() {}
  static void pen_set(bool) {}
  static Status timer_init(TickRate, TimeScale) { return Status::kOk; }
  static void timer_start(uint32_t) {}
  static void timer_next(uint32_t) {}
  static void timer_stop() {}
  static bool timer_chunk_pending() { return false; }
};

// A step HAL that traces, as the example firmware's does.
struct TracingHal {
  uint64_t now = 0;
  TraceEncoder* trace = nullptr;
  void step(uint8_t) {}
  void set_direction(uint8_t, bool) {}
  void pen(bool) {}
};

}  // namespace static_init
using static_init::Board;
using static_init::TracingHal;

// Global, so each keeps its own symbol and section (-fdata-sections) for the test to read.
STATIC_INIT MotionRunner<Board> runner;
STATIC_INIT MotionRunner<Board, TracingHal, TracedQueue<SegmentQueue<64>>> traced_runner;
STATIC_INIT BandConductor conductor;
STATIC_INIT JobSpec job_spec;
STATIC_INIT PreparedJob prepared_job;
STATIC_INIT JobCounters job_counters;
STATIC_INIT BandSpec band_spec;
STATIC_INIT CutPlan cut_plan;
STATIC_INIT CutSet cut_set;
STATIC_INIT CutStats cut_stats;
STATIC_INIT StageNeeds stage_needs;
STATIC_INIT DrawParams draw_params;
STATIC_INIT DrawStats draw_stats;
STATIC_INIT HiddenParams hidden_params;
STATIC_INIT MotionPlanner planner;
STATIC_INIT StepPrep step_prep;
STATIC_INIT SegmentQueue<64> segment_queue;
STATIC_INIT Machine machine;

#if defined(PLANT_CONSTINIT) || defined(PLANT_CONSTRUCTOR)
// The bad case: the motion runner as it was, whose time scale only its constructor set.
namespace {
uint32_t one() {
  static volatile uint32_t v = 1;
  return v;
}
struct PlantedRunner {
  uint32_t time_scale = one();
};
}  // namespace
#if defined(PLANT_CONSTINIT)
STATIC_INIT PlantedRunner planted;  // must not compile
#else
PlantedRunner planted;  // compiles, with a constructor in .init_array: the section check fails
#endif
#endif
