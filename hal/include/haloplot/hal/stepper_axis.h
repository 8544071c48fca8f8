// The stepper drivers: STEP and DIR per motor (an A4988/TMC-style driver), on the step path.
// The step tick (core/include/haloplot/motion/step_engine.h) calls these on every event, so a HAL
// is a plain class used as a template parameter: no virtual call on the step path.
//
//   struct MyHal {
//     void step(uint8_t motor);                          // one STEP pulse
//     void set_direction(uint8_t motor, bool backward);  // the DIR pin, latched until changed
//   };
//
// ENABLE is not on the step path: the board turns the drivers on before a plot (board_hal.h).
#pragma once
#include <stdint.h>

#include "haloplot/hal/detect.h"

namespace haloplot::hal {

// Number of motors a plotter drives (x/y or the two CoreXY belts).
inline constexpr uint8_t kMotors = 2;

HALOPLOT_HAL_MEMBER(HasStep, detail::object<H>().step(uint8_t{0}))
HALOPLOT_HAL_MEMBER(HasSetDirection, detail::object<H>().set_direction(uint8_t{0}, false))

template <typename H>
constexpr bool check_stepper_axes() {
  static_assert(HasStep<H>::value,
                "this HAL has no void step(uint8_t motor): one STEP pulse "
                "(hal/include/haloplot/hal/stepper_axis.h)");
  static_assert(HasSetDirection<H>::value,
                "this HAL has no void set_direction(uint8_t motor, bool backward) "
                "(hal/include/haloplot/hal/stepper_axis.h)");
  return true;
}

// The board's side (board_hal.h): static functions the controller's step HAL and motion runner
// call. step_high() raises STEP, steps_low() ends both pulses at the next interrupt.
HALOPLOT_HAL_MEMBER(HasStepHigh, H::step_high(uint8_t{0}))
HALOPLOT_HAL_MEMBER(HasStepsLow, H::steps_low())
HALOPLOT_HAL_MEMBER(HasDirPin, H::set_dir(uint8_t{0}, false))
HALOPLOT_HAL_MEMBER(HasEnable, H::enable_drivers(false))

template <typename B>
constexpr bool check_board_stepper() {
  static_assert(HasStepHigh<B>::value, "the board has no static void step_high(uint8_t motor)");
  static_assert(HasStepsLow<B>::value, "the board has no static void steps_low()");
  static_assert(HasDirPin<B>::value,
                "the board has no static void set_dir(uint8_t motor, bool backward)");
  static_assert(HasEnable<B>::value, "the board has no static void enable_drivers(bool on)");
  return true;
}

}  // namespace haloplot::hal
