// Streamed bands: a controller that never holds the scene. The host runs the band conductor
// over the whole scene with the controller's arena and sends each band's edges; the controller
// (here the same core on the host, fed by a stream that is often not ready yet) must draw the
// same plot: its step trace equals `haloplot sim` of the same job with the same arena, byte for
// byte, however often the plot waits for a band. A band with an edge missing must show.
#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "band/conductor.h"
#include "check.h"
#include "demo/cube_array.h"
#include "motion/planner.h"
#include "motion/step_engine.h"
#include "motion/step_prep.h"
#include "motion/virtual_run.h"
#include "pipeline/band_stream.h"
#include "sim/simulator.h"
#include "trace/trace_encoder.h"

using namespace haloplot;
using namespace haloplot::host;

namespace {

constexpr size_t kArena = 64 * 1024;

struct StringHal {
  uint64_t now = 0;
  bool backward[2] = {false, false};
  TraceEncoder* trace = nullptr;
  void set_direction(uint8_t m, bool b) { backward[m] = b; }
  void step(uint8_t m) { trace->step(now, m, backward[m]); }
  void pen(bool down) { trace->pen(now, down); }
};

// The controller's side: the streamed bands through the planner and the step tick.
Status run_streamed(const JobSpec& job, const BandSpec& spec, const BandPlan& plan,
                    PlanStream* stream, std::string* trace) {
  std::vector<uint64_t> arena(kArena / 8);
  BandConductor conductor;
  Status s = conductor.begin_streamed(spec, plan.margin, stream->stream(), arena.data(), kArena);
  if (!ok(s)) return s;
  std::vector<uint64_t> ws(MotionPlanner::workspace_bytes(job.effects) / 8 + 1);
  MotionPlanner planner;
  s = planner.init(job.machine, job.effects, nullptr, 0, ws.data(), ws.size() * 8);
  if (!ok(s)) return s;
  planner.set_feed(PointFeed{&BandConductor::feed, &conductor});
  StepPrep prep;
  s = prep.init(job.machine, job.effects);
  if (!ok(s)) return s;
  TraceEncoder encoder(CharSink{[](void* ctx, const char* text, uint32_t n) {
                                  static_cast<std::string*>(ctx)->append(text, n);
                                },
                                trace},
                       job.machine);
  StringHal hal;
  hal.trace = &encoder;
  SegmentQueue<64> queue;
  StepEngine<StringHal, SegmentQueue<64>> engine(hal, queue);
  s = run_virtual(planner, prep, queue, hal, engine);
  if (!ok(s)) return s;
  encoder.finish(hal.now);
  return Status::kOk;
}

}  // namespace

int main() {
  // The README's demo job: Figure 4, halo 50, the demo machine (scenes/demo.job).
  const std::vector<Edge3> edges = cube_array(CubeArrayParams{});
  JobSpec job;
  job.draw = DrawParams{50, HaloMode::kPaper};
  job.machine.kinematics = Kinematics::kCoreXY;
  std::ostringstream reference;
  SimReport report;
  CHECK(simulate(job, edges, &reference, &report, kArena) == Status::kOk);
  BandSpec spec;
  spec.draw = job.draw;
  spec.cut = job.cut;
  BandPlan plan;
  CHECK(plan_streamed_bands(edges, spec, kArena, &plan) == Status::kOk);
  CHECK_EQ(plan.bands.size(), size_t(report.bands.bands));
  CHECK(plan.bands.size() > 1);
  size_t sent = 0;
  for (const PlannedBand& b : plan.bands) sent += b.edges.size();
  std::printf("figure 4 streamed: %zu bands, %zu edges sent for %zu (%.2fx), margin %d\n",
              plan.bands.size(), sent, edges.size(), double(sent) / double(edges.size()),
              plan.margin);

  for (int busy : {0, 3}) {
    PlanStream stream;
    stream.plan = &plan;
    stream.busy_every = stream.busy_left = busy;
    std::string trace;
    const Status s = run_streamed(job, spec, plan, &stream, &trace);
    CHECK_MSG(ok(s), std::string("streamed run: ") + status_name(s));
    CHECK_MSG(trace == reference.str(),
              "streamed trace (" + std::to_string(trace.size()) + " bytes, waited " +
                  std::to_string(stream.busy_answers) + " times) equals haloplot sim's (" +
                  std::to_string(reference.str().size()) + " bytes)");
    if (busy > 0) CHECK(stream.busy_answers >= plan.bands.size());
  }
  // A band sent without one of the edges that lie wholly in its rows: the plot must not come out
  // the same.
  {
    BandPlan broken = plan;
    PlannedBand& b = broken.bands[broken.bands.size() / 2];
    size_t k = 0;
    while (k < b.edges.size() &&
           !(std::min(b.edges[k].a.y, b.edges[k].b.y) >= b.y0 &&
             std::max(b.edges[k].a.y, b.edges[k].b.y) < b.y1))
      ++k;
    CHECK(k < b.edges.size());
    b.edges.erase(b.edges.begin() + long(k));
    b.ids.erase(b.ids.begin() + long(k));
    PlanStream stream;
    stream.plan = &broken;
    std::string trace;
    const Status s = run_streamed(job, spec, broken, &stream, &trace);
    CHECK_MSG(!ok(s) || trace != reference.str(), "a band missing an edge must change the plot");
  }
  return check::finish("band_stream");
}
