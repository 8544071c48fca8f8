// 128-bit two's-complement integers from 32-bit limbs, for the few products that exceed
// 64 bits (squared cross products in the exact halo). Written out by hand because the
// Cortex-M4 has no __int128 and the core must compute the same bits on both targets.
// Host tests check every operation against the compiler's __int128.
#pragma once
#include <stdint.h>

namespace haloplot {

struct Wide {
  uint64_t lo = 0;
  uint64_t hi = 0;  // the top bit is the sign

  static Wide from_i64(int64_t v);
  static Wide from_u64(uint64_t v);

  bool negative() const { return (hi >> 63) != 0; }
  bool is_zero() const { return lo == 0 && hi == 0; }
};

Wide operator+(Wide a, Wide b);
Wide operator-(Wide a, Wide b);
Wide operator-(Wide a);

// Full 64 x 64 -> 128 products. Signed inputs may be any int64_t except INT64_MIN.
Wide mul_u64(uint64_t a, uint64_t b);
Wide mul_i64(int64_t a, int64_t b);

// a * b for a >= 0 whose true product is below 2^127 (the caller's bit budget says so).
Wide mul_wide_u64(Wide a, uint64_t b);

int compare(Wide a, Wide b);  // signed: -1, 0 or +1
inline bool operator<(Wide a, Wide b) { return compare(a, b) < 0; }
inline bool operator<=(Wide a, Wide b) { return compare(a, b) <= 0; }
inline bool operator==(Wide a, Wide b) { return a.lo == b.lo && a.hi == b.hi; }

// floor(sqrt(v)) for 0 <= v < 2^126. Digit-by-digit, no division: exact on every target.
uint64_t isqrt(Wide v);

// round(num / den) for num >= 0 and den > 0, by binary long division; *overflow is set (and
// the result saturated) when the quotient does not fit in 63 bits.
uint64_t divide_round(Wide num, uint64_t den, bool* overflow);
// floor(sqrt(v)) for a 64-bit value.
uint32_t isqrt_u64(uint64_t v);

}  // namespace haloplot
