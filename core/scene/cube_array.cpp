#include "scene/cube_array.h"

namespace haloplot {
namespace {

constexpr int64_t kCosAz = 56756, kSinAz = 32768, kCosEl = 50203, kSinEl = 42125;
constexpr int64_t kSide = 100, kPitch = 125;  // world units: neighbours overlap on screen

struct Projected {
  int64_t x, y, d;  // Q16 world units
};

Projected project(int64_t x, int64_t y, int64_t z) {
  const int64_t xs = x * kCosAz - y * kSinAz;
  const int64_t y1 = (x * kSinAz + y * kCosAz) >> 16;
  return {xs, z * kCosEl + y1 * kSinEl, z * kSinEl - y1 * kCosEl};
}

Projected corner(int32_t i, int32_t j, int k) {
  return project(i * kPitch + (k & 1) * kSide, j * kPitch + ((k >> 1) & 1) * kSide,
                 ((k >> 2) & 1) * kSide);
}

// Round-to-nearest affine map of [lo, hi] onto [out_lo, out_lo + out_size].
int32_t fit(int64_t v, int64_t lo, int64_t hi, int64_t out_lo, int64_t out_size) {
  return int32_t(out_lo + ((v - lo) * out_size * 2 + (hi - lo)) / (2 * (hi - lo)));
}

}  // namespace

Status cube_array(const CubeArrayParams& p, Edge3* out, uint32_t capacity) {
  if (p.cubes < 1 || p.cubes > 200 || p.width < 1 || p.height < 1 || p.margin < 0 ||
      int64_t{p.margin} + p.width > kCoordMax || int64_t{p.margin} + p.height > kCoordMax)
    return Status::kBadParameter;
  if (capacity < cube_array_edges(p)) return Status::kBadParameter;
  // The bounding box of every corner, for the fit.
  int64_t xlo = INT64_MAX, xhi = INT64_MIN, ylo = INT64_MAX, yhi = INT64_MIN, dlo = INT64_MAX,
          dhi = INT64_MIN;
  for (int32_t i = 0; i < p.cubes; ++i)
    for (int32_t j = 0; j < p.cubes; ++j)
      for (int k = 0; k < 8; ++k) {
        const Projected c = corner(i, j, k);
        xlo = c.x < xlo ? c.x : xlo, xhi = c.x > xhi ? c.x : xhi;
        ylo = c.y < ylo ? c.y : ylo, yhi = c.y > yhi ? c.y : yhi;
        dlo = c.d < dlo ? c.d : dlo, dhi = c.d > dhi ? c.d : dhi;
      }
  // Uniform scale: the same steps per world unit on both screen axes.
  const int64_t sx = p.width, sy = p.height;
  const bool x_limits = (xhi - xlo) * sy >= (yhi - ylo) * sx;
  const int64_t out_w = x_limits ? sx : (xhi - xlo) * sy / (yhi - ylo);
  const int64_t out_h = x_limits ? (yhi - ylo) * sx / (xhi - xlo) : sy;
  auto to_point = [&](const Projected& c) {
    return Point3{fit(c.x, xlo, xhi, p.margin, out_w), fit(c.y, ylo, yhi, p.margin, out_h),
                  fit(c.d, dlo, dhi, 0, kCoordMax)};
  };
  uint32_t n = 0;
  for (int32_t i = 0; i < p.cubes; ++i)
    for (int32_t j = 0; j < p.cubes; ++j)
      // The 12 edges of a cube: corner pairs that differ in exactly one bit.
      for (int a = 0; a < 8; ++a)
        for (int bit = 1; bit < 8; bit <<= 1)
          if (!(a & bit))
            out[n++] = Edge3{to_point(corner(i, j, a)), to_point(corner(i, j, a | bit))};
  return Status::kOk;
}

}  // namespace haloplot
