// Positions along an edge as unsigned Q0.32 fractions: t32 = floor(t * 2^32), where t = 0 at
// the edge's first endpoint and t = 1 at its second. 2^32 itself stands for t = 1.
//
// Why Q0.32: an edge is shorter than 2^20.5 steps, so one unit of t32 is below 2^-11.5 steps.
// Storing t32 instead of the exact rational (two 42-bit integers) halves a crossing record,
// and the loss is far below the half step that rounding to the plotter grid costs anyway.
// The bound, tested in tests/unit: |emitted position - exact position| <= 1/2 + 2^-11 steps.
#pragma once
#include <stdint.h>

namespace haloplot {

inline constexpr int kFracBits = 32;
inline constexpr int64_t kFracOne = int64_t{1} << kFracBits;

// floor(a / b) for b > 0, rounding toward minus infinity (C++ '/' truncates toward zero).
// Operands that fit 32 bits take the 32-bit division: one instruction on the Cortex-M4, where
// a 64-bit one is a library call of a hundred or more (CUT's cell walk divides per column).
inline int64_t floor_div(int64_t a, int64_t b) {
  if (a >= INT32_MIN && a <= INT32_MAX && b <= INT32_MAX) {
    const int32_t a32 = static_cast<int32_t>(a), b32 = static_cast<int32_t>(b);
    int32_t q = a32 / b32;
    if ((a32 % b32 != 0) && (a32 < 0)) --q;
    return q;
  }
  int64_t q = a / b;
  if ((a % b != 0) && (a < 0)) --q;
  return q;
}

// floor(num * 2^32 / den) for 0 <= num < den < 2^41. Two int64 divisions, exact: the first
// takes 22 bits (num << 22 < 2^63), the second the remaining 10 from the remainder.
uint32_t frac_q32_small(int64_t num, int64_t den);

// floor(num * 2^32 / den) for 0 <= num < den < 2^62, exact: two or three hardware divisions
// when den < 2^51, restoring long division (32 shift-and-subtract steps) above that.
uint32_t frac_q32(int64_t num, int64_t den);

// floor(num / den * 2^32) for den > 0 and |num| < 2^61; exact for t in [-1, 2), saturating
// to -2^32 below and 2 * 2^32 above. The ceiling twin is exact in (-2, 1] and saturates to
// -2 * 2^32 and 2^32. DRAW clips every gap to [0, 1], so the saturated values behave exactly
// like the true ones while nothing overflows.
int64_t q32_floor_clamped(int64_t num, int64_t den);
int64_t q32_ceil_clamped(int64_t num, int64_t den);

// round(a * num / den) for den != 0, |a|, |num| < 2^63, the product in 128 bits (halves away
// from zero); the quotient must fit in 63 bits (the callers' budgets say so).
int64_t scale_round(int64_t a, int64_t num, int64_t den);

// Round a position p0 + d * t32 / 2^32 to the nearest step (halves round up). |d| < 2^21.
inline int32_t lerp_round(int32_t p0, int32_t d, int64_t t32) {
  const int64_t scaled = int64_t{d} * t32 + (int64_t{1} << (kFracBits - 1));
  return p0 + static_cast<int32_t>(scaled >> kFracBits);  // arithmetic shift = floor
}

}  // namespace haloplot
