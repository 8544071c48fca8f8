// An independent reader and checker of step traces (its own parser: it shares nothing with
// host_sim/sim). It checks what a machine must never see:
//   - two steps of one motor closer than the step-rate limit or the timer floor;
//   - an acceleration above the limit: on a fixed time grid of h ticks the step count x
//     satisfies |x(t+h) - 2 x(t) + x(t-h)| <= A h^2 + 4 for any motion with |x''| <= A,
//     since a count never strays a full step from the true position (so +4 covers it);
//   - a step while the pen is still moving or settling.
#pragma once
#include <algorithm>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

namespace reference {

struct CheckedTrace {
  uint64_t tick_hz = 0, end = 0;
  std::vector<int64_t> step_tick[2];           // each motor's step ticks, in order
  std::vector<int8_t> step_dir[2];             // +1 / -1
  std::vector<std::pair<uint64_t, bool>> pen;  // (tick, down)
  std::string error;
};

inline CheckedTrace parse_trace_independently(const std::string& text) {
  CheckedTrace t;
  std::istringstream in(text);
  std::string line;
  std::vector<std::pair<int64_t, int8_t>> ev[2];
  while (std::getline(in, line)) {
    std::istringstream w(line);
    std::string k;
    w >> k;
    if (k == "tick_hz")
      w >> t.tick_hz;
    else if (k == "end")
      w >> t.end;
    else if (k == "p") {
      uint64_t tick;
      std::string s;
      w >> tick >> s;
      t.pen.push_back({tick, s == "down"});
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
};

struct CheckResult {
  uint64_t min_gap[2] = {UINT64_MAX, UINT64_MAX};
  double worst_accel_ratio = 0;  // max |second difference| / (A h^2 + 4)
  double peak_accel = 0;         // max |second difference| / h^2, steps / s^2
  uint64_t dwell_violations = 0;
  bool ok = true;
  std::string why;
};

inline CheckResult check_trace(const CheckedTrace& t, const Limits& lim) {
  CheckResult r;
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
