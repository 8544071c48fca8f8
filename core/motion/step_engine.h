// The step tick: the only code on the step path. The firmware's timer interrupt and the host
// simulator call the same tick(). It takes one step event from the current segment, runs
// Bresenham for the other motor, and returns how many ticks until the next event, so the
// timer is set once per event (no fixed-rate polling, no idle interrupts).
//
// No division, no floating point, no virtual call: the HAL is a template parameter, so each
// pin write inlines. Time is absolute, in Q8 ticks since the start, and every event fires at
// floor(time): rounding never accumulates.
//
// Hal must provide: void step(uint8_t motor); void set_direction(uint8_t motor, bool backward);
//                   void pen(bool down);
#pragma once
#include <stdint.h>

#include "motion/step_segment.h"

namespace haloplot {

template <typename Hal, typename Queue>
class StepEngine {
 public:
  StepEngine(Hal& hal, Queue& queue) : hal_(hal), queue_(queue) {}

  // Begin, or resume after the queue ran dry: returns the delay to the first event (0: nothing
  // to do). The time base continues from the last event.
  uint32_t start() {
    pending_ = false;
    return advance();
  }

  // The timer fired: do the due event, return ticks until the next one (0: queue empty).
  uint32_t tick() {
    if (pending_) {
      hal_.step(dominant_);
      position_[dominant_] += backward_[dominant_] ? -1 : 1;
      error_ += minor_;
      if (error_ >= major_) {  // Bresenham: the other motor steps when its error overflows
        error_ -= major_;
        hal_.step(other_);
        position_[other_] += backward_[other_] ? -1 : 1;
      }
      ++events_;
    }
    return advance();
  }

  int32_t position(uint8_t motor) const { return position_[motor]; }
  uint64_t events() const { return events_; }
  uint64_t now() const { return fired_q8_ >> 8; }

 private:
  // Schedule the next event: the next step of this segment, or the next segment. Pen changes
  // happen here, at once, and their dwell becomes the delay.
  uint32_t advance() {
    for (;;) {
      if (left_ > 0) {
        --left_;
        time_q8_ += interval_q8_;
        interval_q8_ += add_q8_;
        pending_ = true;
        return fire();
      }
      if (queue_.empty()) {
        pending_ = false;
        return 0;
      }
      const StepSegment& s = queue_.front();
      if (s.kind == StepSegment::kPen) {
        hal_.pen(s.pen_down);
        time_q8_ += s.interval_q8;
        queue_.pop();
        if (s.interval_q8 > 0) {
          pending_ = false;
          return fire();
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
          backward_[m] = (s.dir_bits >> m) & 1u;
          hal_.set_direction(m, backward_[m]);
        }
      }
      left_ = s.count;
      interval_q8_ = s.interval_q8;
      add_q8_ = s.add_q8;
      queue_.pop();
    }
  }

  uint32_t fire() {
    const uint64_t at = time_q8_ >> 8;
    const uint32_t delay = static_cast<uint32_t>(at - (fired_q8_ >> 8));
    fired_q8_ = time_q8_ & ~uint64_t{0xff};
    return delay;
  }

  Hal& hal_;
  Queue& queue_;
  bool pending_ = false;
  uint8_t dominant_ = 0, other_ = 1;
  bool backward_[2] = {false, false};
  uint32_t major_ = 1, minor_ = 0, error_ = 0;
  uint32_t left_ = 0;
  int64_t interval_q8_ = 0, add_q8_ = 0;
  uint64_t time_q8_ = 0;   // when the scheduled event is due
  uint64_t fired_q8_ = 0;  // the tick (as Q8) of the last event handed to the timer
  int32_t position_[2] = {0, 0};
  uint64_t events_ = 0;
};

}  // namespace haloplot
