// Exact products whose operands the bit budget (geometry/contract.h) keeps within 32 bits, as a
// 32 x 32 -> 64 multiply. On the Cortex-M3/M4/M33 and RV32 the plain expression is already that:
// GCC makes int64_t{a} * b of two int32_t one SMULL (mul + mulh on RV32). The Cortex-M0+
// (ARMv6-M) has only MULS, 32 x 32 -> 32, and there GCC calls __aeabi_lmul, a general 64 x 64
// multiply of about 40 instructions plus the call: 38 % of CUT's instructions on the EDGE rows
// (docs/reports/performance.md section 12). On ARMv6-M these build the product from 16-bit
// halves with MULS instead, exactly; the halves versions are also compiled on the host, where
// tests/unit/test_product.cpp checks them against the wide product.
#pragma once
#include <stdint.h>

namespace haloplot {

// ua * ub of two uint32_t from four 16 x 16 -> 32 products, each below 2^32, so MULS is exact:
// ua ub = hh 2^32 + (lh + hl) 2^16 + ll, the middle sum carrying out of 32 bits at times.
struct Product64 {
  uint32_t lo, hi;
};
inline Product64 mul_u32x32_halves(uint32_t ua, uint32_t ub) {
  const uint32_t al = ua & 0xffffu, ah = ua >> 16, bl = ub & 0xffffu, bh = ub >> 16;
  const uint32_t ll = al * bl, lh = al * bh, hl = ah * bl, hh = ah * bh;
  const uint32_t mid = lh + hl;
  const uint32_t mid_carry = mid < lh ? 0x10000u : 0u;  // 2^32 * 2^16, in the high word
  const uint32_t lo = ll + (mid << 16);
  return Product64{lo, hh + (mid >> 16) + mid_carry + (lo < ll ? 1u : 0u)};
}

// 0xffffffff where v < 0 (as int32_t), else 0.
inline uint32_t sign_mask(uint32_t v) { return 0u - (v >> 31); }

inline int64_t to_i64(Product64 p) { return int64_t(uint64_t{p.hi} << 32 | p.lo); }

// a * b of any two int32_t: a = ua - 2^32 [a < 0], so a b = ua ub - 2^32 (ub [a < 0] +
// ua [b < 0]) modulo 2^64; the correction is the high word's.
inline int64_t mul_32x32_halves(int32_t a, int32_t b) {
  const uint32_t ua = uint32_t(a), ub = uint32_t(b);
  Product64 p = mul_u32x32_halves(ua, ub);
  p.hi -= (ub & sign_mask(ua)) + (ua & sign_mask(ub));
  return to_i64(p);
}

// a * b for |a| < 2^kBitsA, |b| < 2^kBitsB with kBitsA + kBitsB <= 46: three 16-bit products.
// With a = ah 2^16 + al (ah = floor(a / 2^16), 0 <= al < 2^16) and b likewise,
// a b = (ah b + al bh) 2^16 + al bl, where |ah b| < 2^(kBitsA + kBitsB - 16) <= 2^30 and
// |al bh| < 2^kBitsB <= 2^30: the middle term is an int32_t, al bl a uint32_t.
template <int kBitsA, int kBitsB>
inline int64_t mul_narrow_halves(int32_t a, int32_t b) {
  static_assert(kBitsA >= 16 && kBitsB >= 16 && kBitsA <= 31 && kBitsB <= 30,
                "operands of 16 to 31 bits (the second at most 30)");
  static_assert(kBitsA + kBitsB <= 46, "the middle term must fit int32_t");
  const int32_t ah = a >> 16, bh = b >> 16;  // arithmetic shifts: floor (as GCC and Clang do)
  const uint32_t al = uint32_t(a) & 0xffffu, bl = uint32_t(b) & 0xffffu;
  const int32_t middle = ah * b + int32_t(al) * bh;
  // middle 2^16 + al bl, word by word: the low word's carry goes to the high one
  const uint32_t shifted = uint32_t(middle) << 16, lo = shifted + al * bl;
  return to_i64(Product64{lo, uint32_t(middle >> 16) + (lo < shifted ? 1u : 0u)});
}

// a * b for any int32_t a, b.
inline int64_t mul_32x32(int32_t a, int32_t b) {
#if defined(__ARM_ARCH_6M__)
  return mul_32x32_halves(a, b);
#else
  return int64_t{a} * b;
#endif
}

// a * b for any uint32_t a, b.
inline uint64_t mul_u32x32(uint32_t a, uint32_t b) {
#if defined(__ARM_ARCH_6M__)
  const Product64 p = mul_u32x32_halves(a, b);
  return uint64_t{p.hi} << 32 | p.lo;
#else
  return uint64_t{a} * b;
#endif
}

// a * b for |a| < 2^kBitsA, |b| < 2^kBitsB within 32 bits: the callers state their budget.
template <int kBitsA, int kBitsB>
inline int64_t mul_narrow(int32_t a, int32_t b) {
  static_assert(kBitsA <= 31 && kBitsB <= 31, "operands within int32_t");
#if defined(__ARM_ARCH_6M__)
  if constexpr (kBitsA + kBitsB <= 46 && kBitsA >= 16 && kBitsB >= 16 && kBitsB <= 30)
    return mul_narrow_halves<kBitsA, kBitsB>(a, b);
  else
    return mul_32x32_halves(a, b);
#else
  return int64_t{a} * b;
#endif
}

// a * b for an int32_t a and an int64_t b whose product fits int64_t (the caller's budget says
// so). Five MULS and their carries: on the M0+ about as long as __aeabi_lmul with its call, so
// used only where it measured faster (CUT's cell ownership; not DRAW's lerp, where it was 2 %
// slower, nor the depth comparison). With b = bh 2^32 + bl, a b = ua bl + 2^32 (ua bh - bl
// [a < 0]) modulo 2^64 (only the low 32 bits of ua bh matter there).
inline int64_t mul_32x64_halves(int32_t a, int64_t b) {
  const uint32_t ua = uint32_t(a), bl = uint32_t(uint64_t(b)), bh = uint32_t(uint64_t(b) >> 32);
  Product64 p = mul_u32x32_halves(ua, bl);
  p.hi += ua * bh - (bl & sign_mask(ua));
  return to_i64(p);
}

// a * b for a uint32_t a and a uint64_t b whose product fits uint64_t: ua bl + 2^32 (ua bh).
inline uint64_t mul_u32x64_halves(uint32_t a, uint64_t b) {
  Product64 p = mul_u32x32_halves(a, uint32_t(b));
  p.hi += a * uint32_t(b >> 32);
  return uint64_t{p.hi} << 32 | p.lo;
}

inline uint64_t mul_u32x64(uint32_t a, uint64_t b) {
#if defined(__ARM_ARCH_6M__)
  return mul_u32x64_halves(a, b);
#else
  return uint64_t{a} * b;
#endif
}

inline int64_t mul_32x64(int32_t a, int64_t b) {
#if defined(__ARM_ARCH_6M__)
  return mul_32x64_halves(a, b);
#else
  return int64_t{a} * b;
#endif
}

}  // namespace haloplot
