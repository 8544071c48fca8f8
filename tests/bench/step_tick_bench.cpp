// Benchmark (not a test): instructions per step event in the shared step tick. Run it under
// callgrind (tools/bench_step_tick.sh): only isr_tick() is collected, and the count divided by
// the events it made is the cost of one event, as the timer interrupt would pay it.
#include <cstdio>

#include "haloplot/motion/step_engine.h"
#include "haloplot/motion/step_segment.h"
#include "selftest/tick_workload.h"

using namespace haloplot;

// A HAL like the firmware's: each call is one store to a GPIO register.
struct GpioHal {
  volatile uint32_t bsrr = 0;
  void step(uint8_t m) { bsrr = 1u << m; }
  void set_direction(uint8_t m, bool back) { bsrr = back ? (1u << (m + 16)) : (1u << (m + 8)); }
  void pen(bool down) { bsrr = down ? 1u << 4 : 1u << 20; }
};

static GpioHal gpio;
static SegmentQueue<64> segments;
static StepEngine<GpioHal, SegmentQueue<64>> engine(gpio, segments);

// The ISR body: what the timer interrupt runs for one event.
__attribute__((noinline)) uint32_t isr_tick() { return engine.tick(); }

int main() {
  // The shared workload (tick_workload.h), also timed on the Cortex-M4.
  uint64_t events_wanted = 2000000, made = 0;
  bool first = true;
  uint32_t delay = 0;
  while (made < events_wanted) {
    bench::fill_tick_workload(segments, &first);
    if (delay == 0) delay = engine.start();
    delay = isr_tick();
    made = engine.events();
  }
  std::printf("events=%llu\n", (unsigned long long)engine.events());
  return delay == 0xffffffffu;  // keep the result alive
}
