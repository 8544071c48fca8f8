// The independent trace checker's limits (tests/reference/trace_checker.h) for a job: the
// machine's step rate, timer floor, motor acceleration (CoreXY: a plot acceleration along a
// diagonal drives one motor sqrt(2) harder), the pen dwell, and the planned path's vertices,
// where grbl's junction speed may change a motor's speed by design.
#pragma once
#include <cmath>
#include <vector>

#include "haloplot/job/job.h"
#include "haloplot/motion/path_plan.h"
#include "reference/trace_checker.h"

namespace haloplot::test {

inline reference::Limits trace_limits(const JobSpec& spec, const std::vector<PathPoint>& points) {
  const Machine& m = spec.machine;
  reference::Limits l;
  l.max_step_rate = m.max_step_rate;
  l.min_interval = m.min_interval;
  const bool corexy = m.kinematics == Kinematics::kCoreXY;
  l.motor_accel = double(m.accel) * m.steps_num / m.steps_den * (corexy ? std::sqrt(2.0) : 1.0);
  l.window = m.tick_hz / 50;
  l.path.push_back({spec.start_x, spec.start_y});
  for (const PathPoint& p : points) l.path.push_back({p.x, p.y});
  l.plot_accel = m.accel;
  l.junction_deviation = m.junction_deviation;
  return l;
}

}  // namespace haloplot::test
