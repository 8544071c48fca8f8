#include "haloplot/scene/cube_array.h"

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
int32_t fit_range(int64_t v, int64_t lo, int64_t hi, int64_t out_lo, int64_t out_size) {
  return int32_t(out_lo + ((v - lo) * out_size * 2 + (hi - lo)) / (2 * (hi - lo)));
}

}  // namespace

Status CubeArrayEdges::fit(const CubeArrayParams& p) {
  if (p.cubes < 1 || p.cubes > 200 || p.width < 1 || p.height < 1 || p.margin < 0 ||
      int64_t{p.margin} + p.width > kCoordMax || int64_t{p.margin} + p.height > kCoordMax)
    return Status::kBadParameter;
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
  out_w_ = x_limits ? sx : (xhi - xlo) * sy / (yhi - ylo);
  out_h_ = x_limits ? (yhi - ylo) * sx / (xhi - xlo) : sy;
  xlo_ = xlo, xhi_ = xhi, ylo_ = ylo, yhi_ = yhi, dlo_ = dlo, dhi_ = dhi;
  margin_ = p.margin;
  cubes_ = p.cubes;
  n_ = cube_array_edges(p);
  return Status::kOk;
}

Point3 CubeArrayEdges::to_point(int32_t i, int32_t j, int k) const {
  const Projected c = corner(i, j, k);
  return Point3{fit_range(c.x, xlo_, xhi_, margin_, out_w_),
                fit_range(c.y, ylo_, yhi_, margin_, out_h_),
                fit_range(c.d, dlo_, dhi_, 0, kCoordMax)};
}

// The 12 edges of a cube are the corner pairs that differ in exactly one bit, in the order
// (corner a ascending, bit ascending) with a lacking the bit.
Edge3 CubeArrayEdges::edge(uint32_t index) const {
  static constexpr uint8_t kPairs[12][2] = {{0, 1}, {0, 2}, {0, 4}, {1, 3}, {1, 5}, {2, 3},
                                            {2, 6}, {3, 7}, {4, 5}, {4, 6}, {5, 7}, {6, 7}};
  const uint32_t cube = index / 12, e = index % 12;
  const int32_t i = int32_t(cube / uint32_t(cubes_)), j = int32_t(cube % uint32_t(cubes_));
  return Edge3{to_point(i, j, kPairs[e][0]), to_point(i, j, kPairs[e][1])};
}

Status cube_array(const CubeArrayParams& p, Edge3* out, uint32_t capacity) {
  CubeArrayEdges gen;
  const Status s = gen.fit(p);
  if (!ok(s)) return s;
  if (capacity < gen.size()) return Status::kBadParameter;
  for (uint32_t i = 0; i < gen.size(); ++i) out[i] = gen.edge(i);
  return Status::kOk;
}

}  // namespace haloplot
