// A MotionPort for host tests of the job server: each plot runs at once in virtual time (the
// core's run_virtual, as the simulator does) into a trace string, and then reports itself
// running for `busy_polls` more polls, so tests can see the busy state and abort it.
#pragma once
#include <string>
#include <vector>

#include "haloplot/motion/planner.h"
#include "haloplot/motion/step_engine.h"
#include "haloplot/motion/step_prep.h"
#include "haloplot/motion/virtual_run.h"
#include "haloplot/protocol/job_server.h"
#include "haloplot/trace/traced_queue.h"

namespace haloplot::test {

struct VirtualMotion {
  std::vector<std::string> traces;  // one per plot
  std::vector<std::vector<Segment2>> spans;
  int busy_polls = 0, left = 0;
  bool aborted = false;
  Status outcome = Status::kOk;

  struct Hal {
    uint64_t now = 0;
    bool backward[2] = {false, false};
    TraceEncoder* trace = nullptr;
    uint32_t steps = 0;
    void set_direction(uint8_t m, bool b) { backward[m] = b; }
    void step(uint8_t m) { trace->step(now, m, backward[m]), ++steps; }
    void pen(bool down) { trace->pen(now, down); }
  };
  uint32_t steps = 0;

  static Status begin(void* ctx, const JobSpec& spec, const PreparedJob& job) {
    auto* self = static_cast<VirtualMotion*>(ctx);
    std::string out;
    const CharSink sink{
        [](void* c, const char* t, uint32_t n) { static_cast<std::string*>(c)->append(t, n); },
        &out};
    std::vector<uint8_t> ws(MotionPlanner::kDefaultLookahead * 64);
    MotionPlanner planner;
    Status s = init_planner(&planner, spec, job, ws.data(), ws.size());
    StepPrep prep;
    if (ok(s)) s = prep.init(spec.machine, spec.effects);
    if (!ok(s)) return s;
    TraceEncoder trace(sink, spec.machine);
    Hal hal;
    hal.trace = &trace;
    TracedQueue<SegmentQueue<64>> queue;
    queue.set_encoder(&trace);
    StepEngine<Hal, TracedQueue<SegmentQueue<64>>> engine(hal, queue);
    s = run_virtual(planner, prep, queue, hal, engine);
    trace.finish(hal.now);
    self->traces.push_back(out);
    self->spans.emplace_back(job.spans, job.spans + job.n_spans);
    self->steps = hal.steps;
    self->outcome = s;
    self->left = self->busy_polls;
    self->aborted = false;
    return Status::kOk;
  }
  static void abort(void* ctx) {
    auto* self = static_cast<VirtualMotion*>(ctx);
    self->aborted = true;
    self->left = 0;
    self->outcome = Status::kAborted;
  }
  static bool running(void* ctx) {
    auto* self = static_cast<VirtualMotion*>(ctx);
    if (self->left == 0) return false;
    --self->left;
    return true;
  }
  static Status result(void* ctx) { return static_cast<VirtualMotion*>(ctx)->outcome; }
  static uint32_t step_events(void* ctx) { return static_cast<VirtualMotion*>(ctx)->steps; }
  MotionPort port() { return MotionPort{this, &begin, &abort, &running, &result, &step_events}; }
};

}  // namespace haloplot::test
