// An independent reader and checker of step traces, versions 1 and 2 (its own parser: it shares
// nothing with host_sim/sim). It checks what a machine must never see:
//   - two steps of one motor closer than the step-rate limit or the timer floor;
//   - an acceleration above the limit: on a fixed time grid of h ticks the step count x
//     satisfies |x(t+h) - 2 x(t) + x(t-h)| <= A h^2 + 4 for any motion with |x''| <= A,
//     since a count never strays a full step from the true position (so +4 covers it);
//   - a step while the pen is still moving or settling;
//   - a speed jump at one step (check_step_speeds): for each motor and each step whose
//     neighbours go the same way, the speeds over the intervals before and after it, v = hz / i,
//     may differ by at most A (i1 + i2) / (2 hz), the acceleration over the time between the
//     two intervals' midpoints. Before comparing, each interval is widened by its rounding:
//     1.5 ticks (an event lies within a tick of its exact time, and a linear interval ramp ends
//     within a tick of the exact interval), plus, where the other motor steps faster, that
//     motor's interval (Bresenham puts the slower motor's steps on the faster one's ticks).
//     Where the pen path turns (a junction) the motors' speeds may jump by design (grbl's
//     junction deviation). Given the path's vertices (Limits::path), a jump within 3 motor steps of
//     a vertex may exceed the bound by v_j |u_out - u_in| per motor, where u are the motor's
//     parts of the unit directions in and out and v_j^2 = a delta s / (1 - s), s = sin(theta/2)
//     (grbl's junction speed, 5 % slack for the planner's integers); anywhere else it fails.
//     Without the vertices, a jump is excused where the replayed positions within 24 events
//     either side stray more than 2 steps from their chord (a turn the checker can see).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace reference {

struct CheckedTrace {
  uint64_t tick_hz = 0, end = 0;
  bool corexy = false;
  int64_t steps_num = 1, steps_den = 1;        // motor steps per plot step
  int64_t backlash[2] = {0, 0};                // slack per motor, motor steps
  std::vector<int64_t> step_tick[2];           // each motor's step ticks, in order
  std::vector<int8_t> step_dir[2];             // +1 / -1
  std::vector<std::pair<uint64_t, bool>> pen;  // (tick, down)
  std::string error;
};

// Version 2 lists the tick's schedule; this expands it by the README's rules, in its own way:
// the k-th event of an s line (k = 1, 2, ...) lies k I + A k (k - 1) / 2 Q8 ticks after the
// line's start, in closed form, where the simulator's reader adds intervals one by one. The
// digest on the end line must then match the expanded steps, or the expansion is wrong.
struct ScheduleExpansion {
  unsigned __int128 start_q8 = 0;  // Q8 time of the line's start
  int64_t reg = 0;                 // the interval register
  int dominant = 0;
  int8_t dir[2] = {1, 1};
  int64_t major = 1, minor = 0, err = 0;
  uint64_t digest = 0;
  bool in_block = false;
  void fold(uint64_t code) { digest = digest * 0x100000001b3ull + code + 1; }
};

