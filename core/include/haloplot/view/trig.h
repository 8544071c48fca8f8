// Sine and cosine in Q2.30 fixed point for angles in millidegrees, for the view transform.
// No table and no floating point: the angle is folded into [0, 45] degrees and a Taylor
// series is summed in Horner form in int64. Error: at most 4 units of 2^-30 (tested against
// the host's long double on every millidegree of a turn's first octant and random angles).
#pragma once
#include <stdint.h>

namespace haloplot {

inline constexpr int kTrigFractionBits = 30;
inline constexpr int64_t kTrigOne = int64_t{1} << kTrigFractionBits;

struct SinCos {
  int64_t sin, cos;  // Q2.30, in [-2^30, 2^30]
};

// Any angle in millidegrees; negative angles and angles beyond a turn are folded.
SinCos sin_cos_mdeg(int32_t millidegrees);

}  // namespace haloplot
