// Every format at its extremes. Run under the host-asan preset, UBSan traps any signed
// overflow on the way; here we also check the answers (or the named refusals).
#include <cstdio>
#include <string>

#include "../check.h"
#include "../reference/brute_cut.h"
#include "../support/plot.h"
#include "../support/run_core.h"
#include "../support/scenes.h"
#include "haloplot/geometry/fraction.h"
#include "haloplot/motion/planner.h"
#include "haloplot/motion/step_prep.h"
#include "haloplot/motion/step_segment.h"

using namespace haloplot;
using scenes::edge;

static void sane(const std::vector<Span>& spans, uint32_t n, const std::string& label) {
  bool good = true;
  for (const Span& s : spans)
    good = good && s.t0 >= 0 && s.t1 <= (int64_t{1} << 32) && s.t0 <= s.t1 && s.edge < n &&
           in_range(Point3{s.x0, s.y0, 0}) && in_range(Point3{s.x1, s.y1, 0});
  CHECK_MSG(good, label + ": spans out of range");
}

// Plan and prep a whole path; returns the first status (kOk when it ran to the end).
static Status run_motion(const Machine& m, const std::vector<PathPoint>& pts,
                         const PlotterEffects& fx) {
  std::vector<uint64_t> ws(MotionPlanner::workspace_bytes(fx) / 8 + 1);
  MotionPlanner planner;
  Status s = planner.init(m, fx, pts.data(), uint32_t(pts.size()), ws.data(), ws.size() * 8);
  if (!ok(s)) return s;
  StepPrep prep;
  s = prep.init(m, fx);
  if (!ok(s)) return s;
  SegmentQueue<64> q;
  while (!prep.done()) {
    s = prep.fill(planner, q);
    if (!ok(s)) return s;
    while (!q.empty()) q.pop();  // the tick's side is not under test here
  }
  return Status::kOk;
}

int main() {
  const int32_t M = kCoordMax;
  // 1. CUT on the range's corners, diagonals and one-step offsets, every depth at an end.
  std::vector<Edge3> e;
  const int32_t v[] = {0, 1, M - 1, M};
  for (int32_t a : v)
    for (int32_t b : v) {
      // Every line passes through the centre; each family has its own depths there, so
      // crossings between the families are decided at the extremes of the depth range.
      e.push_back(edge(0, a, b, M, M - a, b));
      e.push_back(edge(a, 0, M - b, M - a, M, M - b));
    }
  const auto ref = reference::brute_cut(e).records;
  host::HostCut c;
  CHECK(ok(host::host_cut(e, CutParams{}, &c)));
  CHECK(support::records_of(c.set) == ref);
  std::printf("extreme scene: %zu crossings\n", ref.size());
  CHECK(ref.size() > 20);
  // 2. DRAW with the largest halo, both modes, and the exact halo with the largest reach.
  for (HaloMode mode : {HaloMode::kPaper, HaloMode::kExact}) {
    const auto p = support::plot(e, M, mode, mode == HaloMode::kExact ? M : 0);
    sane(p.spans, uint32_t(e.size()), "halo 2^20 - 1");
    const auto q = support::plot(e, 1, mode, mode == HaloMode::kExact ? 1 : 0);
    sane(q.spans, uint32_t(e.size()), "halo 1");
  }
  // 3. Positions at the ends of the Q0.32 range.
  CHECK_EQ(lerp_round(0, M, int64_t{1} << 32), M);
  CHECK_EQ(lerp_round(M, -M, int64_t{1} << 32), 0);
  CHECK_EQ(lerp_round(M, -M, 0), M);
  CHECK_EQ(q32_floor_clamped(int64_t{1} << 60, 1), int64_t{2} << 32);
  CHECK_EQ(q32_ceil_clamped(-(int64_t{1} << 60), 1), -(int64_t{2} << 32));
  // 4. Motion at the extremes: the fastest machine the budgets allow over the whole range,
  //    and the slowest, whose first step from rest needs longer than the tick's 32-bit field.
  const std::vector<PathPoint> path = {{0, 0, 0}, {M, M, 1}, {0, M, 1}, {M, 0, 0}, {0, 0, 1}};
  for (Kinematics k : {Kinematics::kCartesian, Kinematics::kCoreXY}) {
    Machine fast;
    fast.kinematics = k;
    fast.steps_num = 16;
    fast.tick_hz = (1u << 24) - 1;
    fast.min_interval = 1;
    fast.max_step_rate = 10000000;
    fast.draw_speed = fast.travel_speed = 65535;
    fast.accel = (1u << 22) - 1;
    fast.junction_deviation = 65535;
    fast.backlash[0] = fast.backlash[1] = 1000;
    CHECK(ok(validate(fast)));
    CHECK_EQ(status_name(run_motion(fast, path, PlotterEffects{true, true, true})),
             std::string("ok"));
    CHECK_EQ(status_name(run_motion(fast, path, PlotterEffects{false, false, false})),
             std::string("ok"));
    Machine slow = fast;  // 1 step/s at 16.7 MHz: 2^32 Q8 ticks per step, past the tick's int32
    slow.steps_num = 1;
    slow.draw_speed = slow.travel_speed = 1;
    slow.accel = 1;
    const Status slow_status = run_motion(slow, path, PlotterEffects{true, true, false});
    std::printf("slow machine: %s\n", status_name(slow_status));
    CHECK(slow_status == Status::kIntervalTooLong);
    Machine floor = fast;
    floor.min_interval = 2;  // 16.7 M ticks/s at 2 ticks per step: 8.4 M steps/s allowed
    floor.max_step_rate = 1000000;
    CHECK(validate(floor) == Status::kStepRateExceeded);  // 65535 * 16 > 1 M steps/s
  }
  return check::finish("overflow");
}
