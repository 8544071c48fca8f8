// Motion and the simulator: path planning covers exactly the input, replay reproduces every
// span within 1 step and nothing else, moves that return home end at 0 steps, the trace
// respects step rate, timer floor, acceleration and pen dwell (independent checker), traces
// are deterministic, and unrequested effects cost nothing.
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "../check.h"
#include "../reference/trace_checker.h"
#include "../support/scenes.h"
#include "../support/test_machine.h"
#include "demo/cube_array.h"
#include "haloplot/motion/step_engine.h"
#include "sim/replay.h"
#include "sim/simulator.h"

using namespace haloplot;
using namespace haloplot::host;

struct Run {
  std::string trace;
  SimReport report;
  Status status;
};

static Run sim(const JobSpec& spec, const std::vector<Edge3>& edges) {
  Run r;
  std::ostringstream out;
  r.status = simulate(spec, edges, &out, &r.report);
  r.trace = out.str();
  return r;
}

static JobSpec base_spec(Kinematics k, uint32_t num, uint32_t den) {
  return test_support::test_machine(k, num, den);
}

// Squared distance from p to segment ab is <= r^2 (exact integers).
static bool near_segment(int64_t px, int64_t py, int64_t ax, int64_t ay, int64_t bx, int64_t by,
                         int64_t r) {
  const int64_t dx = bx - ax, dy = by - ay, wx = px - ax, wy = py - ay, l2 = dx * dx + dy * dy;
  const int64_t t = dx * wx + dy * wy;
  if (l2 == 0 || t <= 0) return wx * wx + wy * wy <= r * r;
  if (t >= l2) return (px - bx) * (px - bx) + (py - by) * (py - by) <= r * r;
  const __int128 c = __int128(dx) * wy - __int128(dy) * wx;
  return c * c <= __int128(r * r) * l2;
}

// A coarse spatial hash of segments for "is this point within r of any of them".
struct SegmentIndex {
  int64_t cell = 64;
  std::map<std::pair<int64_t, int64_t>, std::vector<Segment2>> grid;
  void add(const Segment2& s) {
    for (int64_t cx = std::min(s.x0, s.x1) / cell - 1; cx <= std::max(s.x0, s.x1) / cell + 1; ++cx)
      for (int64_t cy = std::min(s.y0, s.y1) / cell - 1; cy <= std::max(s.y0, s.y1) / cell + 1;
           ++cy)
        grid[{cx, cy}].push_back(s);
  }
  bool near(int64_t x, int64_t y, int64_t r) const {
    auto it = grid.find({x / cell, y / cell});
    if (it == grid.end()) return false;
    for (const Segment2& s : it->second)
      if (near_segment(x, y, s.x0, s.y0, s.x1, s.y1, r)) return true;
    return false;
  }
};

static void check_replay(const Run& run, const std::string& label) {
  std::istringstream in(run.trace);
  Trace t;
  const InputError e = read_trace(in, "t", &t);
  CHECK_MSG(!e.failed(), label + ": " + e.message());
  const Replay rep = replay(t);
  const int64_t S = rep.scale;  // replayed points are exact, in 1/S plot steps
  SegmentIndex spans, drawn;
  spans.cell = drawn.cell = 64 * S;
  for (const Segment2& s : run.report.spans)
    spans.add(Segment2{int32_t(s.x0 * S), int32_t(s.y0 * S), int32_t(s.x1 * S), int32_t(s.y1 * S)});
  size_t stray = 0, missing = 0, points = 0;
  for (const auto& stroke : rep.strokes) {
    for (size_t i = 0; i < stroke.size(); ++i) {
      ++points;
      if (!spans.near(stroke[i].x, stroke[i].y, S)) ++stray;  // drew nothing else
      if (i > 0)
        drawn.add(Segment2{int32_t(stroke[i - 1].x), int32_t(stroke[i - 1].y), int32_t(stroke[i].x),
                           int32_t(stroke[i].y)});
    }
    if (stroke.size() == 1)
      drawn.add(Segment2{int32_t(stroke[0].x), int32_t(stroke[0].y), int32_t(stroke[0].x),
                         int32_t(stroke[0].y)});
  }
  for (const Segment2& s : run.report.spans) {  // every span, sampled every step, was drawn
    const int64_t len = std::max(std::abs(s.x1 - s.x0), std::abs(s.y1 - s.y0));
    for (int64_t k = 0; k <= len; ++k) {
      const int64_t x = len ? s.x0 * S + (s.x1 - s.x0) * S * k / len : s.x0 * S;
      const int64_t y = len ? s.y0 * S + (s.y1 - s.y0) * S * k / len : s.y0 * S;
      if (!drawn.near(x, y, S)) ++missing;
    }
  }
  CHECK_MSG(points > 100, label + ": too few replayed points");
  CHECK_MSG(stray == 0, label + ": " + std::to_string(stray) + " replayed points off every span");
  CHECK_MSG(missing == 0, label + ": " + std::to_string(missing) + " span points never drawn");
}

