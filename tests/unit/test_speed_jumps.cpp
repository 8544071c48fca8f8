// Motion a real plotter can follow: no motor's speed changes at one step by more than the
// acceleration allows (plus whole-tick rounding), except at the path's vertices, where grbl's
// junction speed bounds it instead (tests/reference/trace_checker.h, check_step_speeds).
//   - the checker sees the defect: a straight cruise with one 5 % jump fails, the same cruise
//     without it passes, and a jump at a right-angle vertex passes only within grbl's bound;
//   - the README's demo (Figure 4 on its CoreXY machine) and a hidden-dashed solid with
//     backlash have no jump;
//   - triangular moves peak where acceleration and deceleration meet (the middle).
#include <cmath>
#include <fstream>
#include <sstream>

#include "../check.h"
#include "../reference/trace_checker.h"
#include "cli/job_file.h"
#include "cli/scene_input.h"
#include "demo/cube_array.h"
#include "sim/simulator.h"
#include "support/motion_jobs.h"
#include "support/trace_limits.h"

using namespace haloplot;
using namespace haloplot::host;

namespace {

// A cartesian trace: motor 0 cruising along x at `interval` ticks, and `jump_at` steps in,
// either the interval becomes `after` (a straight line), or the path turns 45 degrees to the
// diagonal with both motors at `after` ticks a step.
std::string cruise_trace(int steps, int interval, int jump_at, int after, bool turn) {
  std::ostringstream t;
  t << "haloplot-trace 1\ntick_hz 1000000\nkinematics cartesian\nsteps 1/1\nbacklash 0 0\n";
  t << "m 0 1000 " << jump_at << " " << interval << " 0 +\n";
  const int64_t t1 = 1000 + int64_t(jump_at - 1) * interval + after;
  const int rest = steps - jump_at;
  t << "m 0 " << t1 << " " << rest << " " << after << " 0 +\n";
  if (turn) t << "m 1 " << t1 << " " << rest << " " << after << " 0 +\n";
  t << "end " << t1 + int64_t(rest) * after << "\n";
  return t.str();
}

void checker_sees_a_jump() {
  reference::Limits lim;
  lim.max_step_rate = 25000;
  lim.min_interval = 25;
  lim.motor_accel = 60000;
  lim.window = 20000;
  lim.plot_accel = 60000;
  lim.junction_deviation = 4;
  lim.path = {{0, 0}, {200, 0}};
  auto run = [&](const std::string& text) {
    return reference::check_trace(reference::parse_trace_independently(text), lim);
  };
  // 400 ticks = 2,500 steps/s; 60,000 steps/s^2 allow 24 steps/s (1 %) over one interval.
  const auto smooth = run(cruise_trace(200, 400, 100, 400, false));
  CHECK_MSG(smooth.step_jumps == 0, "a steady cruise passes: " + smooth.why);
  const auto jump = run(cruise_trace(200, 400, 100, 420, false));  // 2,500 -> 2,381: -4.8 %
  CHECK_MSG(jump.step_jumps == 1 && !jump.ok, "one 5 % jump on a straight line fails");
  CHECK(jump.worst_step_ratio > 3);
  const auto up = run(cruise_trace(200, 420, 100, 400, false));  // +5 %
  CHECK_MSG(up.step_jumps == 1, "one 5 % jump up fails");
  // A 45-degree turn at (100, 0): the path keeps its speed, motor 0 drops to 1/sqrt(2) of it
  // and motor 1 starts. grbl allows the turn at its junction speed sqrt(a delta s / (1 - s)),
  // s = sin(67.5 deg): 1,709 steps/s, so motor 0 may lose 0.29 of that, 501 steps/s.
  lim.path = {{0, 0}, {100, 0}, {200, 100}};
  const auto fast = run(cruise_trace(200, 400, 100, 566, true));  // 2,500 steps/s: -732
  CHECK_MSG(fast.step_jumps > 0, "a turn taken at 2,500 steps/s breaks grbl's bound");
  const auto slow = run(cruise_trace(200, 625, 100, 884, true));  // 1,600 steps/s: -469
  CHECK_MSG(slow.step_jumps == 0 && slow.junctions_excused > 0,
            "a turn within grbl's junction speed passes: " + slow.why);
  // The same drop 30 steps away from the vertex is a jump.
  lim.path = {{0, 0}, {70, 0}, {170, 100}};
  CHECK_MSG(run(cruise_trace(200, 625, 100, 884, true)).step_jumps > 0,
            "a drop away from the vertex fails");
}

void no_jump(const std::string& label, const JobSpec& spec, const std::vector<Edge3>& edges) {
  std::ostringstream out;
  SimReport r;
  const Status s = simulate(spec, edges, &out, &r);
  CHECK_MSG(ok(s), label + ": " + status_name(s));
  const auto parsed = reference::parse_trace_independently(out.str());
  const auto res = reference::check_trace(parsed, test::trace_limits(spec, r.points));
  CHECK_MSG(res.step_jumps == 0, label + ": " + res.why);
  CHECK_MSG(res.worst_step_ratio > 0.5, label + ": the check measured the ramps");
  std::printf("%s: %zu steps, worst speed change at one step %.3f of the bound, %llu junctions\n",
              label.c_str(), parsed.step_tick[0].size() + parsed.step_tick[1].size(),
              res.worst_step_ratio, (unsigned long long)res.junctions_excused);
}

void demo_and_solid_have_no_jump() {
  CubeArrayParams p;
  p.cubes = 28;
  no_jump("Figure 4", test::demo_job_spec(), cube_array(p));
  std::vector<Edge3> strokes;
  const JobSpec spec = test::cubes_with_backlash_job("speed_jumps_cubes.job", &strokes);
  no_jump("pair of cubes, hidden-dashed, backlash", spec, strokes);
}

// One pen-up travel from rest to rest: the dominant motor's peak speed lies at the middle of
// the move, within two steps, for lengths with and without a cruise.
void triangles_peak_in_the_middle() {
  for (int32_t len : {37, 80, 151, 400, 900, 1200}) {  // triangles, then a short cruise
    JobSpec spec;
    spec.drawing = DrawingEffect::kAllEdges;
    spec.effects.pen_servo = false;
    spec.finish_home = false;  // the one travel alone
    spec.clean.on = false;     // to a lone dot, which the planner's clean-up would drop
    const int32_t x = 1000 + len, y = 1000 + len / 3;
    std::ostringstream out;
    SimReport r;
    CHECK(ok(simulate(spec, {Edge3{{x, y, 0}, {x, y, 0}}}, &out, &r)));
    const auto t = reference::parse_trace_independently(out.str());
    const auto& ticks = t.step_tick[0];  // x dominates the travel from the origin
    CHECK_EQ(ticks.size(), size_t(x));
    // The fastest intervals: the peak of a triangle, the cruise of a trapezoid (ticks are
    // whole, so a peak a little flat). From rest to rest the profile is symmetric: the middle
    // of the first and last fastest interval is the middle of the move.
    int64_t fastest = INT64_MAX;
    for (size_t k = 1; k < ticks.size(); ++k) fastest = std::min(fastest, ticks[k] - ticks[k - 1]);
    size_t first = 0, last = 0;
    for (size_t k = 1; k < ticks.size(); ++k)
      if (ticks[k] - ticks[k - 1] == fastest) {
        if (first == 0) first = k;
        last = k;
      }
    const double middle = 0.5 * double(first + last), n = double(ticks.size());
    CHECK_MSG(std::abs(middle - 0.5 * n) <= 2.0,
              "travel of " + std::to_string(x) + " steps peaks at step " + std::to_string(middle));
  }
}

}  // namespace

int main() {
  checker_sees_a_jump();
  demo_and_solid_have_no_jump();
  triangles_peak_in_the_middle();
  return check::finish("speed_jumps");
}
