// The plot in real time on a board: the main loop refills the step queue (planner and step
// prep), the step clock's interrupt runs the shared step tick (step_engine.h). Header-only, a
// template over the board (hal/include/haloplot/hal/board_hal.h: its stepper drivers, pen and step
// clock, static functions) and the step HAL the tick drives
// (hal/include/haloplot/hal/plotter_hal.h; by default the board's own pins, BoardStepHal). Wiring
// it into an image (docs/porting.md):
//
//   MotionRunner<MyBoard> motion;
//   extern "C" void step_timer_irq() { motion.on_timer(); }       // the step clock's interrupt
//   MyBoard::limits_init([](uint8_t m) { motion.on_limit(m); });  // the end stops' interrupt
//   motion.begin(spec, prepared);                                 // a prepared job (job/job.h)
//   for (;;) { motion.service(); ... }                            // the main loop, often
//
// What it decides, so an integrator does not: the timer starts from service() with the tick's
// first delay; each interrupt ends the STEP pulses of the last event first (steps_low), then
// the tick raises the next ones; a tick that finds the queue dry stops the timer, and service()
// refills and restarts it where the plan was (an underrun: the step sequence and its stamps do
// not change, only wall time stretches, and it is counted); a limit switch stops the timer in
// its own interrupt and service() ends the plot with kLimitSwitch; abort() ends it from the
// main loop with kAborted; pause() brakes to rest and lifts the pen (feed hold), resume() goes
// on. Every end stops the timer, lowers STEP and, unless the plot finished, lifts the pen.
//
// The time base is the core's, not the timer's: the HAL's `now` is the running sum of the
// delays the tick returned, as in the host simulator's run_virtual (virtual_run.h), so a trace
// stamped with it equals the simulator's whatever the interrupt latency.
//
// A HAL may also have `void plot_begin(const Machine&)`, called as each plot starts (after
// `now` is reset, before the first event), and `void plot_end()`, called as it ends (the
// project's test images start and finish their step trace there).
#pragma once
#include <stdint.h>

#include "haloplot/hal/board_hal.h"
#include "haloplot/job/job.h"
#include "haloplot/motion/planner.h"
#include "haloplot/motion/step_engine.h"
#include "haloplot/motion/step_prep.h"
#include "haloplot/motion/virtual_run.h"
#include "haloplot/protocol/job_server.h"

namespace haloplot {

// The step HAL a board gives the tick by default: each call one of the board's pin writes,
// inline in the interrupt. `now` is the plot's time in ticks.
template <typename Board>
struct BoardStepHal {
  uint64_t now = 0;
  void step(uint8_t motor) { Board::step_high(motor); }
  void set_direction(uint8_t motor, bool backward) { Board::set_dir(motor, backward); }
  void pen(bool down) { Board::pen_set(down); }
};

namespace motion_runner_detail {
HALOPLOT_HAL_MEMBER(HasPlotBegin,
                    hal::detail::object<H>().plot_begin(hal::detail::object<const Machine>()))
HALOPLOT_HAL_MEMBER(HasPlotEnd, hal::detail::object<H>().plot_end())
}  // namespace motion_runner_detail

template <typename Board, typename Hal = BoardStepHal<Board>, typename Queue = SegmentQueue<64>>
class MotionRunner {
  static_assert(hal::check_motion_board<Board>(),
                "the motion runner's board (hal/include/haloplot/hal/board_hal.h)");
  static_assert(hal::check_virtual_clock<Hal>(), "the motion runner's step HAL keeps `now`");

 public:
  // Constant-initialised, and all zero: a runner in static storage is in .bss, ready with no
  // constructor run (a start-up that skips .init_array is fine), and nothing is in .data. (The
  // defaulted constructor is constexpr as long as the step HAL's and queue's are; the CTest
  // static_init holds the runner to it.)
  MotionRunner() = default;

