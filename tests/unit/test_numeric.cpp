// The numeric layer against the compiler's __int128 (an independent exact reference):
// 128-bit limbs, integer square roots, Q0.32 fractions, and the documented rounding bound of
// emitted positions: |emitted - exact| <= 1/2 + 2^-11 steps.
#include <cstdint>
#include <string>

#include "../check.h"
#include "../support/scenes.h"
#include "haloplot/cut/grid.h"
#include "haloplot/draw/precision.h"
#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/predicates.h"
#include "haloplot/geometry/wide.h"

using namespace haloplot;
using i128 = __int128;
using u128 = unsigned __int128;

static i128 as_i128(Wide w) { return i128((u128(w.hi) << 64) | w.lo); }

static u128 isqrt_ref(u128 v) {
  // Newton's method on __int128, then fix up: an independent way to the same floor.
  if (v == 0) return 0;
  u128 x = u128(1) << 64;
  if (v < x) x = v;
  for (;;) {
    const u128 y = (x + v / x) / 2;
    if (y >= x) break;
    x = y;
  }
  while (x * x > v) --x;
  while ((x + 1) * (x + 1) <= v) ++x;
  return x;
}

// The square-root policies of draw/precision.h against the exact ceiling of sqrt((dx^2 +
// dy^2) 2^20), computed here by binary search on __int128 squares: SqrtExact must equal it;
// SqrtNewton and SqrtTable must never be below it and stay within 2.5 % and 0.8 % (plus one).
static uint64_t ceil_root_reference(int64_t dx, int64_t dy) {
  const unsigned __int128 v = (unsigned __int128)(dx * dx + dy * dy) << 20;
  uint64_t lo = 0, hi = uint64_t(1) << 32;
  while (lo < hi) {
    const uint64_t mid = lo + (hi - lo) / 2;
    if ((unsigned __int128)mid * mid >= v)
      hi = mid;
    else
      lo = mid + 1;
  }
  return lo;
}

static void check_sqrt_policies(scenes::Rng& r) {
  int bad_exact = 0, bad_newton = 0, bad_table = 0;
  auto one = [&](int64_t dx, int64_t dy) {
    const uint64_t want = ceil_root_reference(dx, dy);
    if (SqrtExact::length_q10_ceil(dx, dy) != want) ++bad_exact;
    const uint64_t n = SqrtNewton::length_q10_ceil(dx, dy), t = SqrtTable::length_q10_ceil(dx, dy);
    if (n < want || n > want + want / 40 + 1) ++bad_newton;
    if (t < want || t > want + want / 125 + 1) ++bad_table;
  };
  const int64_t edge = (int64_t(1) << 21) - 1;
  for (int64_t a :
       {int64_t(0), int64_t(1), int64_t(2), int64_t(3), int64_t(15), int64_t(16), edge, -edge})
    for (int64_t b : {int64_t(0), int64_t(1), int64_t(7), int64_t(255), edge, -edge}) one(a, b);
  for (int i = 0; i < 200000; ++i) {
    const int bits = int(r.next() % 22);
    const int64_t m = (int64_t(1) << bits) - 1;
    one(int64_t(r.next() % uint64_t(2 * m + 1)) - m, int64_t(r.next() % uint64_t(2 * m + 1)) - m);
  }
  CHECK_EQ(bad_exact, 0);
  CHECK_EQ(bad_newton, 0);
  CHECK_EQ(bad_table, 0);
}