inline CheckedTrace parse_trace_independently(const std::string& text) {
  CheckedTrace t;
  std::istringstream in(text);
  std::string line;
  std::vector<std::pair<int64_t, int8_t>> ev[2];
  ScheduleExpansion x;
  int version = 0;
  while (std::getline(in, line)) {
    std::istringstream w(line);
    std::string k;
    w >> k;
    if (k == "haloplot-trace")
      w >> version;
    else if (k == "tick_hz")
      w >> t.tick_hz;
    else if (k == "kinematics") {
      std::string kin;
      w >> kin;
      t.corexy = kin == "corexy";
    } else if (k == "backlash") {
      w >> t.backlash[0] >> t.backlash[1];
    } else if (k == "steps") {
      char slash;
      w >> t.steps_num >> slash >> t.steps_den;
    } else if (k == "end") {
      w >> t.end;
      uint64_t digest = 0;
      if (version == 2 && (!(w >> digest) || digest != x.digest))
        t.error = "the expanded steps do not give the end line's digest";
    } else if (k == "p") {
      uint64_t tick, dwell = 0;
      std::string s;
      w >> tick >> s;
      if (version == 2) {
        w >> dwell;
        if (uint64_t(x.start_q8 >> 8) != tick) t.error = "a p line's tick is not the schedule's";
        x.fold(8 * tick + 4 + (s == "down"));
        x.start_q8 += (unsigned __int128)dwell * 256;
      }
      t.pen.push_back({tick, s == "down"});
    } else if (k == "b") {
      std::string dirs;
      w >> x.dominant >> x.major >> x.minor >> dirs;
      x.err = x.major / 2;
      for (int m = 0; m < 2; ++m) x.dir[m] = dirs.size() == 2 && dirs[m] == '-' ? -1 : 1;
      x.in_block = true;
    } else if (k == "s") {
      int64_t count, delta, add;
      w >> count >> delta >> add;
      if (!x.in_block) t.error = "an s line outside a block";
      const int64_t first = x.reg + delta;
      for (int64_t e = 1; e <= count; ++e) {
        const unsigned __int128 q8 =
            x.start_q8 + (unsigned __int128)(e * first + add * e * (e - 1) / 2);
        const int64_t tick = int64_t(q8 >> 8);
        const int d = x.dominant, o = 1 - x.dominant;
        ev[d].push_back({tick, x.dir[d]});
        x.fold(8 * uint64_t(tick) + 2 * d + (x.dir[d] < 0));
        x.err += x.minor;
        if (x.err >= x.major) {
          x.err -= x.major;
          ev[o].push_back({tick, x.dir[o]});
          x.fold(8 * uint64_t(tick) + 2 * o + (x.dir[o] < 0));
        }
      }
      x.start_q8 += (unsigned __int128)(count * first + add * count * (count - 1) / 2);
      x.reg = first + count * add;
    } else if (k == "m") {
      int m;
      int64_t t0, count, dt, ddt;
      char dir;
      w >> m >> t0 >> count >> dt >> ddt >> dir;
      int64_t tick = t0, gap = dt;
      for (int64_t i = 0; i < count; ++i) {
        ev[m].push_back({tick, dir == '-' ? -1 : 1});
        tick += gap;
        gap += ddt;
      }
    }
  }
  for (int m = 0; m < 2; ++m) {
    std::stable_sort(ev[m].begin(), ev[m].end(), [](auto a, auto b) { return a.first < b.first; });
    for (auto& [tick, d] : ev[m]) {
      t.step_tick[m].push_back(tick);
      t.step_dir[m].push_back(d);
    }
  }
  return t;
}

struct Limits {
  uint64_t max_step_rate = 0, min_interval = 0;
  double motor_accel = 0;  // motor steps / s^2
  uint64_t dwell = 0;      // ticks after each pen change with no step
  uint64_t window = 0;     // h, ticks
  // The pen path's vertices in plot steps, in order from where the pen starts (empty: junctions
  // are found from the steps alone), and the machine's plot acceleration and junction
  // deviation for grbl's junction speed there.
  std::vector<std::pair<int64_t, int64_t>> path;
  double plot_accel = 0, junction_deviation = 0;
};

struct CheckResult {
  uint64_t min_gap[2] = {UINT64_MAX, UINT64_MAX};
  double worst_accel_ratio = 0;  // max |second difference| / (A h^2 + 4)
  double peak_accel = 0;         // max |second difference| / h^2, steps / s^2
  uint64_t dwell_violations = 0;
  double worst_step_ratio = 0;  // max speed change at one step / what accel allows (off junctions)
  uint64_t step_jumps = 0;      // steps whose speed change exceeds it
  uint64_t junctions_excused = 0;  // steps over it where the path turns
  int64_t worst_step_tick = -1;
  bool ok = true;
  std::string why;
};

// The pen path replayed from the steps: the plot position after each event of either motor,
// and each motor step's index among the events. With backlash, the first `backlash` steps
// after a motor reverses take up its slack and leave the carriage where it is (the slack
// starts taken up for + moves).
struct ReplayedPath {
  std::vector<double> x, y;
  std::vector<size_t> event_of[2];
};

inline ReplayedPath replay_path(const CheckedTrace& t) {
  ReplayedPath p;
  std::vector<std::pair<int64_t, int>> ev;  // (tick, motor)
  ev.reserve(t.step_tick[0].size() + t.step_tick[1].size());
  for (int m = 0; m < 2; ++m)
    for (int64_t tick : t.step_tick[m]) ev.push_back({tick, m});
  std::stable_sort(ev.begin(), ev.end(), [](auto a, auto b) { return a.first < b.first; });
  p.x.reserve(ev.size());
  p.y.reserve(ev.size());
  for (int m = 0; m < 2; ++m) p.event_of[m].reserve(t.step_tick[m].size());
  size_t next[2] = {0, 0};
  int64_t motor[2] = {0, 0}, slack_left[2] = {0, 0};
  int8_t last_dir[2] = {1, 1};
  for (const auto& [tick, m] : ev) {
    (void)tick;
    const int8_t d = t.step_dir[m][next[m]];
    if (d != last_dir[m]) slack_left[m] = t.backlash[m];
    last_dir[m] = d;
    if (slack_left[m] > 0)
      --slack_left[m];
    else
      motor[m] += d;
    p.event_of[m].push_back(p.x.size());
    ++next[m];
    p.x.push_back(t.corexy ? 0.5 * double(motor[0] + motor[1]) : double(motor[0]));
    p.y.push_back(t.corexy ? 0.5 * double(motor[0] - motor[1]) : double(motor[1]));
  }
  return p;
}

