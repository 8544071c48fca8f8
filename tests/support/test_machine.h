// The tests' plot job on a given machine: haloed at 40 steps, speeds scaled so every motor
// stays under its step rate at the steps ratio, a quick pen servo.
#pragma once
#include <cstdint>

#include "haloplot/job/job.h"

namespace test_support {

inline haloplot::JobSpec test_machine(haloplot::Kinematics k, uint32_t num, uint32_t den) {
  haloplot::JobSpec s;
  s.drawing = haloplot::DrawingEffect::kHaloed;
  s.draw.halo = 40;
  s.machine.kinematics = k;
  s.machine.steps_num = num;
  s.machine.steps_den = den;
  s.machine.draw_speed = 3000 * den / num;
  s.machine.travel_speed = 6000 * den / num;
  s.machine.pen_travel_ticks = 20000;
  s.machine.pen_settle_ticks = 5000;
  return s;
}

}  // namespace test_support
