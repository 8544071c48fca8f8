// The step tick: the only code on the step path. The firmware's timer interrupt and the host
// simulator call the same tick(). It takes one step event from the current segment, runs
// Bresenham for the other motor, and returns how many ticks until the next event, so the
// timer is set once per event (no fixed-rate polling, no idle interrupts).
//
// No division, no floating point, no virtual call, no 64-bit arithmetic: the HAL is a template
// parameter, so each pin write inlines. Events fire at the floor of the exact running sum of
// the Q8 intervals: rounding never accumulates.
//
// Hal must provide what hal/include/haloplot/hal/plotter_hal.h names: void step(uint8_t motor);
// void set_direction(uint8_t motor, bool backward); void pen(bool down). It is checked here,
// where every HAL is plugged in, and a missing member fails the build with its name.
#pragma once
#include <stdint.h>

#include "haloplot/hal/plotter_hal.h"
#include "haloplot/motion/step_segment.h"

namespace haloplot {

template <typename Hal, typename Queue>
class StepEngine {
  static_assert(hal::check_plotter_hal<Hal>(),
                "the step engine's HAL (hal/include/haloplot/hal/plotter_hal.h)");

 public:
  // Assignable: a motion runner starts each plot with a fresh engine on the same HAL and queue.
  constexpr StepEngine(Hal& hal, Queue& queue) : hal_(&hal), queue_(&queue) {}
  // Unbound and all zero (a motion runner's member in .bss, constant-initialised): assign a
  // bound engine before start() or tick().
  constexpr StepEngine() : other_(0), step_{0, 0}, major_(0) {}

  // Begin, or resume after the queue ran dry: returns the delay to the first event (0: nothing
  // to do). The time base continues from the last event.
  uint32_t start() {
    pending_ = false;
    return advance();
  }

  // The timer fired: do the due event, return ticks until the next one (0: queue empty).
  uint32_t tick() {
    if (pending_) {
      hal_->step(dominant_);
      position_[dominant_] += step_[dominant_];
      error_ += minor_;
      if (error_ >= major_) {  // Bresenham: the other motor steps when its error overflows
        error_ -= major_;
        hal_->step(other_);
        position_[other_] += step_[other_];
      }
      ++events_;
    }
    if (left_ > 0) {  // the common case, all in 32 bits
      --left_;
      return next_delay();
    }
    return advance();
  }

  int32_t position(uint8_t motor) const { return position_[motor]; }
  uint32_t events() const { return events_; }
  // Events of the segment in hand not yet made (the pending one included).
  uint32_t remaining() const { return left_ + (pending_ ? 1u : 0u); }

 private:
  // Time is the running sum of the Q8 intervals; the timer needs only whole ticks between
  // events, floor(t + i) - floor(t) = (frac(t) + i) >> 8, so a byte of fraction carries the
  // rest. No 64-bit arithmetic, no division: the events fire at the floor of the exact sum.
  uint32_t next_delay() {
    const uint32_t sum = fraction_ + static_cast<uint32_t>(interval_q8_);  // < 2^31 + 2^8
    fraction_ = sum & 0xffu;
    interval_q8_ += add_q8_;
    pending_ = true;
    return sum >> 8;
  }

  // Load the next segment: steps, or a pen change (done at once; its dwell is the delay).
  uint32_t advance() {
    for (;;) {
      if (left_ > 0) {
        --left_;
        return next_delay();
      }
      if (queue_->empty()) {
        pending_ = false;
        return 0;
      }
      const StepSegment& s = queue_->front();
      if (s.kind == StepSegment::kPen) {
        hal_->pen(s.pen_down);
        const uint32_t dwell = s.dwell_ticks;
        queue_->pop();
        if (dwell > 0) {
          pending_ = false;
          return dwell;
        }
        continue;
      }
      if (s.new_block) {
        dominant_ = s.dominant;
        other_ = static_cast<uint8_t>(1 - s.dominant);
        major_ = s.major;
        minor_ = s.minor;
        error_ = s.major / 2;  // centred: the other motor is never more than 1/2 step off
        for (uint8_t m = 0; m < 2; ++m) {
          const bool backward = (s.dir_bits >> m) & 1u;
          step_[m] = backward ? -1 : 1;
          hal_->set_direction(m, backward);
        }
      }
      left_ = s.count;
      interval_q8_ = s.interval_q8;
      add_q8_ = s.add_q8;
      queue_->pop();
    }
  }

  Hal* hal_ = nullptr;
  Queue* queue_ = nullptr;
  bool pending_ = false;
  uint8_t dominant_ = 0, other_ = 1;
  int32_t step_[2] = {1, 1};
  uint32_t major_ = 1, minor_ = 0, error_ = 0;
  uint32_t left_ = 0;
  int32_t interval_q8_ = 0, add_q8_ = 0;
  uint32_t fraction_ = 0;  // Q8 fraction of a tick carried between events
  int32_t position_[2] = {0, 0};
  uint32_t events_ = 0;
};

}  // namespace haloplot
