#include "app/motion_runner.h"

#include <new>  // placement construction into static storage: no heap

#include "board/board.h"
#include "motion/virtual_run.h"

namespace haloplot::fw {

void ChipHal::set_direction(uint8_t m, bool b) {
  backward[m] = b;
  Board::set_dir(m, b);
}
// The trace is test instrumentation: only test images compile it onto the step path (its
// decimal text needs division; the flashed image's step path has none, see check_image.cmake).
void ChipHal::step(uint8_t m) {
  Board::step_high(m);
#ifdef HALOPLOT_FW_TEST_HOOKS
  if (trace) trace->step(now, m, backward[m]);
#endif
}
void ChipHal::pen(bool down) {
  Board::pen_set(down);
#ifdef HALOPLOT_FW_TEST_HOOKS
  if (trace) trace->pen(now, down);
#endif
}

MotionPort MotionRunner::port() {
  MotionPort p;
  p.ctx = this;
  p.begin = [](void* c, const JobSpec& s, const PreparedJob& j) {
    return static_cast<MotionRunner*>(c)->begin(s, j);
  };
  p.abort = [](void* c) { static_cast<MotionRunner*>(c)->abort_ = true; };
  p.running = [](void* c) { return static_cast<MotionRunner*>(c)->active_ == true; };
  p.result = [](void* c) { return static_cast<MotionRunner*>(c)->result_; };
  p.step_events = [](void* c) { return static_cast<MotionRunner*>(c)->events(); };
  p.pause = [](void* c) { static_cast<MotionRunner*>(c)->pause(); };
  p.resume = [](void* c) { static_cast<MotionRunner*>(c)->resume(); };
  p.paused = [](void* c) { return static_cast<MotionRunner*>(c)->paused(); };
  return p;
}

Status MotionRunner::begin(const JobSpec& spec, const PreparedJob& job) {
  if (active_) return Status::kBusy;
  Status s = Board::timer_init(spec.machine.tick_hz, time_scale_);
  if (ok(s)) s = init_planner(&planner_, spec, job, planner_ws_, sizeof planner_ws_);
  if (ok(s)) s = prep_.init(spec.machine, spec.effects);
  if (!ok(s)) return s;
  queue_.clear();
  engine_.~StepEngine();
  new (&engine_) StepEngine<ChipHal, Queue>(hal_, queue_);
  hal_ = ChipHal{};
  trace_ = tracing_ ? new (trace_storage_) TraceEncoder(trace_sink_, spec.machine) : nullptr;
  hal_.trace = trace_;
#ifdef HALOPLOT_FW_TEST_HOOKS
  queue_.set_encoder(trace_);
#endif
  abort_ = false;
  limit_ = 0;
  result_ = Status::kOk;
  underruns_ = 0;
  resuming_ = false;
  timer_idle_ = true;
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

// Feed hold, from the main loop (the job server): the queue is topped up first, so the hold
// starts where the host simulator's does after the same step events (motion/virtual_run.h):
// at the end of a full queue. The interrupt then runs the braking out, the pen lifts, the
// queue runs dry and the timer stops; resume() refills and service() restarts it.
void MotionRunner::pause() {
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

void MotionRunner::resume() {
  if (!active_ || !paused()) return;
  prep_.resume();
  resuming_ = true;  // the restart is not an underrun
}

bool MotionRunner::paused() const {
  return active_ && prep_.held() && queue_.empty() && timer_idle_;
}

void MotionRunner::finish(Status s) {
  Board::timer_stop();
  Board::steps_low();
  queue_.clear();
  if (!ok(s)) Board::pen_set(false);  // an interrupted plot lifts the pen
  if (trace_) trace_->finish(hal_.now);
  result_ = s;
  active_ = false;
}

void MotionRunner::service() {
  if (!active_) return;
  if (limit_) return finish(Status::kLimitSwitch);
  if (abort_) return finish(Status::kAborted);
  const Status s = prep_.fill(planner_, queue_);
  if (!ok(s)) return finish(s);
  if (!timer_idle_) return;
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
  timer_idle_ = false;
  Board::timer_start(d);
}

void MotionRunner::on_timer() {
  Board::steps_low();
  hal_.now += delay_;
  const uint32_t d = engine_.tick();
  if (d == 0) {  // the queue is dry: the main loop refills and restarts (or ends the plot)
    Board::timer_stop();
    timer_idle_ = true;
    return;
  }
  delay_ = d;
  Board::timer_next(d);
}

void MotionRunner::on_limit(uint8_t motor) {
  Board::timer_stop();  // first: no further step, whatever the main loop is doing
  timer_idle_ = true;
  limit_ = uint8_t(motor + 1);
}

}  // namespace haloplot::fw
