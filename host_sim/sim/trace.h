// Step traces: what the motors and the pen did, as the schedule the step tick ran (version 2;
// the rules that expand it into steps are in the README's trace section):
//
//   haloplot-trace 2
//   tick_hz 1000000
//   kinematics corexy            cartesian | corexy
//   steps 1/1                    motor steps per plot step
//   backlash 0 0                 slack per motor, in motor steps
//   b DOM MAJOR MINOR DIRS       a move: Bresenham of MINOR other-motor steps in MAJOR events
//   s COUNT DELTA ADD            COUNT events: the interval register (Q8 ticks) changes by
//                                DELTA, then grows by ADD after each event
//   p TICK down|up DWELL         a pen change, then DWELL ticks without events
//   end TICK DIGEST              the last event, and a digest of every step and pen change
//
// Version 1 (m MOTOR T0 COUNT DT DDT DIR lines, one per run of one motor's steps) still reads.
// The same job always gives the same bytes.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "haloplot/motion/machine.h"
#include "haloplot/trace/trace_encoder.h"
#include "io/input_error.h"

namespace haloplot::host {

struct StepEvent {
  uint64_t tick;
  uint8_t motor;  // 0, 1; 2 = pen
  bool flag;      // motor: backward; pen: down
};

// Writes a trace to a stream through the core's encoder (the firmware uses the same one).
class TraceWriter {
 public:
  TraceWriter(std::ostream& out, const Machine& m, TraceForm form = TraceForm::kText);
  void step(uint64_t tick, uint8_t motor, bool backward) { encoder_.step(tick, motor, backward); }
  void pen(uint64_t tick, bool down) { encoder_.pen(tick, down); }
  void finish(uint64_t end_tick) { encoder_.finish(end_tick); }
  TraceEncoder* encoder() { return &encoder_; }

 private:
  static void write(void* context, const char* text, uint32_t length);
  TraceEncoder encoder_;
};

struct Trace {
  Machine machine;                // tick_hz, kinematics, steps, backlash
  std::vector<StepEvent> events;  // every step and pen change, in time order
  uint64_t end_tick = 0;
};

// Reads a trace; more than max_events steps and pen changes is an error (a damaged count in a
// run line must not exhaust memory: 16 bytes an event).
InputError read_trace(std::istream& in, const std::string& name, Trace* out,
                      uint64_t max_events = 200000000);

}  // namespace haloplot::host