static reference::Limits limits_of(const Machine& m, bool corexy, uint64_t dwell) {
  reference::Limits l;
  l.max_step_rate = m.max_step_rate;
  l.min_interval = m.min_interval;
  l.motor_accel = double(m.accel) * m.steps_num / m.steps_den * (corexy ? std::sqrt(2.0) : 1.0);
  l.dwell = dwell;
  l.window = m.tick_hz / 50;  // 20 ms
  return l;
}

// Regression: a move of a few steps that accelerates and brakes inside one segment has equal
// first and last intervals around a faster middle. Step prep once took it for a constant
// ramp and failed with kTimerFloor (the 4 x 4 and 5 x 5 cube arrays on the demo machine).
// Every small cube array on the README's demo machine must plot, and its trace must pass
// the independent checker's floor and rate limits.
static void short_moves_regression() {
  for (int32_t n = 2; n <= 8; ++n) {
    CubeArrayParams p;
    p.cubes = n;
    JobSpec spec;
    spec.drawing = DrawingEffect::kHaloed;
    spec.draw.halo = 50;
    spec.machine.kinematics = Kinematics::kCoreXY;
    const Run run = sim(spec, cube_array(p));
    const std::string label = "demo machine, " + std::to_string(n) + " x " + std::to_string(n);
    CHECK_MSG(ok(run.status), label + ": " + status_name(run.status));
    if (!ok(run.status)) continue;
    const auto parsed = reference::parse_trace_independently(run.trace);
    reference::Limits lim = limits_of(spec.machine, true, 0);
    lim.motor_accel = 1e30;  // junction deviation on: corners are not stops here
    const auto res = reference::check_trace(parsed, lim);
    CHECK_MSG(
        res.min_gap[0] >= spec.machine.min_interval && res.min_gap[1] >= spec.machine.min_interval,
        label + ": timer floor");
    CHECK_MSG(res.min_gap[0] * spec.machine.max_step_rate >= spec.machine.tick_hz &&
                  res.min_gap[1] * spec.machine.max_step_rate >= spec.machine.tick_hz,
              label + ": step rate");
  }
}

