#include "sim/simulator.h"

#include <memory>

#include "motion/step_engine.h"
#include "motion/virtual_run.h"
#include "sim/trace.h"

namespace haloplot::host {
namespace {

// The recording HAL: Pigweed-mock style, it timestamps every call with the virtual clock and
// hands it to the trace writer. Directions are latched, as a DIR pin is.
struct RecordingHal {
  uint64_t now = 0;
  bool backward[2] = {false, false};
  TraceWriter* writer = nullptr;
  SimReport* report = nullptr;
  uint64_t last_step[2] = {UINT64_MAX, UINT64_MAX};
  bool pen_down = false;

  void set_direction(uint8_t motor, bool back) { backward[motor] = back; }
  void step(uint8_t motor) {
    if (writer) writer->step(now, motor, backward[motor]);
    ++report->steps[motor];
    if (last_step[motor] != UINT64_MAX && now - last_step[motor] < report->min_gap[motor])
      report->min_gap[motor] = now - last_step[motor];
    last_step[motor] = now;
  }
  void pen(bool down) {
    if (writer) writer->pen(now, down);
    if (pen_down && !down) ++report->pen_lifts;
    pen_down = down;
  }
};

}  // namespace

Status simulate(const JobSpec& spec, const std::vector<Edge3>& edges, std::ostream* trace,
                SimReport* r) {
  *r = SimReport{};
  const uint32_t n = uint32_t(edges.size());
  // Size the job buffer from the core's own query; one retry if CUT needs more records.
  uint32_t capacity = 4 * n + 1024;
  std::vector<uint64_t> buffer;
  PreparedJob job;
  Status s;
  for (;;) {
    s = job_bytes(spec, edges.data(), n, capacity, &r->bytes);
    if (!ok(s)) return s;
    buffer.assign(r->bytes.total() / 8 + 1, 0);
    s = job_prepare(spec, edges.data(), n, capacity, buffer.data(), buffer.size() * 8, &job,
                    &r->job);
    if (s == Status::kCrossingCapacity && r->retries == 0) {
      capacity = uint32_t(r->job.cut.crossings + r->job.cut.near_misses);
      ++r->retries;
      continue;
    }
    if (!ok(s)) return s;
    break;
  }
  r->points.assign(job.points, job.points + job.n_points);
  r->spans.assign(job.spans, job.spans + job.n_spans);

  r->planner_bytes = MotionPlanner::workspace_bytes(spec.effects);
  std::vector<uint64_t> planner_ws(r->planner_bytes / 8 + 1);
  MotionPlanner planner;
  s = planner.init(spec.machine, spec.effects, job.points, job.n_points, planner_ws.data(),
                   r->planner_bytes);
  if (!ok(s)) return s;
  StepPrep prep;
  s = prep.init(spec.machine, spec.effects);
  if (!ok(s)) return s;

  std::unique_ptr<TraceWriter> writer;
  if (trace) writer = std::make_unique<TraceWriter>(*trace, spec.machine);
  RecordingHal hal;
  hal.writer = writer.get();
  hal.report = r;
  SegmentQueue<64> queue;
  StepEngine<RecordingHal, SegmentQueue<64>> engine(hal, queue);
  s = run_virtual(planner, prep, queue, hal, engine);
  if (!ok(s)) return s;
  r->end_tick = hal.now;
  r->planner = planner.counters();
  r->prep = prep.counters();
  r->final_motors[0] = engine.position(0);
  r->final_motors[1] = engine.position(1);
  if (writer) writer->finish(hal.now);
  return Status::kOk;
}

}  // namespace haloplot::host