// Does the pen path turn within `w` events of event e (a point strays from the chord)?
inline bool path_turns_near(const ReplayedPath& p, size_t e, size_t w) {
  const size_t a = e > w ? e - w : 0, b = std::min(p.x.size() - 1, e + w);
  const double dx = p.x[b] - p.x[a], dy = p.y[b] - p.y[a], len = std::hypot(dx, dy);
  for (size_t i = a; i <= b; ++i) {
    const double ox = p.x[i] - p.x[a], oy = p.y[i] - p.y[a];
    const double off = len > 0 ? std::abs(dx * oy - dy * ox) / len : std::hypot(ox, oy);
    if (off > 2.0) return true;
  }
  return false;
}

// The path's vertices found by position (a grid of 8-step cells), and the most a motor's speed
// may change at each by grbl's junction speed.
struct Junctions {
  std::vector<double> extra[2];  // per vertex: the motor's largest speed change, steps / s
  std::vector<std::pair<int64_t, int64_t>> at;
  std::multimap<std::pair<int64_t, int64_t>, size_t> cells;

  Junctions(const CheckedTrace& t, const Limits& lim) {
    const auto& p = lim.path;
    const double ratio = double(t.steps_num) / double(t.steps_den);
    for (size_t k = 0; k < p.size(); ++k) {
      double e[2] = {0, 0};
      if (k > 0 && k + 1 < p.size()) {
        const double ix = double(p[k].first - p[k - 1].first),
                     iy = double(p[k].second - p[k - 1].second);
        const double ox = double(p[k + 1].first - p[k].first),
                     oy = double(p[k + 1].second - p[k].second);
        const double li = std::hypot(ix, iy), lo = std::hypot(ox, oy);
        if (li > 0 && lo > 0) {
          const double cos_theta = -(ix * ox + iy * oy) / (li * lo);
          const double sin_half = std::sqrt(std::max(0.0, 0.5 * (1 - cos_theta)));
          const double vj =
              sin_half > 0.9999
                  ? 65536.0
                  : std::min(65536.0, 1.05 * std::sqrt(lim.plot_accel * lim.junction_deviation *
                                                       sin_half / (1 - sin_half)));
          const double du[2] = {
              t.corexy ? (ox / lo + oy / lo) - (ix / li + iy / li) : ox / lo - ix / li,
              t.corexy ? (ox / lo - oy / lo) - (ix / li - iy / li) : oy / lo - iy / li};
          for (int m = 0; m < 2; ++m) e[m] = vj * std::abs(du[m]) * ratio;
        }
      }
      extra[0].push_back(e[0]);
      extra[1].push_back(e[1]);
      at.push_back(p[k]);
      cells.insert({{p[k].first >> 3, p[k].second >> 3}, k});
    }
  }
  // The largest allowance of a vertex within 3 motor steps of (x, y) (plot steps; `scale` plot
  // steps to a motor step: a vertex lies between motor positions, so with a quarter of a motor
  // step per plot step the nearest one may be 4 plot steps away), or -1 when there is none.
  double allowance(int m, double x, double y, double scale) const {
    double best = -1;
    const double radius = 3.0 * std::max(1.0, scale);
    const int64_t reach = int64_t(std::ceil(radius / 8));
    const int64_t cx = int64_t(std::floor(x)) >> 3, cy = int64_t(std::floor(y)) >> 3;
    for (int64_t gx = cx - reach; gx <= cx + reach; ++gx)
      for (int64_t gy = cy - reach; gy <= cy + reach; ++gy) {
        auto range = cells.equal_range({gx, gy});
        for (auto it = range.first; it != range.second; ++it) {
          const auto& v = at[it->second];
          if (std::hypot(double(v.first) - x, double(v.second) - y) <= radius)
            best = std::max(best, extra[m][it->second]);
        }
      }
    return best;
  }
};

