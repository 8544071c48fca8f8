#include "haloplot/geometry/fraction.h"

#include "haloplot/geometry/wide.h"

namespace haloplot {

int64_t scale_round(int64_t a, int64_t num, int64_t den) {
  if (den < 0) num = -num, den = -den;
  const bool neg = (a < 0) != (num < 0);
  const Wide prod = mul_u64(uint64_t(a < 0 ? -a : a), uint64_t(num < 0 ? -num : num));
  bool overflow = false;
  const int64_t q = int64_t(divide_round(prod, uint64_t(den), &overflow));
  return neg ? -q : q;
}

uint32_t frac_q32_small(int64_t num, int64_t den) {
  if (den <= 0xffffffff) {
    // Long division in 32-bit steps (a hardware divide each on the Cortex-M4): each step
    // brings in as many bits as keep the shifted remainder below 2^32 (rem < den < 2^(32-k)).
    const uint32_t d = static_cast<uint32_t>(den);
    const int free_bits = __builtin_clz(d);  // d > 0
    uint32_t rem = static_cast<uint32_t>(num), q = 0;
    if (free_bits == 0) {  // d >= 2^31: one bit at a time, the remainder kept below 2^32
      for (int i = 0; i < kFracBits; ++i) {
        const bool carry = (rem >> 31) != 0;
        rem <<= 1;
        q <<= 1;
        if (carry || rem >= d) {
          rem -= d;
          q |= 1u;
        }
      }
      return q;
    }
    for (int left = kFracBits; left > 0;) {
      const int step = free_bits < left ? free_bits : left;
      rem <<= step;
      q = (q << step) | (rem / d);
      rem %= d;
      left -= step;
    }
    return q;
  }
  const int64_t high = (num << 22) / den;        // top 22 bits of the fraction
  const int64_t rem = (num << 22) - high * den;  // < den < 2^41
  const int64_t low = (rem << 10) / den;         // next 10 bits; rem << 10 < 2^51
  return static_cast<uint32_t>((high << 10) | low);
}

uint32_t frac_q32(int64_t num, int64_t den) {
  if (den < (int64_t{1} << 41)) return frac_q32_small(num, den);
  if (den < (int64_t{1} << 51)) {
    // Three exact long-division steps of 12, 12 and 8 bits: rem < den < 2^51, so every
    // shifted remainder stays below 2^63.
    uint64_t rem = static_cast<uint64_t>(num), q = 0;
    const uint64_t d = static_cast<uint64_t>(den);
    constexpr int kSteps[3] = {12, 12, 8};
    for (int bits : kSteps) {
      rem <<= bits;
      q = (q << bits) | (rem / d);
      rem %= d;
    }
    return static_cast<uint32_t>(q);
  }
  uint64_t rem = static_cast<uint64_t>(num);
  const uint64_t d = static_cast<uint64_t>(den);
  uint32_t q = 0;
  for (int i = 0; i < kFracBits; ++i) {
    rem <<= 1;  // rem < den < 2^62, so this stays below 2^63
    q <<= 1;
    if (rem >= d) {
      rem -= d;
      q |= 1u;
    }
  }
  return q;
}

int64_t q32_floor_clamped(int64_t num, int64_t den) {
  if (num <= -den) return -kFracOne;
  if (num >= 2 * den) return 2 * kFracOne;
  // num in (-den, 2 den): integer part is -1, 0 or 1.
  int64_t whole = 0;
  if (num < 0) {
    whole = -1;
    num += den;
  } else if (num >= den) {
    whole = 1;
    num -= den;
  }
  return whole * kFracOne + frac_q32(num, den);
}

int64_t q32_ceil_clamped(int64_t num, int64_t den) { return -q32_floor_clamped(-num, den); }

}  // namespace haloplot