int main() {
  CubeArrayParams cubes;
  cubes.cubes = 3;
  const std::vector<Edge3> scene = cube_array(cubes);
  short_moves_regression();

  // 1. Replay reproduces the spans, for both kinematics and several step ratios.
  struct Case {
    Kinematics k;
    uint32_t num, den;
    bool backlash;
  };
  const Case cases[] = {{Kinematics::kCartesian, 1, 1, false},
                        {Kinematics::kCoreXY, 1, 1, false},
                        {Kinematics::kCoreXY, 16, 5, false},
                        {Kinematics::kCartesian, 2, 1, true},
                        {Kinematics::kCoreXY, 1, 1, true}};
  for (const Case& c : cases) {
    JobSpec spec = base_spec(c.k, c.num, c.den);
    spec.effects.backlash = c.backlash;
    if (c.backlash) spec.machine.backlash[0] = 7, spec.machine.backlash[1] = 3;
    const Run run = sim(spec, scene);
    const std::string label = std::string(c.k == Kinematics::kCoreXY ? "corexy " : "cartesian ") +
                              std::to_string(c.num) + "/" + std::to_string(c.den) +
                              (c.backlash ? " backlash" : "");
    CHECK_MSG(ok(run.status), label + ": " + status_name(run.status));
    check_replay(run, label);
    // The independent checker: rates, floor, acceleration (junction deviation off below).
    const auto parsed = reference::parse_trace_independently(run.trace);
    const auto res = reference::check_trace(
        parsed, limits_of(spec.machine, c.k == Kinematics::kCoreXY,
                          spec.machine.pen_travel_ticks + spec.machine.pen_settle_ticks));
    CHECK_MSG(res.min_gap[0] * spec.machine.max_step_rate >= spec.machine.tick_hz,
              label + ": step rate");
    CHECK_MSG(res.dwell_violations == 0, label + ": steps during pen dwell");
  }

  // 2. Acceleration: with junction deviation 0 every corner stops, so the motors' own
  //    acceleration bound holds; the checker must also catch a plan judged against half
  //    the limit (it can fail), and see at least half the limit (it measures something).
  //    Also with a motor step of 8 and 16 plot steps, where a move's ends round to motor
  //    steps: a move timed over its plot segment rather than its motors' move ran a motor
  //    over the bound (here: 87 steps up to 4.7 % too fast at 1/8, 112 up to 5.6 % at 1/16,
  //    63 up to 12.9 % at 1/16 Cartesian).
  const Case accel_cases[] = {{Kinematics::kCartesian, 1, 1, false},
                              {Kinematics::kCoreXY, 1, 1, false},
                              {Kinematics::kCoreXY, 1, 8, false},
                              {Kinematics::kCoreXY, 1, 16, false},
                              {Kinematics::kCartesian, 1, 16, false}};
  for (const Case& c : accel_cases) {
    const Kinematics k = c.k;
    JobSpec spec = base_spec(k, c.num, c.den);
    spec.machine.junction_deviation = 0;
    if (spec.machine.travel_speed >= (1u << 16)) spec.machine.travel_speed = 60000;  // budget
    const Run run = sim(spec, scene);
    CHECK(ok(run.status));
    const auto parsed = reference::parse_trace_independently(run.trace);
    reference::Limits lim = limits_of(spec.machine, k == Kinematics::kCoreXY, 25000);
    const auto res = reference::check_trace(parsed, lim);
    CHECK_MSG(res.ok, "acceleration check, " + std::to_string(c.num) + "/" + std::to_string(c.den) +
                          ": " + res.why);
    // (The checker's acceleration estimate, steps counted in 20 ms windows less 4 for their
    // rounding, sees nothing at 3,750 motor steps / s^2: at a sixteenth it is not asked.)
    if (c.den <= 8)
      CHECK_MSG(res.peak_accel > 0.5 * spec.machine.accel * c.num / c.den,
                "the checker sees the planned acceleration (motor steps / s^2)");
    lim.motor_accel /= 4;
    CHECK_MSG(!reference::check_trace(parsed, lim).ok, "the checker fails a quarter of the limit");
    // Junction deviation only ever saves time.
    JobSpec smooth = spec;
    smooth.machine.junction_deviation = 8;
    CHECK(sim(smooth, scene).report.end_tick < run.report.end_tick);
  }

  // 3. Random moves that come home end at exactly 0 steps on every motor (engine count and the
  //    trace's own count), including odd ratios where every target is rounded.
  scenes::Rng rng(3);
  for (int trial = 0; trial < 6; ++trial) {
    std::vector<Edge3> walk;
    int32_t x = 0, y = 0;
    for (int i = 0; i < 40; ++i) {
      const int32_t nx = int32_t(rng.uniform(0, 30000)), ny = int32_t(rng.uniform(0, 30000));
      walk.push_back(scenes::edge(x, y, 0, nx, ny, 0));
      x = nx, y = ny;
    }
    walk.push_back(scenes::edge(x, y, 0, 0, 0, 0));
    JobSpec spec = base_spec(trial % 2 ? Kinematics::kCoreXY : Kinematics::kCartesian,
                             trial % 3 ? 7 : 1, trial % 3 ? 3 : 1);
    spec.drawing = DrawingEffect::kAllEdges;
    spec.effects.acceleration = trial % 4 != 3;
    const Run run = sim(spec, walk);
    CHECK(ok(run.status));
    // The planner ends where the path ends; the path here ends at the last span's end.
    const PathPoint& last = run.report.points.back();
    int32_t want[2];
    motor_position(spec.machine, last.x, last.y, want);
    CHECK_EQ(run.report.final_motors[0], want[0]);
    CHECK_EQ(run.report.final_motors[1], want[1]);
    const auto parsed = reference::parse_trace_independently(run.trace);
    int64_t sum[2] = {0, 0};
    for (int m = 0; m < 2; ++m)
      for (int8_t d : parsed.step_dir[m]) sum[m] += d;
    CHECK_EQ(sum[0], int64_t(want[0]));
    CHECK_EQ(sum[1], int64_t(want[1]));
  }
  {  // A closed walk, planned as drawn, returns to motor 0 exactly.
    std::vector<Edge3> loop;
    int32_t px = 0, py = 0;
    for (int i = 0; i < 25; ++i) {
      const int32_t nx = i == 24 ? 0 : int32_t(rng.uniform(0, 20000)),
                    ny = i == 24 ? 0 : int32_t(rng.uniform(0, 20000));
      loop.push_back(scenes::edge(px, py, 0, nx, ny, 0));
      px = nx, py = ny;
    }
    JobSpec spec = base_spec(Kinematics::kCoreXY, 5, 2);
    spec.drawing = DrawingEffect::kAllEdges;
    const Run run = sim(spec, loop);
    const PathPoint& last = run.report.points.back();
    CHECK_MSG(last.x == 0 && last.y == 0, "the closed walk ends where it began");
    CHECK_EQ(run.report.final_motors[0], 0);
    CHECK_EQ(run.report.final_motors[1], 0);
  }

  // 4. Determinism: the same job gives the same bytes.
  {
    const JobSpec spec = base_spec(Kinematics::kCoreXY, 1, 1);
    CHECK(sim(spec, scene).trace == sim(spec, scene).trace);
  }

  // 5. Effects: what is not asked for does not run and takes no bytes.
  {
    JobSpec all = base_spec(Kinematics::kCartesian, 1, 1);
    all.drawing = DrawingEffect::kAllEdges;
    all.effects = PlotterEffects{false, false, false};
    const Run bare = sim(all, scene);
    CHECK_EQ(bare.report.job.cut_runs, 0u);
    CHECK_EQ(bare.report.job.draw_runs, 0u);
    CHECK_EQ(
        bare.report.bytes.cut_scratch + bare.report.bytes.cutset + bare.report.bytes.draw_scratch,
        size_t{0});
    CHECK_EQ(bare.report.planner_bytes, size_t{0});
    CHECK_EQ(bare.report.planner.replans, uint64_t{0});
    CHECK_EQ(bare.report.planner.junctions, uint64_t{0});
    CHECK_EQ(bare.report.planner.dwell_ticks, uint64_t{0});
    CHECK_EQ(bare.report.prep.backlash_takeups, uint64_t{0});
    CHECK_EQ(bare.report.spans.size(), scene.size());
    JobSpec full = all;
    full.drawing = DrawingEffect::kHaloed;
    full.effects = PlotterEffects{true, true, true};
    full.machine.backlash[0] = 4;
    const Run rich = sim(full, scene);
    CHECK(ok(rich.status));
    CHECK_EQ(rich.report.job.cut_runs, 1u);
    CHECK_EQ(rich.report.job.draw_runs, 1u);
    CHECK(rich.report.bytes.cut_scratch > 0 && rich.report.bytes.cutset > 0);
    CHECK(rich.report.planner_bytes > 0 && rich.report.planner.replans > 0 &&
          rich.report.planner.junctions > 0);
    CHECK(rich.report.planner.dwell_ticks > 0);
    CHECK(rich.report.prep.backlash_takeups > 0);
    // Pen servo time is the only difference between these two.
    JobSpec no_servo = full;
    no_servo.effects.pen_servo = false;
    const Run quick = sim(no_servo, scene);
    CHECK_EQ(rich.report.end_tick - quick.report.end_tick, rich.report.planner.dwell_ticks);
  }

  // 6. Faces-only drawing effects and impossible machines are refused with named statuses.
  {
    JobSpec s = base_spec(Kinematics::kCartesian, 1, 1);
    s.drawing = DrawingEffect::kHiddenRemoved;
    CHECK(sim(s, scene).status == Status::kBadParameter);
    Machine m;
    m.travel_speed = 30000;  // above 25,000 steps/s on a 1:1 motor
    CHECK(validate(m) == Status::kStepRateExceeded);
    m = Machine{};
    m.min_interval = 100;  // 25,000 steps/s needs 40-tick intervals at 1 MHz
    CHECK(validate(m) == Status::kTimerFloor);
    m = Machine{};
    m.kinematics = Kinematics::kCoreXY;
    m.travel_speed = 20000;  // fine on cartesian, sqrt(2) * 20,000 > 25,000 on CoreXY
    CHECK(validate(m) == Status::kStepRateExceeded);
  }
  // 7. Home: a job ends pen up at the origin (finish home, the default), or where its last
  //    stroke ended (finish stay); the trace's own steps sum to that, and its end line is the
  //    last event. Both kinematics, a step ratio that rounds.
  for (Kinematics k : {Kinematics::kCartesian, Kinematics::kCoreXY}) {
    JobSpec home = base_spec(k, 7, 3);
    JobSpec stay = home;
    stay.finish_home = false;
    const Run h = sim(home, scene), st = sim(stay, scene);
    CHECK(ok(h.status) && ok(st.status));
    CHECK_EQ(h.report.final_motors[0], 0);
    CHECK_EQ(h.report.final_motors[1], 0);
    const auto ph = reference::parse_trace_independently(h.trace);
    for (int m = 0; m < 2; ++m) {
      int64_t sum = 0;
      for (int8_t d : ph.step_dir[m]) sum += d;
      CHECK_EQ(sum, int64_t{0});
    }
    int64_t last = 0;
    for (int m = 0; m < 2; ++m)
      if (!ph.step_tick[m].empty()) last = std::max(last, ph.step_tick[m].back());
    CHECK_EQ(int64_t(ph.end), last);  // the end line is the arrival home
    const PathPoint& end = st.report.points.back();
    int32_t want[2];
    motor_position(stay.machine, end.x, end.y, want);
    CHECK(end.x != 0 || end.y != 0);
    CHECK_EQ(st.report.final_motors[0], want[0]);
    CHECK_EQ(st.report.final_motors[1], want[1]);
    CHECK(h.report.end_tick > st.report.end_tick);     // the travel home takes time
    CHECK(h.report.pen_lifts == st.report.pen_lifts);  // and no extra pen change
  }
  return check::finish("motion");
}