  // Main loop. begin(): the plot of a prepared job (job/job.h job_prepare, or a band feed),
  // resumed after job.resume_after_events if set; the timer starts at once. kBusy while a plot
  // runs; a board's timer_init() refusing the tick rate ends it before it starts.
  Status begin(const JobSpec& spec, const PreparedJob& job);
  // Often (every pass of the main loop): refill the queue, restart the timer after the queue ran
  // dry, and end the plot when it is done, aborted or stopped by a limit switch.
  void service();
  void abort() { abort_ = true; }  // the next service() ends the plot (kAborted)
  void pause();                    // feed hold: brake to rest, lift the pen, stop the timer
  void resume();                   // after a hold at rest, go on
  bool paused() const { return active_ && prep_.held() && queue_.empty() && !timer_armed_; }

  // Interrupts. on_timer(): the step clock's (with a long delay's chunks passed over);
  // on_limit(): an end stop's, which stops the timer before anything else.
  void on_timer();
  void on_limit(uint8_t motor);

  bool running() const { return active_; }
  bool stepping() const { return active_ && timer_armed_; }  // the timer will interrupt
  Status result() const { return result_; }                  // the last plot's end
  uint32_t events() const { return engine_.events(); }
  uint32_t underruns() const { return underruns_; }
  // The step events at the last pause(), and whether the count is exact (see pause()).
  uint32_t hold_events() const { return hold_events_; }
  bool hold_exact() const { return hold_exact_; }
  // The board's step clock runs k times fast (timer_init's scale): test images under emulation.
  // 0, the default, is 1.
  void set_time_scale(uint32_t k) { time_scale_ = k; }
  Hal& hal() { return hal_; }
  Queue& queue() { return queue_; }
  // The job server's view of this runner (protocol/job_server.h).
  MotionPort port();

 private:
  // Not copyable (declared, never defined): the engine points at this runner's HAL and queue.
  MotionRunner(const MotionRunner&);
  MotionRunner& operator=(const MotionRunner&);
  void finish(Status s);

