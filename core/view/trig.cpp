#include "haloplot/view/trig.h"

namespace haloplot {
namespace {

// pi / 180000 in Q50: millidegrees to radians in Q30 after a 20-bit shift (rounded).
constexpr int64_t kRadPerMdegQ50 = 19650660422;
constexpr int32_t kTurn = 360000, kQuarter = 90000, kEighth = 45000;
static_assert(int64_t{kEighth} * kRadPerMdegQ50 < (int64_t{1} << 62), "angle product fits");

int64_t mul_q30(int64_t a, int64_t b) {  // |a|, |b| <= 2^30: the product fits in 61 bits
  return (a * b + (kTrigOne >> 1)) >> kTrigFractionBits;
}

// x in [0, pi/4] (Q30): Horner form of the Taylor series; each factor (1 - x^2 / (k (k+1)))
// stays in [0, 1], so every intermediate is below 2^31 and the products below 2^61.
int64_t sin_octant(int64_t x) {
  const int64_t x2 = mul_q30(x, x);
  int64_t r = kTrigOne;
  for (int64_t k = 12; k >= 2; k -= 2) r = kTrigOne - mul_q30(x2, r) / (k * (k + 1));
  return mul_q30(x, r);
}
int64_t cos_octant(int64_t x) {
  const int64_t x2 = mul_q30(x, x);
  int64_t r = kTrigOne;
  for (int64_t k = 13; k >= 1; k -= 2) r = kTrigOne - mul_q30(x2, r) / (k * (k + 1));
  return r;
}

}  // namespace

SinCos sin_cos_mdeg(int32_t millidegrees) {
  int32_t a = millidegrees % kTurn;
  if (a < 0) a += kTurn;
  const int32_t quadrant = a / kQuarter;
  int32_t r = a % kQuarter;
  // In the quadrant's upper half use the complement: sin(r) = cos(90 - r).
  const bool swap = r > kEighth;
  if (swap) r = kQuarter - r;
  const int64_t x = (int64_t{r} * kRadPerMdegQ50 + (int64_t{1} << 19)) >> 20;
  int64_t s = sin_octant(x), c = cos_octant(x);
  if (swap) {
    const int64_t t = s;
    s = c;
    c = t;
  }
  switch (quadrant) {
    case 0:
      return {s, c};
    case 1:
      return {c, -s};
    case 2:
      return {-s, -c};
    default:
      return {-c, s};
  }
}

}  // namespace haloplot
