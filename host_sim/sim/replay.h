// Replay: rebuild the pen-down drawing from a trace alone. Motor positions are integrated
// step by step; the carriage follows each motor through a dead band of the trace's backlash
// (the slack the machine has), and the plot position comes from the inverse kinematics.
#pragma once
#include <vector>

#include "motion/path_plan.h"
#include "sim/trace.h"

namespace haloplot::host {

struct ReplayStats {
  uint64_t pen_down_steps = 0, pen_up_steps = 0;  // motor steps while the pen was down / up
  uint64_t pen_up_length = 0;  // plot steps: straight lines between strokes (travel is straight)
  uint32_t pen_lifts = 0;
  int32_t final_motors[2] = {0, 0};
};

// Pen-down strokes as lists of plot positions, one per step event while the pen is down.
std::vector<std::vector<PathPoint>> replay_strokes(const Trace& t, ReplayStats* stats);

// Douglas-Peucker with an exact integer distance test: drop points within `tolerance` steps of
// the chord. For compact pictures; the checks use the raw strokes.
std::vector<PathPoint> simplify(const std::vector<PathPoint>& stroke, int32_t tolerance);

}  // namespace haloplot::host
