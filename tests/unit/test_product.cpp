// The 32 x 32 -> 64 products of geometry/product.h against the compiler's __int128 (an
// independent exact reference): the 16-bit-halves versions the Cortex-M0+ runs, compiled here,
// on the edges of their ranges (0, +-1, around 2^15, 2^16, 2^20, 2^21, 2^30, 2^31 and the
// type's limits) crossed with each other, and on random operands of every width; the plain
// versions the host runs likewise. And isqrt_u64's 32-bit path around its word and range
// boundaries against a root found by binary search on __int128 squares.
#include <cstdint>
#include <string>
#include <vector>

#include "../check.h"
#include "haloplot/geometry/product.h"
#include "haloplot/geometry/wide.h"
#include "haloplot/scene/random_edges.h"

using namespace haloplot;
using i128 = __int128;
using u128 = unsigned __int128;

namespace {

// Values around each power of two up to 2^bits (below it), both signs when is_signed.
std::vector<int64_t> edges_within(int bits, bool is_signed) {
  std::vector<int64_t> v = {0, 1, 2, 3};
  const int64_t top = (int64_t{1} << bits) - 1;
  for (int k = 1; k <= bits; ++k)
    for (int64_t d = -2; d <= 1; ++d) {
      const int64_t x = (int64_t{1} << k) + d;
      if (x >= 0 && x <= top) v.push_back(x);
    }
  v.push_back(top);
  v.push_back(top - 1);
  if (is_signed) {
    const size_t n = v.size();
    for (size_t i = 0; i < n; ++i) v.push_back(-v[i]);
  }
  return v;
}

// A random value of a random width below 2^bits, of either sign when is_signed.
int64_t random_within(SplitMix64& r, int bits, bool is_signed) {
  const int width = 1 + int(r.next() % uint64_t(bits));
  int64_t x = int64_t(r.next() & ((uint64_t{1} << width) - 1));
  if (x > (int64_t{1} << bits) - 1) x = (int64_t{1} << bits) - 1;
  return is_signed && (r.next() & 1) ? -x : x;
}

std::string pair(int64_t a, int64_t b) { return std::to_string(a) + " * " + std::to_string(b); }

void check_32x32(SplitMix64& r) {
  std::vector<int64_t> e = edges_within(31, true);
  e.push_back(INT32_MIN);
  e.push_back(INT32_MIN + 1);
  int bad = 0;
  auto one = [&](int32_t a, int32_t b) {
    const i128 want = i128(a) * b;
    if (i128(mul_32x32_halves(a, b)) != want || i128(mul_32x32(a, b)) != want) {
      if (++bad <= 5) CHECK_MSG(false, "mul_32x32 " + pair(a, b));
    }
    const uint32_t ua = uint32_t(a), ub = uint32_t(b);
    const u128 uwant = u128(ua) * ub;
    const Product64 p = mul_u32x32_halves(ua, ub);
    if ((u128(p.hi) << 32 | p.lo) != uwant || u128(mul_u32x32(ua, ub)) != uwant) {
      if (++bad <= 5) CHECK_MSG(false, "mul_u32x32 " + pair(ua, ub));
    }
  };
  for (int64_t a : e)
    for (int64_t b : e) one(int32_t(a), int32_t(b));
  for (int i = 0; i < 300000; ++i)
    one(int32_t(random_within(r, 31, true)), int32_t(random_within(r, 31, true)));
  for (int i = 0; i < 100000; ++i) one(int32_t(r.next()), int32_t(r.next()));  // any bits
  CHECK_EQ(bad, 0);
}

template <int kBitsA, int kBitsB>
void check_narrow(SplitMix64& r) {
  const std::vector<int64_t> ea = edges_within(kBitsA, true), eb = edges_within(kBitsB, true);
  int bad = 0;
  auto one = [&](int32_t a, int32_t b) {
    const i128 want = i128(a) * b;
    if (i128(mul_narrow_halves<kBitsA, kBitsB>(a, b)) != want ||
        i128(mul_narrow<kBitsA, kBitsB>(a, b)) != want) {
      if (++bad <= 5)
        CHECK_MSG(false, "mul_narrow<" + std::to_string(kBitsA) + ", " + std::to_string(kBitsB) +
                             "> " + pair(a, b));
    }
  };
  for (int64_t a : ea)
    for (int64_t b : eb) one(int32_t(a), int32_t(b));
  for (int i = 0; i < 200000; ++i)
    one(int32_t(random_within(r, kBitsA, true)), int32_t(random_within(r, kBitsB, true)));
  CHECK_EQ(bad, 0);
}

// 32 x 64 products whose result fits 64 bits: b up to the largest magnitude that keeps it so.
void check_32x64(SplitMix64& r) {
  std::vector<int64_t> ea = edges_within(31, true);
  ea.push_back(INT32_MIN);
  const std::vector<int64_t> eb = edges_within(62, true);
  int bad = 0;
  auto one = [&](int32_t a, int64_t b) {
    const i128 want = i128(a) * b;
    if (want > INT64_MAX || want < INT64_MIN) return;  // outside the contract
    if (i128(mul_32x64_halves(a, b)) != want || i128(mul_32x64(a, b)) != want) {
      if (++bad <= 5) CHECK_MSG(false, "mul_32x64 " + pair(a, b));
    }
    if (a >= 0 && b >= 0) {
      const u128 uw = u128(uint32_t(a)) * uint64_t(b);
      if (u128(mul_u32x64_halves(uint32_t(a), uint64_t(b))) != uw ||
          u128(mul_u32x64(uint32_t(a), uint64_t(b))) != uw) {
        if (++bad <= 5) CHECK_MSG(false, "mul_u32x64 " + pair(a, b));
      }
    }
  };
  for (int64_t a : ea)
    for (int64_t b : eb) one(int32_t(a), b);
  // The callers' budgets: a coordinate or difference (21 bits) by a numerator or denominator
  // (42 bits), and a difference by a Q0.32 fraction up to 2^32; then any fitting pair.
  for (int i = 0; i < 200000; ++i) {
    one(int32_t(random_within(r, 21, true)), random_within(r, 42, true));
    one(int32_t(random_within(r, 21, true)), int64_t(r.next() % ((uint64_t{1} << 32) + 1)));
    const int32_t a = int32_t(random_within(r, 31, true));
    one(a,
        random_within(
            r, 62 - (a == 0 ? 0 : 63 - __builtin_clzll(uint64_t(a < 0 ? -int64_t{a} : a))), true));
  }
  // The unsigned grid division's reciprocal (up to 2^42) by offsets below 2^21.
  for (int i = 0; i < 100000; ++i) {
    const uint32_t v = uint32_t(r.next() & ((1u << 21) - 1));
    const uint64_t rec = r.next() & ((uint64_t{1} << 42) - 1);
    if (u128(mul_u32x64_halves(v, rec)) != u128(v) * rec) {
      if (++bad <= 5) CHECK_MSG(false, "mul_u32x64 (grid) " + pair(v, int64_t(rec)));
    }
  }
  CHECK_EQ(bad, 0);
}

uint64_t root_reference(uint64_t v) {
  uint64_t lo = 0, hi = uint64_t{1} << 32;  // the root is in [lo, hi)
  while (hi - lo > 1) {
    const uint64_t mid = lo + (hi - lo) / 2;
    if (u128(mid) * mid <= v)
      lo = mid;
    else
      hi = mid;
  }
  return lo;
}

void check_isqrt(SplitMix64& r) {
  int bad = 0;
  auto one = [&](uint64_t v) {
    if (isqrt_u64(v) != root_reference(v) && ++bad <= 5)
      CHECK_MSG(false, "isqrt_u64 " + std::to_string(v));
  };
  // Squares and their neighbours around every power of two of the root: the words' border
  // (roots near 2^16), the 32-bit path's end (v near 2^60, roots near 2^30) and the top.
  for (int k = 0; k <= 32; ++k)
    for (int64_t d = -3; d <= 3; ++d) {
      const i128 s = (i128(1) << k) + d;
      if (s < 0 || s > 0xffffffff) continue;
      for (int64_t e = -2; e <= 2; ++e) {
        const i128 v = s * s + e;
        if (v >= 0 && v <= i128(UINT64_MAX)) one(uint64_t(v));
      }
    }
  for (int k = 0; k < 64; ++k)
    for (int64_t d = -2; d <= 2; ++d) one((uint64_t{1} << k) + uint64_t(d));
  for (int i = 0; i < 100000; ++i) one(r.next() >> (r.next() % 64));
  CHECK_EQ(bad, 0);
}

}  // namespace

int main() {
  SplitMix64 r(48);
  check_32x32(r);
  check_narrow<21, 21>(r);  // the cross products of differences (kDiffBits)
  check_narrow<23, 23>(r);
  check_narrow<16, 30>(r);
  check_narrow<30, 16>(r);
  check_32x64(r);
  check_isqrt(r);
  return check::finish("product");
}
