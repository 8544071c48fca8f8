#include "haloplot/draw/precision.h"

#include "haloplot/geometry/contract.h"
#include "haloplot/geometry/product.h"
#include "haloplot/geometry/wide.h"

namespace haloplot {
namespace {

// |(dx, dy)|^2 in Q20: < 2^42 << 20 < 2^62. The differences are below 2^kDiffBits, so the
// squares are 32 x 32 -> 64 products (geometry/product.h).
uint64_t square_q20(int64_t dx, int64_t dy) {
  const int32_t x = static_cast<int32_t>(dx), y = static_cast<int32_t>(dy);
  return static_cast<uint64_t>(mul_narrow<kDiffBits, kDiffBits>(x, x) +
                               mul_narrow<kDiffBits, kDiffBits>(y, y))
         << 20;
}

int bit_length(uint64_t v) { return v ? 64 - __builtin_clzll(v) : 0; }

constexpr uint32_t isqrt_ceil_constexpr(uint64_t v) {
  uint64_t r = 0;
  while (r * r < v) ++r;  // compile time only: at most 4097 steps per entry
  return static_cast<uint32_t>(r);
}

// kRootTable[m] = ceil(sqrt((m + 1) * 2^16)) for m in [64, 256): the root of the top of the
// bucket, so every square in the bucket gets an upper bound.
struct RootTable {
  uint16_t v[256];
};
constexpr RootTable make_root_table() {
  RootTable t{};
  for (uint32_t m = 0; m < 256; ++m)
    t.v[m] = static_cast<uint16_t>(isqrt_ceil_constexpr((uint64_t{m} + 1) << 16));
  return t;
}
constexpr RootTable kRootTable = make_root_table();

}  // namespace

uint64_t SqrtExact::length_q10_ceil(int64_t dx, int64_t dy) {
  // The table's upper bound (within 0.8 %), two Newton steps from above (relative excess
  // 0.008 -> 3e-5 -> 5e-10: within one unit of the root, which is below 2^31), then the exact
  // ceiling by comparing squares. Two divisions instead of the bit-pair root's 31 rounds.
  const uint64_t l2 = square_q20(dx, dy);
  if (l2 < 256) {
    uint64_t s = isqrt_u64(l2);
    return s * s < l2 ? s + 1 : s;
  }
  uint64_t s = SqrtTable::length_q10_ceil(dx, dy);
  s = (s + l2 / s) / 2;
  s = (s + l2 / s) / 2;
  // s is within one of the root, below 2^31: its squares are 32 x 32 -> 64 products
  while (mul_u32x32(uint32_t(s), uint32_t(s)) < l2) ++s;  // Newton's floor may sit one below
  while (mul_u32x32(uint32_t(s - 1), uint32_t(s - 1)) >= l2) --s;  // the least s, s^2 >= l2
  return s;
}

uint64_t SqrtNewton::length_q10_ceil(int64_t dx, int64_t dy) {
  const uint64_t l2 = square_q20(dx, dy);
  if (l2 == 0) return 0;
  // Seed 2^ceil(bits / 2) >= sqrt(l2), at most twice the root. Newton from above stays above
  // the floor of the root and shrinks the relative excess e to e^2 / (2 (1 + e)): 1 -> 0.25
  // -> 0.025 after two steps.
  uint64_t s = uint64_t{1} << ((bit_length(l2) + 1) / 2);
  s = (s + l2 / s) / 2;
  s = (s + l2 / s) / 2;
  if (s * s < l2) ++s;  // floor of the root at worst: make it an upper bound
  return s;
}

uint64_t SqrtTable::length_q10_ceil(int64_t dx, int64_t dy) {
  const uint64_t l2 = square_q20(dx, dy);
  if (l2 < 256) return isqrt_u64(l2) + 1;  // tiny: exact enough and still an upper bound
  // Keep the top 8 bits (an even shift, so the root's shift is whole): m in [64, 256).
  int shift = bit_length(l2) - 8;
  shift += shift & 1;
  const uint64_t m = l2 >> shift;
  // sqrt(l2) <= sqrt((m + 1) 2^shift) = table[m] 2^(shift / 2 - 8), rounded up.
  const uint64_t root = uint64_t{kRootTable.v[m]} << (shift / 2);
  return (root + 255) >> 8;
}

}  // namespace haloplot
