#include "sim/simulator.h"

#include <memory>

#include "export/plotter_outputs.h"
#include "haloplot/motion/step_engine.h"
#include "haloplot/motion/virtual_run.h"
#include "haloplot/trace/traced_queue.h"
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

// The path for the planner: the whole scene's from one job buffer (the job stage the
// exporters of `plot` plan with too).
Status prepare_whole(const JobSpec& spec, const std::vector<Edge3>& edges, SimReport* r,
                     const std::vector<BezierEdge3>* curves) {
  PlannedJob planned;
  const Status s = plan_job_path(spec, edges, &planned, curves);
  r->job = planned.counters;
  r->bytes = planned.bytes;
  r->retries = planned.retries;
  if (!ok(s)) return s;
  r->points = std::move(planned.points);
  r->spans = std::move(planned.spans);
  r->layer_points = planned.layer_points;
  return Status::kOk;
}

// The banded run's feed: the conductor's bands, each band's points also kept for the report,
// and the tick at which each band was asked for (the plot of the band before ends about then).
template <typename Conductor>  // BandConductor, or CurveBands (a scene with curves)
struct BandFeed {
  Conductor* conductor;
  SimReport* report;
  const uint64_t* now = nullptr;
  static Status more(void* ctx, const PathPoint** points, uint32_t* n) {
    auto* self = static_cast<BandFeed*>(ctx);
    const uint32_t before = self->conductor->stats().bands;
    const Status s = self->conductor->next(points, n);
    if (ok(s)) self->report->points.insert(self->report->points.end(), *points, *points + *n);
    if (self->conductor->stats().bands != before) self->report->band_ticks.push_back(*self->now);
    return s;
  }
  static void piece(void* ctx, const BandPiece& p) {
    static_cast<BandFeed*>(ctx)->report->spans.push_back(p.segment);
  }
};

// The motion of the plot: from r->points, then (with a conductor) from its bands.
template <typename Conductor = BandConductor>
Status run_motion(const JobSpec& spec, Conductor* conductor, std::ostream* trace, SimReport* r,
                  TraceForm form = TraceForm::kText, const std::vector<uint32_t>& pause_at = {},
                  uint32_t resume_at = 0) {
  r->planner_bytes = MotionPlanner::workspace_bytes(spec.effects);
  std::vector<uint64_t> planner_ws(r->planner_bytes / 8 + 1);
  RecordingHal hal;
  BandFeed<Conductor> feed{conductor, r, &hal.now};
  PreparedJob job;  // the whole plan's points, or (banded) none and the bands' feed
  job.points = r->points.data();
  job.n_points = uint32_t(r->points.size());
  if (conductor != nullptr) {
    conductor->set_observer(PieceObserver{&BandFeed<Conductor>::piece, &feed});
    job.feed = PointFeed{&BandFeed<Conductor>::more, &feed};
  }
  MotionPlanner planner;
  Status s = init_planner(&planner, spec, job, planner_ws.data(), r->planner_bytes);
  if (!ok(s)) return s;
  std::unique_ptr<TraceWriter> writer;
  if (trace) writer = std::make_unique<TraceWriter>(*trace, spec.machine, form);
  hal.writer = writer.get();
  hal.report = r;
  StepPrep prep;
  s = prep.init(spec.machine, spec.effects);
  if (!ok(s)) return s;
  TracedQueue<SegmentQueue<64>> queue;
  if (writer) queue.set_encoder(writer->encoder());
  StepEngine<RecordingHal, TracedQueue<SegmentQueue<64>>> engine(hal, queue);
  job.resume_after_events = resume_at;  // as the controller takes it from kPlot
  s = skip_events(planner, prep, job.resume_after_events);
  if (!ok(s)) return s;
  s = run_virtual(planner, prep, queue, hal, engine,
                  HoldSchedule{pause_at.data(), uint32_t(pause_at.size())});
  if (!ok(s)) return s;
  r->holds = prep.counters().holds;
  r->end_tick = hal.now;
  r->planner = planner.counters();
  r->prep = prep.counters();
  r->final_motors[0] = engine.position(0);
  r->final_motors[1] = engine.position(1);
  // The travel home is the plan's last point too (the exporters' G-code and HPGL end there).
  add_travel_home(spec, &r->points);
  if (conductor != nullptr) {
    r->bands = conductor->stats();
    r->job.path = r->bands.path;
    r->job.cut_runs = uint32_t(r->bands.cut_runs);
    r->job.draw_runs = uint32_t(r->bands.draw_runs);
  }
  if (writer) writer->finish(hal.now);
  return Status::kOk;
}

