// One stepper motor driver: STEP, DIR and ENABLE pins (an A4988/TMC-style driver).
// The step tick calls step() and set_direction() on every event, so implementations are
// plain classes used as template parameters: no virtual call on the step path.
//
//   struct MyAxis {
//     void enable(bool on);            // driver outputs on or off
//     void set_direction(bool backward);
//     void step();                     // one STEP pulse
//   };
#pragma once
#include <stdint.h>

namespace haloplot::hal {

// Number of motors a plotter drives (x/y or the two CoreXY belts).
inline constexpr uint8_t kMotors = 2;

}  // namespace haloplot::hal
