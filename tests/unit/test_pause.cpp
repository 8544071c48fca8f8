// Feed hold (pause and resume, core/include/haloplot/motion/step_prep.h) checked from the traces
// alone, by the independent reader (tests/reference/trace_checker.h):
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
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

#include "../check.h"
#include "../reference/trace_checker.h"
#include "cli/job_file.h"
#include "cli/scene_input.h"
#include "demo/cube_array.h"
#include "sim/simulator.h"
#include "support/motion_jobs.h"
#include "support/pen_drawing.h"
#include "support/trace_limits.h"

using namespace haloplot;
using namespace haloplot::host;

namespace {

struct Run {
  reference::CheckedTrace trace;
  SimReport report;
};

Run run(const JobSpec& spec, const std::vector<Edge3>& edges, const std::vector<uint32_t>& holds,
        uint32_t resume_at = 0) {
  std::ostringstream out;
  Run r;
  const Status s = simulate(spec, edges, &out, &r.report, 0, TraceForm::kText, holds, resume_at);
  CHECK_MSG(ok(s), std::string("simulate: ") + status_name(s));
  r.trace = reference::parse_trace_independently(out.str());
  CHECK_MSG(r.trace.error.empty(), "the paused trace reads: " + r.trace.error);
  return r;
}

// Step events (what --pause-at counts): the steps of one event share its tick.
uint64_t step_events(const reference::CheckedTrace& t) {
  std::vector<int64_t> ticks(t.step_tick[0].begin(), t.step_tick[0].end());
  ticks.insert(ticks.end(), t.step_tick[1].begin(), t.step_tick[1].end());
  std::sort(ticks.begin(), ticks.end());
  return uint64_t(std::unique(ticks.begin(), ticks.end()) - ticks.begin());
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
  const uint64_t events = step_events(plain.trace);
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

// The demo (Figure 4, 28 x 28 cubes) at 100 moments; `small` (under the sanitizers, ten times
// slower): 6 x 6 cubes at 30, the same strokes, travel and pen moves to hold in, fewer of them.
void demo_paused(bool small) {
  CubeArrayParams p;
  p.cubes = small ? 6 : 28;
  paused_equals_unpaused(small ? "6 x 6 cubes" : "Figure 4", test::demo_job_spec(), cube_array(p),
                         small ? 30 : 100);
}

void solid_with_backlash_paused(uint32_t holds) {
  std::vector<Edge3> strokes;
  const JobSpec spec = test::cubes_with_backlash_job("pause_cubes.job", &strokes);
  paused_equals_unpaused("pair of cubes, hidden-dashed, backlash", spec, strokes, holds);
}

// Long lines whose other CoreXY motor runs slowly (dx 1000 : dy 900 makes motor B a tenth of
// motor A), held at 24 moments mid-line: a braking stretch that restarted the move's
// Bresenham moved motor B's next step by up to a step's time (a speed jump at one step of
// 1.6-3.4x the bound before the stretch kept the move's block).
void slow_minor_motor_paused() {
  std::vector<Edge3> lines;
  for (int32_t k = 0; k < 6; ++k)
    lines.push_back(Edge3{{400 + 500 * k, 400, 0}, {10400 + 500 * k, 9400, 0}});
  paused_equals_unpaused("six lines with a slow motor", test::demo_job_spec(), lines, 24);
}

// An abort after E step events (the plot's first E events: an abort just stops), then the
// plot resumed from E after a reset (from the origin): together they draw the uninterrupted
// plot, each pen-down step exactly once, and the resumed run keeps the speed bound.
void resumed_after_abort(const std::string& label, const JobSpec& spec,
                         const std::vector<Edge3>& edges, uint32_t count) {
  const Run plain = run(spec, edges, {});
  const uint64_t events = step_events(plain.trace);
  const std::vector<test::InkedStep> plain_ink = test::inked_steps(plain.trace);
  const test::Drawn whole = test::drawn(plain_ink);
  reference::Limits lim = test::trace_limits(spec, plain.report.points);
  lim.dwell =
      spec.effects.pen_servo ? spec.machine.pen_travel_ticks + spec.machine.pen_settle_ticks : 0;
  double worst = 0;
  uint32_t gaps_seen = 0;
  for (uint32_t stop : random_holds(events, count, 11)) {
    const Run resumed = run(spec, edges, {}, stop);
    const test::Drawn before = test::drawn(plain_ink, stop);
    const test::Drawn after = test::drawn(resumed.trace);
    test::Drawn both = before;
    both.add(after);
    std::string why;
    const bool same = test::same_drawing(both, whole, &why);
    CHECK_MSG(same, label + ", stopped after " + std::to_string(stop) + " events: " + why);
    // The check sees a gap: the aborted part cut short by a tenth leaves ink out (when that
    // tenth drew any).
    test::Drawn short_by = test::drawn(plain_ink, stop - stop / 10);
    if (short_by.steps[0] + short_by.steps[1] < before.steps[0] + before.steps[1]) {
      short_by.add(after);
      CHECK_MSG(!test::same_drawing(short_by, whole, &why),
                label + ": a resume that leaves a gap compares equal");
      ++gaps_seen;
    }
    // A path that starts with the travel from the origin: its vertices for the junctions.
    reference::Limits lr = lim;
    lr.path.insert(lr.path.begin(), {0, 0});
    const auto res = reference::check_trace(resumed.trace, lr);
    CHECK_MSG(res.step_jumps == 0 && res.dwell_violations == 0,
              label + ", resumed after " + std::to_string(stop) + ": " + res.why);
    worst = std::max(worst, res.worst_step_ratio);
  }
  std::printf(
      "%s: %u aborts resumed, the two parts draw the whole plot, worst speed change at "
      "one step %.3f of the bound (a gap seen %u times)\n",
      label.c_str(), count, worst, gaps_seen);
  CHECK_MSG(gaps_seen > 0, label + ": the gap check never ran");
}

// The comparison is not blind: Figure 4 at another halo width draws differently.
void comparison_sees_a_difference() {
  CubeArrayParams p;
  p.cubes = 4;
  JobSpec a = test::demo_job_spec(), b = test::demo_job_spec();
  b.draw.halo = 80;
  std::string why;
  CHECK_MSG(!test::same_drawing(test::drawn(run(a, cube_array(p), {}).trace),
                                test::drawn(run(b, cube_array(p), {}).trace), &why),
            "halo 50 and halo 80 compare equal");
  std::printf("halo 50 against 80: %s\n", why.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  const bool small = argc > 1 && std::string(argv[1]) == "small";
  comparison_sees_a_difference();
  demo_paused(small);
  solid_with_backlash_paused(small ? 12 : 40);
  slow_minor_motor_paused();
  // 4 x 4 cubes in both builds: an abort and a resume meet the step stream at one event, and
  // 16 cubes already give each of the 12 moments strokes, travel and pen moves to land in
  // (6 x 6 cubes proved nothing more at twice the time).
  CubeArrayParams p;
  p.cubes = 4;
  resumed_after_abort("4 x 4 cubes", test::demo_job_spec(), cube_array(p), small ? 6 : 12);
  std::vector<Edge3> strokes;
  const JobSpec spec = test::cubes_with_backlash_job("resume_cubes.job", &strokes);
  resumed_after_abort("pair of cubes, hidden-dashed, backlash", spec, strokes, small ? 3 : 8);
  return check::finish("pause");
}
