#include "haloplot/geometry/wide.h"

namespace haloplot {

Wide Wide::from_i64(int64_t v) {
  Wide w;
  w.lo = static_cast<uint64_t>(v);
  w.hi = v < 0 ? ~uint64_t{0} : 0;
  return w;
}

Wide Wide::from_u64(uint64_t v) {
  Wide w;
  w.lo = v;
  return w;
}

Wide operator+(Wide a, Wide b) {
  Wide r;
  r.lo = a.lo + b.lo;
  r.hi = a.hi + b.hi + (r.lo < a.lo ? 1 : 0);
  return r;
}

Wide operator-(Wide a) {
  Wide r;
  r.lo = ~a.lo + 1;
  r.hi = ~a.hi + (r.lo == 0 ? 1 : 0);
  return r;
}

Wide operator-(Wide a, Wide b) { return a + (-b); }

Wide mul_u64(uint64_t a, uint64_t b) {
  // Schoolbook on 32-bit halves: each partial product is 32 x 32 -> 64, which the
  // Cortex-M4 does in one UMULL.
  const uint64_t a0 = a & 0xffffffffu, a1 = a >> 32;
  const uint64_t b0 = b & 0xffffffffu, b1 = b >> 32;
  const uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
  const uint64_t middle = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
  Wide r;
  r.lo = (middle << 32) | (p00 & 0xffffffffu);
  r.hi = p11 + (p01 >> 32) + (p10 >> 32) + (middle >> 32);
  return r;
}

Wide mul_i64(int64_t a, int64_t b) {
  const bool neg = (a < 0) != (b < 0);
  const uint64_t ua = a < 0 ? 0 - static_cast<uint64_t>(a) : static_cast<uint64_t>(a);
  const uint64_t ub = b < 0 ? 0 - static_cast<uint64_t>(b) : static_cast<uint64_t>(b);
  const Wide m = mul_u64(ua, ub);
  return neg ? -m : m;
}

Wide mul_wide_u64(Wide a, uint64_t b) {
  Wide r = mul_u64(a.lo, b);
  r.hi += a.hi * b;  // only the low 64 bits of a.hi * b matter below 2^128
  return r;
}

int compare(Wide a, Wide b) {
  const int64_t ah = static_cast<int64_t>(a.hi), bh = static_cast<int64_t>(b.hi);
  if (ah != bh) return ah < bh ? -1 : 1;
  if (a.lo != b.lo) return a.lo < b.lo ? -1 : 1;
  return 0;
}

uint64_t isqrt(Wide v) {
  // Classic bit-pair method: the root grows one bit per step, the remainder stays below
  // 2 * root + 1, so every intermediate fits in 128 bits for v < 2^126.
  uint64_t root = 0;
  Wide rem;  // remainder, unsigned in practice
  for (int shift = 124; shift >= 0; shift -= 2) {
    // bring down the next two bits of v
    const uint64_t two_bits = shift >= 64 ? (v.hi >> (shift - 64)) & 3u : (v.lo >> shift) & 3u;
    rem.hi = (rem.hi << 2) | (rem.lo >> 62);
    rem.lo = (rem.lo << 2) | two_bits;
    // trial = 4 * root + 1 (as a 128-bit value; root < 2^63 here)
    Wide trial;
    trial.lo = (root << 2) | 1u;
    trial.hi = root >> 62;
    root <<= 1;
    if (!(rem < trial)) {
      rem = rem - trial;
      root |= 1u;
    }
  }
  return root;
}

namespace {

// One step of the bit-pair method in 32 bits: valid while the root stays below 2^30
// (v < 2^60), where the shifted remainder, at most 2 (2^29 - 1) * 4 + 3, fits 32 bits.
inline void isqrt_step(uint32_t two_bits, uint32_t& root, uint32_t& rem) {
  rem = (rem << 2) | two_bits;
  const uint32_t trial = (root << 2) | 1u;
  root <<= 1;
  if (rem >= trial) {
    rem -= trial;
    root |= 1u;
  }
}

}  // namespace

uint32_t isqrt_u64(uint64_t v) {
  // The bit-pair method, starting at the highest non-zero pair (CLZ is one instruction on
  // most targets): lengths below 2^21 need 21 steps, not 32.
  if (v == 0) return 0;
  if (v < (uint64_t{1} << 60)) {
    // The same steps on 32-bit words: the high word's pairs, then the low word's. The
    // Cortex-M0+ shifts 64 bits by a variable amount in a library call; 32 bits in one.
    const uint32_t hi = static_cast<uint32_t>(v >> 32), lo = static_cast<uint32_t>(v);
    uint32_t root = 0, rem = 0;
    int first_low = 30;
    if (hi != 0) {
      for (int shift = (31 - __builtin_clz(hi)) & ~1; shift >= 0; shift -= 2)
        isqrt_step((hi >> shift) & 3u, root, rem);
    } else {
      first_low = (31 - __builtin_clz(lo)) & ~1;
    }
    for (int shift = first_low; shift >= 0; shift -= 2) isqrt_step((lo >> shift) & 3u, root, rem);
    return root;
  }
  uint64_t root = 0, rem = 0;
  for (int shift = (63 - __builtin_clzll(v)) & ~1; shift >= 0; shift -= 2) {
    rem = (rem << 2) | ((v >> shift) & 3u);
    const uint64_t trial = (root << 2) | 1u;
    root <<= 1;
    if (rem >= trial) {
      rem -= trial;
      root |= 1u;
    }
  }
  return static_cast<uint32_t>(root);
}

uint64_t divide_round(Wide num, uint64_t den, bool* overflow) {
  // One quotient bit per step from the top: the remainder stays below den, so (rem << 1)
  // needs one bit more than den has; den < 2^63 keeps it in 64 bits.
  uint64_t q = 0, rem = 0;
  *overflow = false;
  for (int bit = 127; bit >= 0; --bit) {
    const uint64_t in = bit >= 64 ? (num.hi >> (bit - 64)) & 1u : (num.lo >> bit) & 1u;
    rem = (rem << 1) | in;
    if (rem >= den) {
      rem -= den;
      if (bit >= 63)
        *overflow = true;
      else
        q |= uint64_t{1} << bit;
    }
  }
  if (rem >= den - rem) ++q;  // round half up: 2 rem >= den
  if (*overflow) q = (uint64_t{1} << 63) - 1;
  return q;
}

}  // namespace haloplot