// The per-step speed check described at the top of this file.
inline void check_step_speeds(const CheckedTrace& t, const Limits& lim, CheckResult* r) {
  const ReplayedPath path = replay_path(t);
  const Junctions junctions(t, lim);
  const double scale = double(t.steps_den) / double(t.steps_num);  // motor space to plot steps
  const double hz = double(t.tick_hz);
  for (int m = 0; m < 2; ++m) {
    const auto& ticks = t.step_tick[m];
    const auto& other = t.step_tick[1 - m];
    for (size_t k = 1; k + 1 < ticks.size(); ++k) {
      if (t.step_dir[m][k - 1] != t.step_dir[m][k] || t.step_dir[m][k] != t.step_dir[m][k + 1])
        continue;
      const double i1 = double(ticks[k] - ticks[k - 1]), i2 = double(ticks[k + 1] - ticks[k]);
      double widen = 1.5;
      auto it = std::upper_bound(other.begin(), other.end(), ticks[k]);
      if (it != other.begin() && it != other.end()) {
        const double d = double(*it - *(it - 1));
        if (d <= std::max(i1, i2)) widen += d;
      }
      const double lo1 = hz / (i1 + widen), hi1 = hz / std::max(i1 - widen, 0.5);
      const double lo2 = hz / (i2 + widen), hi2 = hz / std::max(i2 - widen, 0.5);
      const double gap = std::max({0.0, lo2 - hi1, lo1 - hi2});
      const double allowed = lim.motor_accel * (i1 + i2) / (2 * hz);
      const double ratio = gap / allowed;
      if (ratio <= 1.0) {
        r->worst_step_ratio = std::max(r->worst_step_ratio, ratio);
        continue;
      }
      const size_t e = path.event_of[m][k];
      if (lim.path.empty() ? path_turns_near(path, e, 24)
                           : gap <= allowed + junctions.allowance(m, path.x[e] * scale,
                                                                  path.y[e] * scale, scale)) {
        ++r->junctions_excused;
        continue;
      }
      ++r->step_jumps;
      if (ratio > r->worst_step_ratio) {
        r->worst_step_ratio = ratio;
        r->worst_step_tick = ticks[k];
      }
    }
  }
  if (r->step_jumps > 0) {
    r->ok = false;
    r->why += std::to_string(r->step_jumps) +
              " speed jumps at one step away from junctions (worst " +
              std::to_string(r->worst_step_ratio) + "x the limit at tick " +
              std::to_string(r->worst_step_tick) + "); ";
  }
}

inline CheckResult check_trace(const CheckedTrace& t, const Limits& lim) {
  CheckResult r;
  if (!t.error.empty()) {  // a trace that does not expand to its own digest is not checked
    r.ok = false;
    r.why = t.error + "; ";
    return r;
  }
  check_step_speeds(t, lim, &r);
  const double h = double(lim.window) / double(t.tick_hz);  // seconds
  for (int m = 0; m < 2; ++m) {
    const auto& ticks = t.step_tick[m];
    for (size_t i = 1; i < ticks.size(); ++i) {
      const uint64_t gap = uint64_t(ticks[i] - ticks[i - 1]);
      r.min_gap[m] = std::min(r.min_gap[m], gap);
    }
    // signed position at grid times: steps with tick <= g
    std::vector<int64_t> pos;
    size_t k = 0;
    int64_t x = 0;
    for (uint64_t g = 0; g <= t.end + lim.window; g += lim.window) {
      while (k < ticks.size() && uint64_t(ticks[k]) <= g) x += t.step_dir[m][k++];
      pos.push_back(x);
    }
    for (size_t i = 1; i + 1 < pos.size(); ++i) {
      const double d2 = std::abs(double(pos[i + 1] - 2 * pos[i] + pos[i - 1]));
      r.worst_accel_ratio = std::max(r.worst_accel_ratio, d2 / (lim.motor_accel * h * h + 4));
      r.peak_accel = std::max(r.peak_accel, (d2 - 4) / (h * h));
    }
    if (r.min_gap[m] != UINT64_MAX &&
        (r.min_gap[m] * lim.max_step_rate < t.tick_hz || r.min_gap[m] < lim.min_interval)) {
      r.ok = false;
      r.why += "motor " + std::to_string(m) + " steps too fast (gap " +
               std::to_string(r.min_gap[m]) + " ticks); ";
    }
    for (const auto& [pt, down] : t.pen) {
      (void)down;
      auto it = std::upper_bound(ticks.begin(), ticks.end(), int64_t(pt));
      if (it != ticks.end() && uint64_t(*it) < pt + lim.dwell) ++r.dwell_violations;
    }
  }
  if (r.worst_accel_ratio > 1.0) {
    r.ok = false;
    r.why += "acceleration above the limit (ratio " + std::to_string(r.worst_accel_ratio) + "); ";
  }
  if (r.dwell_violations) {
    r.ok = false;
    r.why += std::to_string(r.dwell_violations) + " steps during pen dwell; ";
  }
  return r;
}

}  // namespace reference
