// Replay: rebuild the pen-down drawing from a trace alone. Motor positions are integrated
// tick by tick (all steps of one tick together, as the driver pulses them); the carriage
// follows each motor through a dead band of the trace's backlash (the slack the machine has),
// and the plot position comes from the inverse kinematics, kept exact: in units of
// 1 / scale plot steps, scale = steps_num (cartesian) or 2 * steps_num (CoreXY).
#pragma once
#include <cstdint>
#include <vector>

#include "haloplot/motion/path_plan.h"
#include "sim/trace.h"

namespace haloplot::host {

struct ExactPoint {
  int64_t x, y;  // plot steps * scale
};

struct Replay {
  int64_t scale = 1;
  std::vector<std::vector<ExactPoint>> strokes;   // one point per tick with steps, pen down
  uint64_t pen_down_steps = 0, pen_up_steps = 0;  // motor steps while the pen was down / up
  uint64_t pen_up_length = 0;  // plot steps: straight lines between strokes (travel is straight)
  uint32_t pen_lifts = 0;
  int32_t final_motors[2] = {0, 0};
};

Replay replay(const Trace& t);

// A stroke in whole plot steps (rounded), without points closer than `tolerance` steps to the
// chord between kept points (Douglas-Peucker, exact integer distances): for pictures.
std::vector<PathPoint> simplify(const std::vector<ExactPoint>& stroke, int64_t scale,
                                int32_t tolerance);

}  // namespace haloplot::host