  // Sized by the planner at compile time; PlotterEffects{} has acceleration on, the most any
  // job asks (without it the planner needs none).
  alignas(8) uint8_t planner_ws_[MotionPlanner::workspace_bytes(PlotterEffects{})] = {};
  MotionPlanner planner_;
  StepPrep prep_;
  Queue queue_;
  Hal hal_;
  StepEngine<Hal, Queue> engine_;  // unbound until begin() binds it to hal_ and queue_
  // Every default here is zero (a zero time scale is 1), so the runner's constant initial
  // state is all zero bytes.
  volatile bool active_ = false, timer_armed_ = false, abort_ = false;
  volatile uint8_t limit_ = 0;   // motor + 1 whose switch fired
  volatile uint32_t delay_ = 0;  // ticks of the period now running
  uint32_t underruns_ = 0, time_scale_ = 0;
  bool resuming_ = false, hold_exact_ = false;
  uint32_t hold_events_ = 0;
  Status result_ = Status::kOk;
};

template <typename Board, typename Hal, typename Queue>
MotionPort MotionRunner<Board, Hal, Queue>::port() {
  MotionPort p;
  p.ctx = this;
  p.begin = [](void* c, const JobSpec& s, const PreparedJob& j) {
    return static_cast<MotionRunner*>(c)->begin(s, j);
  };
  p.abort = [](void* c) { static_cast<MotionRunner*>(c)->abort(); };
  p.running = [](void* c) { return static_cast<MotionRunner*>(c)->running(); };
  p.result = [](void* c) { return static_cast<MotionRunner*>(c)->result(); };
  p.step_events = [](void* c) { return static_cast<MotionRunner*>(c)->events(); };
  p.pause = [](void* c) { static_cast<MotionRunner*>(c)->pause(); };
  p.resume = [](void* c) { static_cast<MotionRunner*>(c)->resume(); };
  p.paused = [](void* c) { return static_cast<MotionRunner*>(c)->paused(); };
  return p;
}

template <typename Board, typename Hal, typename Queue>
Status MotionRunner<Board, Hal, Queue>::begin(const JobSpec& spec, const PreparedJob& job) {
  if (active_) return Status::kBusy;
  Status s = Board::timer_init(TickRate{spec.machine.tick_hz},
                               TimeScale{time_scale_ == 0 ? 1 : time_scale_});
  if (ok(s)) s = init_planner(&planner_, spec, job, planner_ws_, sizeof planner_ws_);
  if (ok(s)) s = prep_.init(spec.machine, spec.effects);
  if (!ok(s)) return s;
  queue_.clear();
  engine_ = StepEngine<Hal, Queue>(hal_, queue_);
  hal_.now = 0;
  if constexpr (motion_runner_detail::HasPlotBegin<Hal>::value) hal_.plot_begin(spec.machine);
  abort_ = false;
  limit_ = 0;
  result_ = Status::kOk;
  underruns_ = 0;
  resuming_ = false;
  timer_armed_ = false;
  // A resumed plot: its first events made again with no motor moving, then a travel there.
  s = skip_events(planner_, prep_, job.resume_after_events);
  if (!ok(s)) return s;
  s = prep_.fill(planner_, queue_);
  if (!ok(s)) return s;
  Board::enable_drivers(true);
  active_ = true;
  service();  // starts the timer
  return Status::kOk;
}

// Feed hold, from the main loop: the queue is topped up first, so the hold starts where the
// host simulator's does after the same step events (virtual_run.h): at the end of a full
// queue. The interrupt then runs the braking out, the pen lifts, the queue runs dry and the
// timer stops; resume() refills and service() restarts it.
template <typename Board, typename Hal, typename Queue>
void MotionRunner<Board, Hal, Queue>::pause() {
  if (!active_ || prep_.holding()) return;
  const uint32_t before = events();
  const Status s = prep_.fill(planner_, queue_);
  if (!ok(s)) return finish(s);
  prep_.hold();
  // Where the hold was asked for, as `haloplot sim --pause-at` takes it: exact unless a step
  // event came in between (the refill then followed fewer events than the count says).
  hold_events_ = events();
  hold_exact_ = hold_events_ == before;
}

template <typename Board, typename Hal, typename Queue>
void MotionRunner<Board, Hal, Queue>::resume() {
  if (!active_ || !paused()) return;
  prep_.resume();
  resuming_ = true;  // the restart is not an underrun
}

template <typename Board, typename Hal, typename Queue>
void MotionRunner<Board, Hal, Queue>::finish(Status s) {
  Board::timer_stop();
  Board::steps_low();
  queue_.clear();
  if (!ok(s)) Board::pen_set(false);  // an interrupted plot lifts the pen
  if constexpr (motion_runner_detail::HasPlotEnd<Hal>::value) hal_.plot_end();
  result_ = s;
  active_ = false;
}

template <typename Board, typename Hal, typename Queue>
void MotionRunner<Board, Hal, Queue>::service() {
  if (!active_) return;
  if (limit_) return finish(Status::kLimitSwitch);
  if (abort_) return finish(Status::kAborted);
  const Status s = prep_.fill(planner_, queue_);
  if (!ok(s)) return finish(s);
  if (timer_armed_) return;
  // The interrupt found the queue empty (or the plot is starting): resume, or end.
  const bool mid_plot = engine_.events() > 0 || hal_.now > 0;
  const uint32_t d = engine_.start();
  if (d == 0) {
    if (queue_.empty() && prep_.done()) finish(Status::kOk);
    return;
  }
  if (mid_plot && !resuming_ && !prep_.held()) ++underruns_;
  resuming_ = false;
  delay_ = d;
  timer_armed_ = true;
  Board::timer_start(d);
}

template <typename Board, typename Hal, typename Queue>
void MotionRunner<Board, Hal, Queue>::on_timer() {
  if (Board::timer_chunk_pending()) return;  // a long delay (a pen dwell) is still running
  Board::steps_low();
  hal_.now += delay_;
  const uint32_t d = engine_.tick();
  if (d == 0) {  // the queue is dry: the main loop refills and restarts (or ends the plot)
    Board::timer_stop();
    timer_armed_ = false;
    return;
  }
  delay_ = d;
  Board::timer_next(d);
}

template <typename Board, typename Hal, typename Queue>
void MotionRunner<Board, Hal, Queue>::on_limit(uint8_t motor) {
  Board::timer_stop();  // first: no further step, whatever the main loop is doing
  timer_armed_ = false;
  limit_ = uint8_t(motor + 1);
}

}  // namespace haloplot
