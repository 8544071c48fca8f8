// The step-trace encoder, freestanding so the firmware and the host simulator write the same
// bytes for the same plot (the format is in the README and host_sim/sim/trace.h).
//
// Version 2 records the schedule the step tick runs, not its steps: the segments the tick
// takes from its queue (trace/traced_queue.h hands them over), from which every step's tick
// follows exactly by the tick's own rules (a Q8 running time, Bresenham for the other motor).
// A ramp that goes on joins one `s` line: a cruise at a fractional interval takes a line per
// 50 to 100 events (step prep's flat ramp), where a list of step ticks needs a line every few
// steps (67, 68, 67, ... ticks at 67.5). The HAL's step and pen calls still come here: they
// count the events each line really ran (an abort cuts the last line short) and fold every
// step into a digest on the `end` line, so a replayer can prove that its expansion gives the
// steps the pins saw.
#pragma once
#include <stdint.h>

#include "haloplot/motion/machine.h"
#include "haloplot/motion/step_segment.h"

namespace haloplot {

struct CharSink {
  void (*write)(void* context, const char* text, uint32_t length);
  void* context;
};

// The digest of the steps and pen changes: h = h * kTraceDigestPrime + code + 1 (mod 2^64),
// code = 8 * tick + 2 * motor + backward for a step, 8 * tick + 4 + down for a pen change,
// in the order the tick makes them. One multiply-add a step: cheap enough for a test image.
constexpr uint64_t kTraceDigestPrime = 0x100000001b3ull;
inline uint64_t trace_digest_step(uint64_t h, uint64_t code) {
  return h * kTraceDigestPrime + code + 1;
}

// Text (the default, one line a record) or binary: the same records, each a tag byte and
// LEB128 varints (the README's trace section), about 2.6 times smaller. The controller's test
// images write text; `haloplot sim --binary` writes either from this one encoder.
enum class TraceForm : uint8_t { kText, kBinary };

class TraceEncoder {
 public:
  TraceEncoder(CharSink sink, const Machine& m, TraceForm form = TraceForm::kText);  // header
  void segment(const StepSegment& s);  // the tick took s from its queue
  void step(uint64_t tick, uint8_t motor, bool backward);
  void pen(uint64_t tick, bool down);
  void finish(uint64_t end_tick);  // writes the last line with the events it ran, then "end"

 private:
  // The open `s` line: consecutive segments of one block whose intervals continue one linear
  // ramp (the next starts where the last left off, with the same add) join it.
  struct Line {
    uint64_t count = 0;  // events the segments promise
    uint64_t ran = 0;    // events the HAL reported (dominant steps)
    int64_t interval_q8 = 0, add_q8 = 0;
    bool open = false;
  };
  void close_line();
  void write_block(const StepSegment& b);
  void write_steps(uint64_t count, int64_t delta, int64_t add);
  void write_pen(uint64_t tick, bool down, uint32_t dwell);
  void write_end(uint64_t tick);
  void put_byte(uint8_t b) { sink_.write(sink_.context, reinterpret_cast<const char*>(&b), 1); }
  void put_varint(uint64_t v);  // LEB128: 7 bits a byte, low first, high bit = more follow
  void put(const char* text);
  void put_u64(uint64_t v);
  void put_i64(int64_t v);

  CharSink sink_;
  TraceForm form_;
  Line line_;
  StepSegment block_{};         // the block of the open line (b line), written with it
  bool block_pending_ = false;  // its b line is not written yet
  uint8_t dominant_ = 0;        // the motor whose steps count events
  uint64_t pen_tick_ = 0;       // the HAL's last pen change, written with its dwell
  bool pen_down_ = false;
  int64_t register_q8_ = 0;  // the tick's interval register after the last s line
  uint64_t digest_ = 0;
};

}  // namespace haloplot
