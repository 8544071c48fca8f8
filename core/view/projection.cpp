#include "haloplot/view/projection.h"

#include "haloplot/geometry/wide.h"
#include "haloplot/view/trig.h"

namespace haloplot {
namespace {

// Rotated values: |world| <= 2^20, |sin|, |cos| <= 2^B, two products summed: < 2^(22 + B).
static_assert(2 * (int64_t{kWorldLimit} << kTrigFractionBits) < (int64_t{1} << 53), "rotation");

struct Rotated {
  int64_t x, y, d;  // world units in Q(B)
};

template <int B>
struct Rotation {
  static_assert(B == 16 || B == 30, "Q16.16 or Q2.30 trigonometry");
  SinCos az, el;
  Rotation(int32_t az_mdeg, int32_t el_mdeg)
      : az(round_trig(sin_cos_mdeg(az_mdeg))), el(round_trig(sin_cos_mdeg(el_mdeg))) {}
  // The Q2.30 values rounded to B fraction bits.
  static SinCos round_trig(SinCos v) {
    if constexpr (B == kTrigFractionBits) {
      return v;
    } else {
      constexpr int drop = kTrigFractionBits - B;
      constexpr int64_t half = int64_t{1} << (drop - 1);
      return {(v.sin + half) >> drop, (v.cos + half) >> drop};
    }
  }
  Rotated apply(const Point3& p) const {
    const int64_t xs = p.x * az.cos - p.y * az.sin;
    // y1 stays exact in Q(B); its products with the elevation's sin and cos are rounded once,
    // back to Q(B).
    const int64_t y1 = p.x * az.sin + p.y * az.cos;
    return {xs, p.z * el.cos + mul_shift(y1, el.sin), p.z * el.sin - mul_shift(y1, el.cos)};
  }
  // round(a * b / 2^B) for |a| < 2^(22 + B) and |b| <= 2^B. For B = 16 the product fits
  // (< 2^54); for B = 30 a 128-bit product is avoided by splitting a into a high part and 26
  // low bits, each product below 2^56.
  static int64_t mul_shift(int64_t a, int64_t b) {
    const bool neg = a < 0;
    const uint64_t m = neg ? 0 - uint64_t(a) : uint64_t(a);
    int64_t r;
    if constexpr (B <= 20) {
      r = (int64_t(m) * b + (int64_t{1} << (B - 1))) >> B;
    } else {
      const int64_t high = int64_t(m >> 26) * b, low = int64_t(m & 0x3ffffffu) * b;
      constexpr int kHighShift = B - 26;  // high carries 2^26: divide by 2^(B - 26)
      const int64_t q = high >> kHighShift;
      const int64_t rem = high - q * (int64_t{1} << kHighShift);
      r = q + (((rem << 26) + low + (int64_t{1} << (B - 1))) >> B);
    }
    return neg ? -r : r;
  }
};

struct Bounds {
  int64_t lo = INT64_MAX, hi = INT64_MIN;
  void add(int64_t v) {
    lo = v < lo ? v : lo;
    hi = v > hi ? v : hi;
  }
};

int bit_length(uint64_t v) {
  int n = 0;
  while (v) ++n, v >>= 1;
  return n;
}

// One axis of the fit: out_lo + round((v - lo) * out_size / range). The range is pre-shifted
// to 32 bits so the product stays in int64 (< 2^53); the shift drops less than 2^-31 of the
// range, under 2^-11 step. Both screen axes share one (out_size, range) pair: the scale is
// uniform, set by the axis that fills its side.
struct AxisFit {
  int64_t lo = 0, out_lo = 0, out_size = 0, range = 0;
  int shift = 0;
  AxisFit(int64_t lo_, uint64_t range_, int64_t out_lo_, int64_t out_size_)
      : lo(lo_), out_lo(out_lo_), out_size(out_size_) {
    shift = bit_length(range_) > 32 ? bit_length(range_) - 32 : 0;
    range = int64_t(range_ >> shift);
  }
  int32_t operator()(int64_t v) const {
    if (range == 0) return int32_t(out_lo);
    const int64_t num = int64_t(uint64_t(v - lo) >> shift) * out_size;
    return int32_t(out_lo + (2 * num + range) / (2 * range));
  }
};

}  // namespace

Status validate(const View& v) {
  if (v.substep_bits < 0 || v.substep_bits > kMaxSubstepBits) return Status::kBadParameter;
  const int s = v.substep_bits;
  if (v.width < 1 || v.height < 1 || v.margin < 0 ||
      (int64_t{v.margin} + v.width) << s > kCoordMax ||
      (int64_t{v.margin} + v.height) << s > kCoordMax || v.perspective < 0 ||
      v.perspective > 2 * kWorldLimit)
    return Status::kBadParameter;
  return Status::kOk;
}

// Perspective: (x, y, d) * D / (D - d), to Q16 world units, in one rounded 128-bit division. The
// eye is at depth D (Q(B): eye_q); kCoordinateOutOfRange for points within kEyeClearance of
// the eye plane or behind it.
template <int B>
Status perspective(const Rotated& r, int64_t eye_q, int32_t distance, Rotated* out) {
  const int64_t gap = eye_q - r.d;
  if (gap < (int64_t{kEyeClearance} << B)) return Status::kCoordinateOutOfRange;
  auto scale = [&](int64_t v) {
    const bool neg = v < 0;
    // |v| < 2^(22 + B) times distance * 2^16 < 2^37: below 2^(59 + B), in 128 bits; the
    // quotient by gap >= 2^B stays below 2^59.
    const Wide num = mul_u64(uint64_t(neg ? -v : v), uint64_t(distance) << 16);
    bool overflow = false;
    const uint64_t q = divide_round(num, uint64_t(gap), &overflow);
    return neg ? -int64_t(q) : int64_t(q);
  };
  // Depth the same way: d * D / (D - d) grows with d (nearer stays nearer), and with the same
  // divisor as x and y it is a projective map of the scene, so along a projected edge it
  // changes linearly, as CUT and every depth test interpolate it. The linear d does not: at a
  // crossing it would name the wrong edge in front.
  *out = Rotated{scale(r.x), scale(r.y), scale(r.d)};
  return Status::kOk;
}

template <int kTrigBits>
Status project_points_with(const View& view, const Point3* world, uint32_t n, Point3* out) {
  Status s = validate(view);
  if (!ok(s)) return s;
  const Rotation<kTrigBits> rot(view.azimuth_mdeg, view.elevation_mdeg);
  const int64_t eye_q = int64_t{view.perspective} << kTrigBits;
  auto place = [&](const Point3& p, Rotated* r) {
    *r = rot.apply(p);
    return view.perspective > 0 ? perspective<kTrigBits>(*r, eye_q, view.perspective, r)
                                : Status::kOk;
  };
  Bounds bx, by, bd;
  for (uint32_t i = 0; i < n; ++i) {
    const Point3& p = world[i];
    if (p.x < -kWorldLimit || p.x > kWorldLimit || p.y < -kWorldLimit || p.y > kWorldLimit ||
        p.z < -kWorldLimit || p.z > kWorldLimit)
      return Status::kCoordinateOutOfRange;
    Rotated r;
    s = place(p, &r);
    if (!ok(s)) return s;
    bx.add(r.x), by.add(r.y), bd.add(r.d);
  }
  if (n == 0) return Status::kOk;
  // Uniform scale: the axis whose range is larger relative to its side limits the scale.
  // xr / w >= yr / h compares as xr * h >= yr * w on ranges pre-shifted to 40 bits.
  const uint64_t xr = uint64_t(bx.hi - bx.lo), yr = uint64_t(by.hi - by.lo);
  const int len = bit_length(xr > yr ? xr : yr), sh = len > 40 ? len - 40 : 0;
  const bool x_limits = int64_t(xr >> sh) * view.height >= int64_t(yr >> sh) * view.width;
  const uint64_t range = x_limits ? xr : yr;
  // In units of 2^-s steps: the same fit, 2^s times finer.
  const int sub = view.substep_bits;
  const int64_t side = int64_t{x_limits ? view.width : view.height} << sub;
  const int64_t margin = int64_t{view.margin} << sub;
  const AxisFit fx(bx.lo, range, margin, side), fy(by.lo, range, margin, side),
      fd(bd.lo, uint64_t(bd.hi - bd.lo), 0, kCoordMax);
  for (uint32_t i = 0; i < n; ++i) {
    Rotated r;
    (void)place(world[i], &r);  // succeeded in the first pass: its status is kOk
    out[i] = Point3{fx(r.x), fy(r.y), fd(r.d)};
  }
  return Status::kOk;
}

Status project_points(const View& view, const Point3* world, uint32_t n, Point3* out) {
  return project_points_with<kTrigFractionBits>(view, world, n, out);
}
template Status project_points_with<16>(const View&, const Point3*, uint32_t, Point3*);
template Status project_points_with<30>(const View&, const Point3*, uint32_t, Point3*);

Status edges_from_indices(const Point3* points, uint32_t n_points, const uint32_t* pairs,
                          uint32_t n_edges, Edge3* out) {
  for (uint32_t e = 0; e < n_edges; ++e)
    if (pairs[2 * e] >= n_points || pairs[2 * e + 1] >= n_points) return Status::kBadParameter;
  for (uint32_t e = 0; e < n_edges; ++e)
    out[e] = Edge3{points[pairs[2 * e]], points[pairs[2 * e + 1]]};
  return Status::kOk;
}

}  // namespace haloplot
