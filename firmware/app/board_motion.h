// The controller's motion: the library's runner (core/include/haloplot/controller/motion_runner.h)
// on this image's board, its step HAL the board's pins. Test images (HALOPLOT_FW_TEST_HOOKS) also
// trace every event for comparison with the host simulator: their HAL writes the trace beside each
// pin, and their queue shows it each segment the tick takes. The flashed image has none of that:
// the trace's decimal text needs division, which its step path must not (check_image.cmake).
#pragma once
#include "board/board.h"
#include "haloplot/controller/motion_runner.h"

#ifdef HALOPLOT_FW_TEST_HOOKS
#include <new>  // placement construction into static storage: no heap

#include "haloplot/trace/traced_queue.h"
#endif

namespace haloplot::fw {

#ifdef HALOPLOT_FW_TEST_HOOKS
using TracedSegments = TracedQueue<SegmentQueue<64>>;

// The board's pins, and the trace of each event at the plot's time (`now`, the runner's).
struct TracingHal {
  uint64_t now = 0;
  bool backward[2] = {false, false};
  TraceEncoder* trace = nullptr;
  TracedSegments* segments = nullptr;
  CharSink sink{nullptr, nullptr};
  bool tracing = false;
  alignas(8) uint8_t storage[sizeof(TraceEncoder)];

  void set_direction(uint8_t m, bool b) {
    backward[m] = b;
    Board::set_dir(m, b);
  }
  void step(uint8_t m) {
    Board::step_high(m);
    if (trace) trace->step(now, m, backward[m]);
  }
  void pen(bool down) {
    Board::pen_set(down);
    if (trace) trace->pen(now, down);
  }
  void plot_begin(const Machine& machine) {
    backward[0] = backward[1] = false;
    trace = tracing ? new (storage) TraceEncoder(sink, machine) : nullptr;
    segments->set_encoder(trace);
  }
  void plot_end() {
    if (trace) trace->finish(now);
  }
};

class MotionRunner : public haloplot::MotionRunner<Board, TracingHal, TracedSegments> {
 public:
  MotionRunner() { hal().segments = &queue(); }
  void set_trace(CharSink sink) { hal().sink = sink, hal().tracing = true; }
};
#else
using MotionRunner = haloplot::MotionRunner<Board>;
#endif

}  // namespace haloplot::fw
