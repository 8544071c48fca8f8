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
#include <string>
#include <utility>
#include <vector>

#include "reference/trace_checker.h"

namespace haloplot::test {

// Half-step positions, kept as a sorted vector: a std::set allocates a node for each of a
// plot's hundreds of thousands of positions, which costs seconds under the sanitizers.
// Inserting appends; the first look sorts and drops duplicates.
class Cells {
 public:
  using Cell = std::pair<int64_t, int64_t>;
  void insert(Cell c) {
    v_.push_back(c);
    sorted_ = false;
  }
  void insert(const Cells& o) {
    v_.insert(v_.end(), o.begin(), o.end());
    sorted_ = false;
  }
  size_t size() const { return sealed().size(); }
  std::vector<Cell>::const_iterator begin() const { return sealed().begin(); }
  std::vector<Cell>::const_iterator end() const { return sealed().end(); }
  // A cell within `r` half steps of (x, y) in both coordinates.
  bool near(int64_t x, int64_t y, int64_t r) const {
    const std::vector<Cell>& v = sealed();
    for (int64_t dx = -r; dx <= r; ++dx) {
      const auto it = std::lower_bound(v.begin(), v.end(), Cell{x + dx, y - r});
      if (it != v.end() && it->first == x + dx && it->second <= y + r) return true;
    }
    return false;
  }

 private:
  const std::vector<Cell>& sealed() const {
    if (!sorted_) {
      std::sort(v_.begin(), v_.end());
      v_.erase(std::unique(v_.begin(), v_.end()), v_.end());
      sorted_ = true;
    }
    return v_;
  }
  mutable std::vector<Cell> v_;
  mutable bool sorted_ = true;
};

// What the pen drew, from a trace: the positions (in half plot steps, so CoreXY's half steps
// are whole) after every step made with the pen down, and each motor's pen-down step count.
struct Drawn {
  void add(const Drawn& o) {
    at.insert(o.at);
    steps[0] += o.steps[0];
    steps[1] += o.steps[1];
  }
  Cells at;
  uint64_t steps[2] = {0, 0};
};

// Every carriage step made with the pen down, in the replay's order: the step event it
// belongs to (its steps share its tick), the motor, and where the pen is after it.
struct InkedStep {
  uint64_t event;
  int motor;
  Cells::Cell at;
};

inline std::vector<InkedStep> inked_steps(const reference::CheckedTrace& t) {
  const reference::ReplayedPath path = reference::replay_path(t);
  std::vector<std::pair<int64_t, int>> ev;  // the replay's own order: (tick, motor), stable
  ev.reserve(path.x.size());
  for (int m = 0; m < 2; ++m)
    for (int64_t tick : t.step_tick[m]) ev.push_back({tick, m});
  std::stable_sort(ev.begin(), ev.end(), [](auto a, auto b) { return a.first < b.first; });
  std::vector<InkedStep> inked;
  size_t p = 0;
  bool down = false;
  uint64_t events = 0;
  for (size_t i = 0; i < ev.size(); ++i) {
    if (i == 0 || ev[i].first != ev[i - 1].first) ++events;
    // The pen state before the step's tick: a pen change on a step's own tick follows it.
    while (p < t.pen.size() && int64_t(t.pen[p].first) < ev[i].first) down = t.pen[p++].second;
    if (!down) continue;
    // Steps that move the carriage: a backlash take-up moves the motor alone, and draws nothing.
    if (i > 0 && path.x[i] == path.x[i - 1] && path.y[i] == path.y[i - 1]) continue;
    inked.push_back({events,
                     ev[i].second,
                     {int64_t(std::llround(2 * path.x[i])), int64_t(std::llround(2 * path.y[i]))}});
  }
  return inked;
}

// What the first `max_events` step events drew (a plot aborted there).
inline Drawn drawn(const std::vector<InkedStep>& inked, uint64_t max_events = UINT64_MAX) {
  Drawn d;
  for (const InkedStep& s : inked) {
    if (s.event > max_events) break;
    ++d.steps[s.motor];
    d.at.insert(s.at);
  }
  return d;
}

inline Drawn drawn(const reference::CheckedTrace& t, uint64_t max_events = UINT64_MAX) {
  return drawn(inked_steps(t), max_events);
}

// Every position of `a` within one plot step (two half steps) of one of `b`'s; the first that
// is not, in *where.
inline bool within_a_step(const Drawn& a, const Drawn& b, std::pair<int64_t, int64_t>* where) {
  for (const auto& [x, y] : a.at) {
    if (!b.at.near(x, y, 2)) {
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
