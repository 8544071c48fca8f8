// The serial link's receive ring, the same on every board: the receive interrupt pushes, the
// main loop pops (one producer, one consumer on one core: free-running volatile indices, no
// lock). A byte that finds the ring full is counted as an overrun, as is one the UART itself
// lost (count_overrun()).
#pragma once
#include <stdint.h>

namespace haloplot::fw {

template <uint32_t kBytes>
class RxRing {
  static_assert((kBytes & (kBytes - 1)) == 0, "power of two: free-running indices");

 public:
  void push(uint8_t b) {  // the interrupt
    if (tail_ - head_ < kBytes) {
      bytes_[tail_ % kBytes] = b;
      tail_ = tail_ + 1;
    } else {
      count_overrun();
    }
  }
  bool pop(uint8_t* b) {  // the main loop
    if (head_ == tail_) return false;
    *b = bytes_[head_ % kBytes];
    head_ = head_ + 1;
    return true;
  }
  void count_overrun() { overruns_ = overruns_ + 1; }
  uint32_t overruns() const { return overruns_; }

 private:
  uint8_t bytes_[kBytes] = {};  // every member initialised: constant-initialised, in .bss
  volatile uint32_t head_ = 0, tail_ = 0, overruns_ = 0;
};

}  // namespace haloplot::fw
