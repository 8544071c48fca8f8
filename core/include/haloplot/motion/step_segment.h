// What the step prep hands the step tick: short runs of steps with linearly changing
// intervals, pen changes with their dwell, and backlash take-up. A fixed-size ring, filled by
// the main loop and drained by the timer interrupt (single producer, single consumer).
#pragma once
#include <stdint.h>

namespace haloplot {

struct StepSegment {
  enum Kind : uint8_t { kSteps, kPen };
  Kind kind = kSteps;
  bool new_block = false;  // kSteps: reset the Bresenham state and set directions
  bool pen_down = false;   // kPen
  uint8_t dominant = 0;    // kSteps: the motor that steps on every event
  uint8_t dir_bits = 0;    // bit m set: motor m runs backwards
  uint16_t count = 0;      // kSteps: events in this segment
  uint32_t major = 0;      // Bresenham: dominant steps in the block
  uint32_t minor = 0;      //            other motor's steps in the block
  // 32-bit on purpose: the tick does only 32-bit arithmetic on the M4. The prep guarantees
  // every interval of the segment lies in [min_interval * 256, 2^31).
  int32_t interval_q8 = 0;   // kSteps: ticks * 256 before the first event
  int32_t add_q8 = 0;        // kSteps: change of the interval after each event
  uint32_t dwell_ticks = 0;  // kPen: whole ticks to wait after the pen moves
};

template <uint32_t kCapacity>
class SegmentQueue {
  static_assert((kCapacity & (kCapacity - 1)) == 0, "capacity must be a power of two");

 public:
  bool empty() const { return head_ == tail_; }
  bool full() const { return tail_ - head_ == kCapacity; }
  uint32_t size() const { return tail_ - head_; }
  // One producer (the main loop) and one consumer (the timer interrupt) on one core: the
  // signal fences stop the compiler from moving the slot's stores past the index update
  // (push) or the slot's loads past the release of the slot (pop); the indices are volatile.
  void push(const StepSegment& s) {
    items_[tail_ % kCapacity] = s;
    __atomic_signal_fence(__ATOMIC_RELEASE);
    tail_ = tail_ + 1;
  }
  const StepSegment& front() const {
    __atomic_signal_fence(__ATOMIC_ACQUIRE);
    return items_[head_ % kCapacity];
  }
  void pop() {
    __atomic_signal_fence(__ATOMIC_RELEASE);
    head_ = head_ + 1;
  }
  void clear() { head_ = tail_; }  // only while the consumer is stopped

 private:
  StepSegment items_[kCapacity];
  volatile uint32_t head_ = 0, tail_ = 0;  // free-running counters: no wrap ambiguity
};

}  // namespace haloplot
