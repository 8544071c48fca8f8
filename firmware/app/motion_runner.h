// The plot in motion on the chip: the planner and step prep refill the segment queue from the
// main loop; the step timer's interrupt (SysTick) runs the shared step tick
// (core/motion/step_engine.h) on the chip's HAL. Implements the job server's MotionPort.
//
// The time base is the core's, not the timer's: every event is stamped with the running sum
// of the delays the tick returned, exactly as the host simulator's run_virtual does. If the
// main loop ever falls behind (the interrupt finds the queue empty mid-plot: an underrun),
// the timer stops, the main loop refills and restarts it, and the plan resumes where it was:
// the step sequence and its timestamps are unchanged; only wall time stretches (counted).
#pragma once
#include <stdint.h>

#include "motion/planner.h"
#include "motion/step_engine.h"
#include "motion/step_prep.h"
#include "protocol/job_server.h"
#include "trace/traced_queue.h"

namespace haloplot::fw {

// The chip's plotter HAL: GPIO for STEP/DIR, the servo for the pen, and (test images only)
// a trace of every event for comparison with the host simulator.
struct ChipHal {
  uint64_t now = 0;
  bool backward[2] = {false, false};
  TraceEncoder* trace = nullptr;
  void set_direction(uint8_t m, bool b);
  void step(uint8_t m);
  void pen(bool down);
};

class MotionRunner {
 public:
#ifdef HALOPLOT_FW_TEST_HOOKS
  using Queue = TracedQueue<SegmentQueue<64>>;  // shows the trace each segment the tick takes
#else
  using Queue = SegmentQueue<64>;
#endif

  MotionPort port();
  void service();                // main loop: refill, restart after a dry queue, notice the end
  void on_timer();               // the step timer's interrupt (SysTick)
  void on_limit(uint8_t motor);  // EXTI interrupt: stop at once
  void pause();                  // main loop: feed hold (brake to rest, lift the pen, wait)
  void resume();                 // main loop: after a hold at rest, go on
  bool paused() const;           // held at rest, the timer stopped
  // The step events at the last pause(), and whether the count is exact (see pause()).
  uint32_t hold_events() const { return hold_events_; }
  bool hold_exact() const { return hold_exact_; }
  void set_trace(CharSink sink) { trace_sink_ = sink, tracing_ = true; }
  void set_time_scale(uint32_t k) { time_scale_ = k; }  // see step_timer.h
  uint32_t underruns() const { return underruns_; }
  uint32_t events() const { return engine_.events(); }
  bool running() const { return active_; }
  bool stepping() const { return active_ && !timer_idle_; }  // the timer will interrupt

 private:
  Status begin(const JobSpec& spec, const PreparedJob& job);
  void finish(Status s);

  // Sized by the planner at compile time; PlotterEffects{} has acceleration on, the most any
  // job asks (without it the planner needs none).
  alignas(8) uint8_t planner_ws_[MotionPlanner::workspace_bytes(PlotterEffects{})];
  MotionPlanner planner_;
  StepPrep prep_;
  Queue queue_;
  ChipHal hal_;
  StepEngine<ChipHal, Queue> engine_{hal_, queue_};
  TraceEncoder* trace_ = nullptr;
  alignas(8) uint8_t trace_storage_[sizeof(TraceEncoder)];
  CharSink trace_sink_{nullptr, nullptr};
  bool tracing_ = false;
  volatile bool active_ = false, timer_idle_ = true, abort_ = false;
  volatile uint8_t limit_ = 0;   // motor + 1 whose switch fired
  volatile uint32_t delay_ = 0;  // ticks of the period now running
  uint32_t underruns_ = 0, time_scale_ = 1;
  bool resuming_ = false, hold_exact_ = false;
  uint32_t hold_events_ = 0;
  Status result_ = Status::kOk;
};

}  // namespace haloplot::fw
