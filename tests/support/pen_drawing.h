// What the pen drew, from a step trace read by the independent reader
// (tests/reference/trace_checker.h), and whether two traces drew the same: every position
// drawn in one within a plot step of a position drawn in the other, both ways, and each motor
// making exactly as many pen-down steps that move the carriage (so nothing was drawn twice or
// left out). The pause
// test and its QEMU counterpart (tools/pause_check.cpp) compare a paused plot with the
// uninterrupted one this way.
#pragma once
#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "reference/trace_checker.h"

namespace haloplot::test {

// What the pen drew, from a trace: the positions (in half plot steps, so CoreXY's half steps
// are whole) after every step made with the pen down, and each motor's pen-down step count.
struct Drawn {
  void add(const Drawn& o) {
    at.insert(o.at.begin(), o.at.end());
    steps[0] += o.steps[0];
    steps[1] += o.steps[1];
  }
  std::set<std::pair<int64_t, int64_t>> at;
  uint64_t steps[2] = {0, 0};
};

// max_events: only the first that many step events (a plot aborted there), each event's
// steps sharing its tick.
inline Drawn drawn(const reference::CheckedTrace& t, uint64_t max_events = UINT64_MAX) {
  const reference::ReplayedPath path = reference::replay_path(t);
  std::vector<std::pair<int64_t, int>> ev;  // the replay's own order: (tick, motor), stable
  for (int m = 0; m < 2; ++m)
    for (int64_t tick : t.step_tick[m]) ev.push_back({tick, m});
  std::stable_sort(ev.begin(), ev.end(), [](auto a, auto b) { return a.first < b.first; });
  Drawn d;
  size_t p = 0;
  bool down = false;
  uint64_t events = 0;
  for (size_t i = 0; i < ev.size(); ++i) {
    if (i == 0 || ev[i].first != ev[i - 1].first) ++events;
    if (events > max_events) break;
    // The pen state before the step's tick: a pen change on a step's own tick follows it.
    while (p < t.pen.size() && int64_t(t.pen[p].first) < ev[i].first) down = t.pen[p++].second;
    if (!down) continue;
    // Steps that move the carriage: a backlash take-up moves the motor alone, and draws nothing.
    if (i > 0 && path.x[i] == path.x[i - 1] && path.y[i] == path.y[i - 1]) continue;
    ++d.steps[ev[i].second];
    d.at.insert({int64_t(std::llround(2 * path.x[i])), int64_t(std::llround(2 * path.y[i]))});
  }
  return d;
}

// Every position of `a` within one plot step (two half steps) of one of `b`'s; the first that
// is not, in *where.
inline bool within_a_step(const Drawn& a, const Drawn& b, std::pair<int64_t, int64_t>* where) {
  for (const auto& [x, y] : a.at) {
    bool near = false;
    for (int64_t dx = -2; dx <= 2 && !near; ++dx)
      for (int64_t dy = -2; dy <= 2 && !near; ++dy) near = b.at.count({x + dx, y + dy}) > 0;
    if (!near) {
      *where = {x, y};
      return false;
    }
  }
  return true;
}

inline bool same_drawing(const Drawn& a, const Drawn& b, std::string* why) {
  std::pair<int64_t, int64_t> w;
  if (!within_a_step(a, b, &w) || !within_a_step(b, a, &w)) {
    *why = "drawn at (" + std::to_string(double(w.first) / 2) + ", " +
           std::to_string(double(w.second) / 2) + ") in one run only";
    return false;
  }
  if (a.steps[0] != b.steps[0] || a.steps[1] != b.steps[1]) {
    *why = "pen-down steps " + std::to_string(a.steps[0]) + "/" + std::to_string(a.steps[1]) +
           " against " + std::to_string(b.steps[0]) + "/" + std::to_string(b.steps[1]);
    return false;
  }
  return true;
}

}  // namespace haloplot::test
