// The host simulator: the core's job, motion planner, step prep and step tick, driven in
// virtual time, with a recording HAL that streams every step and pen change into a trace.
#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "haloplot/band/conductor.h"
#include "haloplot/job/job.h"
#include "haloplot/motion/planner.h"
#include "haloplot/motion/step_prep.h"
#include "haloplot/trace/trace_encoder.h"
#include "pipeline/band_stream.h"

namespace haloplot::host {

struct SimReport {
  JobBytes bytes;
  size_t planner_bytes = 0;
  JobCounters job;
  PlannerCounters planner;
  PrepCounters prep;
  uint64_t end_tick = 0;
  uint64_t steps[2] = {0, 0};
  uint64_t min_gap[2] = {UINT64_MAX, UINT64_MAX};  // ticks between steps of one motor
  uint32_t pen_lifts = 0;
  uint64_t holds = 0;  // feed holds that came to rest
  int retries = 0;
  std::vector<PathPoint> points;  // the planned path (for the exporters)
  std::vector<Segment2> spans;    // what DRAW emitted (for checks)
  LayerCounts layer_points;       // the points of each layer (none: one layer, or bands)
  int32_t final_motors[2] = {0, 0};
  size_t arena_bytes = 0;  // > 0: the plot ran in bands in this arena, as on the controller
  BandStats bands;
  std::vector<uint64_t> band_ticks;  // the tick at which each band was asked for
};

// Runs the whole job and writes the trace to `trace` (may be null). Returns the first status
// that stopped it. With arena_bytes > 0 the drawing runs in bands in an arena of that size
// (band/conductor.h), exactly as a controller with that arena runs it; 0: one job buffer sized
// for the whole scene. The trace is text, or the binary form of the same records.
// pause_at: feed holds (motion/virtual_run.h HoldSchedule), each asked for once the plot has
// made that many step events, and resumed at rest; ascending. resume_at > 0: the plot goes on
// from where a run of it stopped after that many step events (an abort), as the controller
// does after `haloplot send --resume` (motion/virtual_run.h skip_events).
// `curves` (not empty): the scene's Bézier edges, `edges` its straight ones, drawn haloed by
// the core's curve job (job/job.h job_prepare_curves) as the controller draws them, or with
// an arena in bands (band/curve_bands.h), as a controller with that arena draws them.
Status simulate(const JobSpec& spec, const std::vector<Edge3>& edges, std::ostream* trace,
                SimReport* report, size_t arena_bytes = 0, TraceForm form = TraceForm::kText,
                const std::vector<uint32_t>& pause_at = {}, uint32_t resume_at = 0,
                const std::vector<BezierEdge3>* curves = nullptr);

// The same with the bands streamed in (band/conductor.h begin_streamed), as a controller that
// receives them over its link runs it: the stream may make the plot wait (kBusy).
// A solid's hidden-line drawing (spec.drawing kHiddenRemoved or kHiddenDashed) in bands, as a
// controller with that arena plots it (band/conductor.h begin_solid); `closed` is the model's
// check (solid_pipeline.h model_closed).
Status simulate_solid(const JobSpec& spec, const SolidInput& in, bool closed, std::ostream* trace,
                      SimReport* report, size_t arena_bytes, TraceForm form = TraceForm::kText,
                      const std::vector<uint32_t>& pause_at = {}, uint32_t resume_at = 0);

// The same with the bands streamed in (band/conductor.h begin_streamed), as a controller that
// receives them over its link runs it: the stream may make the plot wait (kBusy). `solid`: the
// plan of a solid's bands (plan_streamed_solid), whose closedness the controller is told.
Status simulate_streamed(const JobSpec& spec, BandStream stream, int32_t margin, size_t arena_bytes,
                         std::ostream* trace, SimReport* report, const BandPlan* solid = nullptr);

}  // namespace haloplot::host
