// The plotter: kinematics, step ratios, speed and acceleration limits, the step clock and the
// pen. Everything is integer: speeds in plot steps per second, times in step-clock ticks.
#pragma once
#include <stdint.h>

#include "haloplot/status/status.h"

namespace haloplot {

enum class Kinematics : uint8_t {
  kCartesian,  // motor 0 moves x, motor 1 moves y
  kCoreXY,     // AxiDraw-style H-bot: motor 0 = x + y, motor 1 = x - y
};

// Plotter effects a job may ask the simulation (and the firmware) to model. An effect that is
// off costs no time and no workspace: its stage does not run.
struct PlotterEffects {
  bool acceleration = true;  // trapezoid profiles and junction speeds; off: constant speed
  bool pen_servo = true;     // pen travel and settle dwell; off: the pen moves instantly
  bool backlash = false;     // take up each motor's slack when it reverses
};

struct Machine {
  Kinematics kinematics = Kinematics::kCartesian;
  // Motor steps per plot step, as a ratio so no fraction is ever lost: motor position =
  // round(plot position * steps_num / steps_den), always from the absolute position.
  uint32_t steps_num = 1, steps_den = 1;
  uint32_t tick_hz = 1000000;          // step clock frequency
  uint32_t min_interval = 25;          // timer floor: ticks between two step events, at least
  uint32_t max_step_rate = 25000;      // per motor, steps per second
  uint32_t draw_speed = 6000;          // plot steps per second, pen down
  uint32_t travel_speed = 12000;       // plot steps per second, pen up
  uint32_t accel = 60000;              // plot steps per second squared
  uint32_t junction_deviation = 4;     // plot steps (grbl's junction deviation)
  uint32_t pen_travel_ticks = 150000;  // servo travel time
  uint32_t pen_settle_ticks = 50000;   // settle time before XY motion resumes
  uint32_t backlash[2] = {0, 0};       // motor steps of slack per motor
};

// All zero: no machine to run (validate() refuses it), the settings a planner and a step prep
// hold before their init(), so that one in static storage (a motion runner's) is zero bytes,
// in .bss, with no constructor to run. Every field is named: one added to Machine or
// PlotterEffects must be added here too, or its default puts the runner in .data (the CTest
// static_init checks the runner's bytes are all zero).
inline constexpr PlotterEffects kUnsetEffects{false, false, false};
inline constexpr Machine kUnsetMachine{Kinematics{}, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, {0, 0}};

// Check a machine against the limits the step generator can honour. Rejects, with a named
// status, any speed whose step rate exceeds max_step_rate on some motor, a step rate the
// timer floor cannot produce, and parameters outside the integer budgets below.
//   speeds < 2^16, accel < 2^22, steps_num / steps_den in [1/64, 16], tick_hz <= 2^28.
Status validate(const Machine& m);

// Motor positions (absolute steps) of a plot position (absolute plot steps).
void motor_position(const Machine& m, int32_t x, int32_t y, int32_t motors[2]);

// The plot position a motor position stands for, rounded to plot steps (for replay).
void plot_position(const Machine& m, const int32_t motors[2], int32_t* x, int32_t* y);

// How far the pen travels, in plot steps * 256 (Q8), on a move of `delta` motor steps (|delta|
// below 2^27): the motors' own move, not the plot segment it was rounded from. The planner
// times each move over this length, so a motor never accelerates faster than the machine's
// `accel` allows however the move's ends round to motor steps. (Timed over the segment's
// length, a 26-step move whose ends round half a step outward each ran its motor 1.7 % over
// the acceleration at an eighth of a motor step per plot step, 5.5 % at a sixteenth.) With
// whole motor steps per plot step it is the segment's own length.
uint32_t motor_move_length_q8(const Machine& m, const int32_t delta[2]);

}  // namespace haloplot
