// A segment queue that shows the trace encoder each segment as the step tick takes it: the
// tick calls front() and then pop() on every load, so pop() is where a segment starts to run.
// Only traced builds (the simulator, tests, the firmware's test images) use it; the flashed
// controller's queue is the plain one, so the step path carries no trace code.
#pragma once
#include "haloplot/motion/step_segment.h"
#include "haloplot/trace/trace_encoder.h"

namespace haloplot {

template <typename Queue>
class TracedQueue : public Queue {
 public:
  void set_encoder(TraceEncoder* encoder) { encoder_ = encoder; }
  void pop() {
    if (encoder_ != nullptr) encoder_->segment(Queue::front());
    Queue::pop();
  }

 private:
  TraceEncoder* encoder_ = nullptr;
};

}  // namespace haloplot
