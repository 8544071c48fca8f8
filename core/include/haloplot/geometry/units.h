// Units and steps. A projected scene may be fitted in units of 2^-s plot steps
// (View::substep_bits, geometry/contract.h) so that every decision that shapes the drawing (a
// crossing, a face's facing, which face hides a point) is made on the model 2^s times finer
// than the pen moves. The pen still moves in whole steps: lengths a user gives in steps (the
// halo, dashes, hatch spacing) become units on the way in, and emitted positions become steps
// on the way out, once, just before the path is planned.
//
// Rounding bound: DRAW and the stroke stages round an exact position to the nearest unit
// (1/2 unit), and round_to_steps() rounds that to the nearest step (1/2 step, ties upward),
// so an emitted position is within 1/2 + 2^-(s+1) step of the exact one. Two spans that meet
// at one unit point still meet after rounding: the path planner joins them as before.
#pragma once
#include <stdint.h>

#include "haloplot/geometry/contract.h"

namespace haloplot {

// A length in steps as units. Values beyond the coordinate range clamp to kCoordLimit (and
// stay negative when negative), so the stage's own range check refuses them by name.
inline int32_t steps_to_units(int32_t steps, int substep_bits) {
  const int64_t u = int64_t{steps} * (int64_t{1} << substep_bits);
  return u > kCoordLimit ? kCoordLimit : u < -kCoordLimit ? -kCoordLimit : int32_t(u);
}

// A coordinate in units (>= 0) to the nearest step, ties upward (never a division: a shift).
inline int32_t units_to_steps(int32_t units, int substep_bits) {
  if (substep_bits == 0) return units;
  return int32_t((int64_t{units} + (int64_t{1} << (substep_bits - 1))) >> substep_bits);
}

}  // namespace haloplot
