// The interface the step engine drives, composed from the capability interfaces above. The
// firmware and the host simulator each provide one such class; StepEngine<Hal> inlines it.
//
//   struct PlotterHal {
//     void step(uint8_t motor);                       // stepper_axis.h
//     void set_direction(uint8_t motor, bool backward);
//     void pen(bool down);                            // pen.h
//   };
//
// Why templates and not virtual functions: a step event must cost a few dozen instructions
// (the goal is at most 60). An indirect call per pin write, through a vtable the compiler
// cannot see through, costs more than the Bresenham step itself and blocks inlining.
#pragma once
#include "limit_switch.h"
#include "pen.h"
#include "serial.h"
#include "step_clock.h"
#include "stepper_axis.h"