bool edge_drawing(const JobSpec& spec) {
  return spec.drawing == DrawingEffect::kHaloed || spec.drawing == DrawingEffect::kAllEdges;
}

}  // namespace

Status simulate(const JobSpec& spec, const std::vector<Edge3>& edges, std::ostream* trace,
                SimReport* r, size_t arena_bytes, TraceForm form,
                const std::vector<uint32_t>& pause_at, uint32_t resume_at,
                const std::vector<BezierEdge3>* curves) {
  *r = SimReport{};
  r->arena_bytes = arena_bytes;
  Status s = validate(spec.machine);
  if (!ok(s)) return s;
  std::vector<uint64_t> buffer;
  const bool has_curves = curves != nullptr && !curves->empty();
  if (arena_bytes == 0) {
    s = prepare_whole(spec, edges, r, curves);
    return ok(s) ? run_motion(spec, static_cast<BandConductor*>(nullptr), trace, r, form, pause_at,
                              resume_at)
                 : s;
  }
  if (has_curves) {  // the curve job in bands, as a controller with this arena plots it
    CurveBandSpec cb;
    s = curve_band_spec(spec, &cb);
    if (!ok(s)) return s;
    buffer.assign(arena_bytes / 8, 0);
    CurveBands bands;
    s = bands.begin(cb, curves->data(), uint32_t(curves->size()), edges.data(),
                    uint32_t(edges.size()), buffer.data(), buffer.size() * 8);
    if (ok(s)) s = run_motion(spec, &bands, trace, r, form, pause_at, resume_at);
    r->bands = bands.stats();  // a band that did not fit says what it asked for
    return s;
  }
  if (!edge_drawing(spec)) return Status::kBadParameter;
  buffer.assign(arena_bytes / 8, 0);
  BandConductor conductor;
  s = conductor.begin(band_spec(spec), array_edge_source(edges.data(), uint32_t(edges.size())),
                      buffer.data(), buffer.size() * 8);
  if (ok(s)) s = run_motion(spec, &conductor, trace, r, form, pause_at, resume_at);
  r->bands = conductor.stats();  // a band that did not fit says what it asked for
  return s;
}

Status simulate_solid(const JobSpec& spec, const SolidInput& in, bool closed, std::ostream* trace,
                      SimReport* r, size_t arena_bytes, TraceForm form,
                      const std::vector<uint32_t>& pause_at, uint32_t resume_at) {
  *r = SimReport{};
  r->arena_bytes = arena_bytes;
  Status s = validate(spec.machine);
  if (!ok(s)) return s;
  if (edge_drawing(spec) || arena_bytes == 0) return Status::kBadParameter;
  std::vector<uint64_t> buffer(arena_bytes / 8);
  BandConductor conductor;
  s = conductor.begin_solid(band_spec(spec), array_solid_source(&in, closed), buffer.data(),
                            buffer.size() * 8);
  if (ok(s)) s = run_motion(spec, &conductor, trace, r, form, pause_at, resume_at);
  r->bands = conductor.stats();  // a band that did not fit says what it asked for
  return s;
}

namespace {
SolidStreamFlags solid_flags(const BandPlan& plan) {
  return (plan.closed ? SolidStreamFlags::kClosed : SolidStreamFlags::kNone) |
         (plan.turned ? SolidStreamFlags::kTurned : SolidStreamFlags::kNone);
}
}  // namespace

Status simulate_streamed(const JobSpec& spec, BandStream stream, int32_t margin, size_t arena_bytes,
                         std::ostream* trace, SimReport* r, const BandPlan* solid) {
  *r = SimReport{};
  r->arena_bytes = arena_bytes;
  Status s = validate(spec.machine);
  if (!ok(s)) return s;
  if (edge_drawing(spec) == (solid != nullptr)) return Status::kBadParameter;
  std::vector<uint64_t> buffer(arena_bytes / 8);
  BandConductor conductor;
  s = solid != nullptr ? conductor.begin_streamed_solid(band_spec(spec), solid_flags(*solid),
                                                        stream, buffer.data(), buffer.size() * 8)
                       : conductor.begin_streamed(band_spec(spec), margin, stream, buffer.data(),
                                                  buffer.size() * 8);
  return ok(s) ? run_motion(spec, &conductor, trace, r) : s;
}

}  // namespace haloplot::host