int main() {
  scenes::Rng r(42);
  const int64_t extremes[] = {0,
                              1,
                              -1,
                              (int64_t(1) << 62),
                              -(int64_t(1) << 62),
                              INT64_MAX,
                              -INT64_MAX,
                              (int64_t(1) << 41) - 1,
                              -((int64_t(1) << 41) - 1),
                              0x7fffffff,
                              -0x80000000LL};
  // Multiplication, addition, comparison: extremes crossed with random values.
  for (int i = 0; i < 20000; ++i) {
    const int64_t a = i < 121 ? extremes[i % 11] : int64_t(r.next());
    const int64_t b = i < 121 ? extremes[i / 11] : int64_t(r.next() >> (r.next() % 40));
    const Wide p = mul_i64(a, b);
    CHECK_MSG(as_i128(p) == i128(a) * b, "mul_i64");
    const Wide q = mul_i64(b, a >> 3);
    CHECK_MSG(as_i128(p - q) == i128(a) * b - i128(b) * (a >> 3), "sub");
    CHECK_MSG(as_i128(p + q) == i128(a) * b + i128(b) * (a >> 3), "add");
    CHECK_MSG((compare(p, q) < 0) == (as_i128(p) < as_i128(q)), "compare");
    const uint64_t ua = r.next(), ub = r.next();
    CHECK_MSG((u128(mul_u64(ua, ub).hi) << 64 | mul_u64(ua, ub).lo) == u128(ua) * ub, "mul_u64");
    const uint64_t small = r.next() >> 24;                  // < 2^40
    const Wide w = mul_u64(r.next() >> 1, r.next() >> 40);  // < 2^87: product < 2^127
    CHECK_MSG(as_i128(mul_wide_u64(w, small)) == as_i128(w) * i128(small), "mul_wide_u64");
  }
  // Square roots: random magnitudes up to 2^126, perfect squares and their neighbours.
  for (int i = 0; i < 20000; ++i) {
    const int bits = int(r.next() % 126) + 1;
    u128 v = ((u128(r.next()) << 64) | r.next()) >> (128 - bits);
    if (i % 3 == 1) {
      const u128 s = v >> (bits / 2 + 1);
      v = s * s - (s > 0 ? (i % 2) : 0);  // a perfect square or one below it
    }
    Wide w;
    w.lo = uint64_t(v);
    w.hi = uint64_t(v >> 64);
    CHECK_MSG(u128(isqrt(w)) == isqrt_ref(v), "isqrt");
  }
  CHECK_EQ(isqrt_u64(~uint64_t{0}), 0xffffffffu);
  for (int i = 0; i < 20000; ++i) {
    const uint64_t v = r.next() >> (r.next() % 64);
    CHECK_MSG(u128(isqrt_u64(v)) == isqrt_ref(v), "isqrt_u64");
  }
  // The grid's multiply-shift division equals integer division for every offset below 2^21,
  // for every cell side up to 2^20: all boundaries k * cell - 1, k * cell and random values.
  for (int32_t cell : {1, 2, 3, 7, 10, 255, 1000, 10486, 65537, 123457, 524287, 1 << 20}) {
    Grid g;
    g.set_cell(cell);
    bool same = true;
    for (uint64_t k = 0; k * uint64_t(cell) < (1u << 21) && same; k += 1 + k / 4096) {
      const uint32_t v = uint32_t(k * uint64_t(cell));
      same = g.divide(v) == v / uint32_t(cell) &&
             (v == 0 || g.divide(v - 1) == (v - 1) / uint32_t(cell));
    }
    for (int i = 0; i < 20000 && same; ++i) {
      const uint32_t v = uint32_t(r.next() % (1u << 21));
      same = g.divide(v) == v / uint32_t(cell);
    }
    CHECK_MSG(same, "grid division, cell " + std::to_string(cell));
  }
  // Q0.32 fractions below 2^32: the 32-bit long division takes every denominator width, the
  // one-bit path (den >= 2^31) and the largest numerators.
  for (int bits = 1; bits <= 32; ++bits)
    for (int i = 0; i < 2000; ++i) {
      const uint64_t top = uint64_t(1) << (bits - 1);
      int64_t den = int64_t(top | (r.next() & (top - 1)));
      if (i == 0) den = int64_t((top << 1) - 1);
      if (i == 1) den = int64_t(top);
      int64_t num = int64_t(r.next() % uint64_t(den));
      if (i == 2) num = den - 1;
      if (i == 3) num = 0;
      const uint32_t want = uint32_t((i128(num) << 32) / den);
      CHECK_MSG(frac_q32_small(num, den) == want,
                "frac_q32_small below 2^32, " + std::to_string(num) + "/" + std::to_string(den));
    }
  // floor_div's 32-bit path and its 64-bit one, against __int128, around the 32-bit limits.
  for (int i = 0; i < 200000; ++i) {
    const int shift = int(r.next() % 40);
    const int64_t a = int64_t(r.next() >> (24 + shift % 24)) * ((r.next() & 1) ? -1 : 1);
    const int64_t b = int64_t(r.next() >> (shift + 24)) + 1;
    i128 q = i128(a) / b;
    if (i128(a) % b != 0 && a < 0) --q;
    CHECK_MSG(floor_div(a, b) == int64_t(q), "floor_div");
  }
  // Q0.32 fractions: both division routines give floor(num * 2^32 / den) exactly.
  for (int i = 0; i < 50000; ++i) {
    const int64_t den = int64_t(r.next() % ((uint64_t(1) << 41) - 1)) + 1;
    const int64_t num = int64_t(r.next() % uint64_t(den));
    const uint32_t want = uint32_t((i128(num) << 32) / den);
    CHECK_MSG(frac_q32_small(num, den) == want, "frac_q32_small");
    CHECK_MSG(frac_q32(num, den) == want, "frac_q32");
    const int64_t big_den = int64_t(r.next() >> 3) + 1;  // up to 2^61
    const int64_t snum = int64_t(r.next() >> 3) - (int64_t(1) << 60);
    const i128 exact = i128(snum) * (i128(1) << 32);
    i128 fl = exact / big_den;
    if (exact % big_den != 0 && exact < 0) --fl;
    const i128 lo = -(i128(1) << 32), hi = i128(2) << 32;
    const i128 clamped = fl < lo ? lo : (fl > hi ? hi : fl);
    CHECK_MSG(q32_floor_clamped(snum, big_den) == int64_t(clamped), "q32_floor_clamped");
  }
  // Rounding bound: a crossing emitted at its stored t32 lies within 1/2 + 2^-11 steps of the
  // exact crossing point, on both axes. Checked in integers: 2^12 * |emitted - exact| * den.
  const auto edges = scenes::paper_random(200, 500000, 3);
  int crossings = 0;
  for (size_t i = 0; i < edges.size(); ++i)
    for (size_t j = i + 1; j < edges.size(); ++j) {
      const Edge3 &p = edges[i], &q = edges[j];
      const CrossingTest c = test_crossing(p, q);
      if (!c.crosses) continue;
      ++crossings;
      const uint32_t t32 = frac_q32_small(c.tn, c.den);
      const int32_t ex = lerp_round(p.a.x, p.b.x - p.a.x, t32);
      const int32_t ey = lerp_round(p.a.y, p.b.y - p.a.y, t32);
      // exact x * den = a.x * den + dx * tn
      const i128 xd = i128(p.a.x) * c.den + i128(p.b.x - p.a.x) * c.tn;
      const i128 yd = i128(p.a.y) * c.den + i128(p.b.y - p.a.y) * c.tn;
      const i128 errx = (i128(ex) * c.den - xd) * 4096, erry = (i128(ey) * c.den - yd) * 4096;
      const i128 bound = i128(c.den) * (2048 + 2);  // (1/2 + 2^-11) * 2^12 * den
      CHECK_MSG(errx <= bound && -errx <= bound && erry <= bound && -erry <= bound,
                "rounding bound");
    }
  CHECK(crossings > 1000);
  check_sqrt_policies(r);
  return check::finish("numeric");
}
