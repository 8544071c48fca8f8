// What an integrator's image links for one kind of plot: the smallest programs that plot a
// scene from its edges to the step tick, linked (not run) so their .text can be compared and
// their symbols checked (firmware/check_no_solid.cmake, tests/rules/lean_link_test.sh). One
// source, three programs, each through the planner, step prep and step tick alike:
//   LEAN_PLOT == 1  haloed, unbanded: job_prepare (CUT, DRAW and the path on the whole scene);
//   LEAN_PLOT == 2  haloed, in bands: BandConductor::begin, the same stages band by band;
//   LEAN_PLOT == 3  a solid's hidden lines in bands: begin_solid, the solid stages too.
// An edges-only banded plot must cost about what the unbanded one does, not drag in the solid
// model's stages it never runs.
#include "haloplot/band/conductor.h"
#include "haloplot/job/job.h"
#include "haloplot/motion/planner.h"
#include "haloplot/motion/step_engine.h"
#include "haloplot/motion/step_prep.h"
#include "haloplot/motion/virtual_run.h"

using namespace haloplot;

#ifndef LEAN_PLOT
#error "LEAN_PLOT selects the program (1, 2 or 3)"
#endif

namespace {

// Three crossing edges, so CUT has records and DRAW cuts gaps.
const Edge3 kScene[] = {{{100, 100, 10}, {900, 900, 10}},
                        {{100, 900, 20}, {900, 100, 20}},
                        {{500, 50, 5}, {520, 950, 30}}};
constexpr uint32_t kEdges = sizeof kScene / sizeof kScene[0];
alignas(8) uint8_t arena[16 * 1024];
alignas(8) uint8_t planner_ws[MotionPlanner::workspace_bytes(PlotterEffects{})];

// A step HAL that writes "pins" the compiler must keep.
struct PinHal {
  uint64_t now = 0;
  volatile uint32_t pins = 0;
  void step(uint8_t m) { pins = pins ^ (1u << m); }
  void set_direction(uint8_t m, bool b) { pins = b ? pins | (4u << m) : pins & ~(4u << m); }
  void pen(bool down) { pins = down ? pins | 16u : pins & ~16u; }
};

MotionPlanner planner;
StepPrep prep;
SegmentQueue<64> queue;
PinHal pins;
#if LEAN_PLOT != 1
BandConductor conductor;
#endif

Status prepare(const JobSpec& job, PreparedJob* prepared) {
#if LEAN_PLOT == 1
  JobCounters counters;
  return job_prepare(job, Edges{kScene, kEdges}, 16, arena, sizeof arena, prepared, &counters);
#else
  BandSpec spec = band_spec(job);
#if LEAN_PLOT == 2
  Status s = conductor.begin(spec, array_edge_source(kScene, kEdges), arena, sizeof arena);
#else
  // The edges as a solid with one triangle: enough to link the solid stages.
  static const Point3 vertices[] = {kScene[0].a, kScene[0].b, kScene[1].a, kScene[1].b};
  static const uint32_t pairs[] = {0, 1, 2, 3};
  static const Triangle triangles[] = {{{0, 1, 2}, 0}};
  static SolidInput in;
  in.vertices = vertices;
  in.n_vertices = 4;
  in.edge_pairs = pairs;
  in.n_edges = 2;
  in.triangles = triangles;
  in.n_triangles = 1;
  spec.style.mode = SolidMode::kHiddenRemoved;
  Status s = conductor.begin_solid(spec, array_solid_source(&in, false), arena, sizeof arena);
#endif
  prepared->feed = PointFeed{&BandConductor::feed, &conductor};
  return s;
#endif
}

}  // namespace

int main() {
  JobSpec job;
  job.draw = DrawParams{50, HaloMode::kPaper};
  PreparedJob prepared;
  Status s = prepare(job, &prepared);
  if (ok(s)) s = init_planner(&planner, job, prepared, planner_ws, sizeof planner_ws);
  if (ok(s)) s = prep.init(job.machine, job.effects);
  StepEngine<PinHal, SegmentQueue<64>> engine(pins, queue);
  if (ok(s)) s = run_virtual(planner, prep, queue, pins, engine);
  return ok(s) ? int(engine.events()) : -1;
}
