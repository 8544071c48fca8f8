// Feed hold (pause and resume, core/motion/step_prep.h) checked from the traces alone, by the
// independent reader (tests/reference/trace_checker.h):
//   - the README's demo (Figure 4 on its CoreXY machine) paused at 100 random moments, and a
//     hidden-dashed solid with backlash paused at 40: every hold comes to rest within the
//     acceleration limit (no speed change at one step beyond what accel allows, away from the
//     path's vertices; no step while the pen moves), the pen is lifted at rest and lowered
//     where it was lifted;
//   - the pen-down motion is the uninterrupted run's: every position drawn in one is within a
//     step of a position drawn in the other, both ways, and each motor makes exactly as many
//     pen-down steps (nothing drawn twice, nothing left out);
//   - the comparison sees a difference: a plot of a different halo width fails it.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <random>
#include <set>
#include <sstream>

#include "../check.h"
#include "../reference/trace_checker.h"
#include "demo/cube_array.h"
#include "io/job_file.h"
#include "pipeline/scene_input.h"
#include "sim/simulator.h"
#include "support/pen_drawing.h"
#include "support/trace_limits.h"

using namespace haloplot;
using namespace haloplot::host;

namespace {

struct Run {
  reference::CheckedTrace trace;
  SimReport report;
};

Run run(const JobSpec& spec, const std::vector<Edge3>& edges, const std::vector<uint32_t>& holds) {
  std::ostringstream out;
  Run r;
  const Status s = simulate(spec, edges, &out, &r.report, 0, TraceForm::kText, holds);
  CHECK_MSG(ok(s), std::string("simulate: ") + status_name(s));
  r.trace = reference::parse_trace_independently(out.str());
  CHECK_MSG(r.trace.error.empty(), "the paused trace reads: " + r.trace.error);
  return r;
}

// `count` holds at random moments, one in each of `count` equal stretches of the plot's step
// events (so each comes to rest before the next is asked for).
std::vector<uint32_t> random_holds(uint64_t events, uint32_t count, uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<uint32_t> at;
  const uint64_t stretch = events / count;
  for (uint32_t k = 0; k < count; ++k)
    at.push_back(uint32_t(k * stretch + rng() % (stretch / 2)));  // the first half: room to stop
  return at;
}

void paused_equals_unpaused(const std::string& label, const JobSpec& spec,
                            const std::vector<Edge3>& edges, uint32_t count) {
  const Run plain = run(spec, edges, {});
  // Step events (what --pause-at counts): the steps of one event share its tick.
  std::set<int64_t> ticks(plain.trace.step_tick[0].begin(), plain.trace.step_tick[0].end());
  ticks.insert(plain.trace.step_tick[1].begin(), plain.trace.step_tick[1].end());
  const uint64_t events = ticks.size();
  const std::vector<uint32_t> at = random_holds(events, count, 7);
  const Run paused = run(spec, edges, at);
  CHECK_MSG(paused.report.holds == count, label + ": " + std::to_string(paused.report.holds) +
                                              " of " + std::to_string(count) +
                                              " holds came to rest");
  reference::Limits lim = test::trace_limits(spec, plain.report.points);
  lim.dwell =
      spec.effects.pen_servo ? spec.machine.pen_travel_ticks + spec.machine.pen_settle_ticks : 0;
  // The bound, step by step (check_step_speeds), with the pen dwell and the step rate.
  // Not the checker's windowed second difference: it does not know the path's vertices, and
  // the unpaused plot's junction speeds exceed it already (reported below).
  const auto res = reference::check_trace(paused.trace, lim);
  const auto res_plain = reference::check_trace(plain.trace, lim);
  CHECK_MSG(res.step_jumps == 0 && res.dwell_violations == 0 &&
                res.why.find("too fast") == std::string::npos,
            label + ", paused: " + res.why);
  // Each hold that stopped with the pen down lifted it once and lowered it once.
  const size_t extra_pen = paused.trace.pen.size() - plain.trace.pen.size();
  CHECK_MSG(extra_pen % 2 == 0 && extra_pen > 0 && extra_pen <= 2 * count,
            label + ": " + std::to_string(extra_pen) + " extra pen changes");
  std::string why;
  const bool same = test::same_drawing(test::drawn(paused.trace), test::drawn(plain.trace), &why);
  CHECK_MSG(same, label + ": " + why);
  std::printf(
      "%s: %u holds at rest, %zu pen lifts for them, worst speed change at one step %.3f "
      "of the bound, windowed acceleration %.3f of the limit (unpaused %.3f), plot %.1f s "
      "(unpaused %.1f s)\n",
      label.c_str(), unsigned(paused.report.holds), extra_pen / 2, res.worst_step_ratio,
      res.worst_accel_ratio, res_plain.worst_accel_ratio,
      double(paused.report.end_tick) / spec.machine.tick_hz,
      double(plain.report.end_tick) / spec.machine.tick_hz);
}

JobSpec demo_spec() {
  JobSpec demo;  // the README's demo machine (scenes/demo.job): the defaults, CoreXY
  demo.drawing = DrawingEffect::kHaloed;
  demo.draw.halo = 50;
  demo.draw.mode = HaloMode::kPaper;
  demo.machine.kinematics = Kinematics::kCoreXY;
  return demo;
}

void demo_paused_100_times() {
  CubeArrayParams p;
  p.cubes = 28;
  paused_equals_unpaused("Figure 4", demo_spec(), cube_array(p), 100);
}

void solid_with_backlash_paused() {
  const std::string job = "pause_cubes.job";
  std::ofstream(job) << "scene " HALOPLOT_SOURCE_DIR "/scenes/pair_of_cubes.obj\n"
                     << "drawing hidden-dashed\noutline on\nkinematics corexy\n"
                     << "effects acceleration pen-servo backlash\nbacklash 7 3\n";
  JobFile jf;
  const InputError e = read_job_file(job, &jf);
  CHECK_MSG(!e.failed(), e.message());
  std::vector<Edge3> strokes;
  std::string error;
  CHECK_MSG(load_job_scene(jf, &strokes, &error), error);
  JobSpec spec = jf.spec;
  spec.drawing = DrawingEffect::kAllEdges;  // the strokes, decided on the host, drawn whole
  paused_equals_unpaused("pair of cubes, hidden-dashed, backlash", spec, strokes, 40);
}

// The comparison is not blind: Figure 4 at another halo width draws differently.
void comparison_sees_a_difference() {
  CubeArrayParams p;
  p.cubes = 4;
  JobSpec a = demo_spec(), b = demo_spec();
  b.draw.halo = 80;
  std::string why;
  CHECK_MSG(!test::same_drawing(test::drawn(run(a, cube_array(p), {}).trace),
                                test::drawn(run(b, cube_array(p), {}).trace), &why),
            "halo 50 and halo 80 compare equal");
  std::printf("halo 50 against 80: %s\n", why.c_str());
}

}  // namespace

int main() {
  comparison_sees_a_difference();
  demo_paused_100_times();
  solid_with_backlash_paused();
  return check::finish("pause");
}
