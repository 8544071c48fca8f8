#include "demo/cube_array.h"

#include <algorithm>
#include <cstdint>

namespace haloplot::host {
namespace {

// View direction: azimuth 30 degrees, elevation 40 degrees, as Q16 constants (cos 30 = 0.8660,
// sin 30 = 0.5, cos 40 = 0.7660, sin 40 = 0.6428), so the demo needs no floating point. Same
// convention as the README's view:
//   x' = x cos(az) - y sin(az);  y1 = x sin(az) + y cos(az)
//   screen y' = z cos(el) - y1 sin(el);  depth d = z sin(el) - y1 cos(el)   (larger d = nearer)
constexpr int64_t kCosAz = 56756, kSinAz = 32768, kCosEl = 50203, kSinEl = 42125;

struct Projected {
  int64_t x, y, d;  // Q16 world units
};

Projected project(int64_t x, int64_t y, int64_t z) {
  const int64_t xs = x * kCosAz - y * kSinAz;
  const int64_t y1 = (x * kSinAz + y * kCosAz) >> 16;
  const int64_t ys = z * kCosEl - y1 * kSinEl;
  const int64_t d = z * kSinEl - y1 * kCosEl;
  return {xs, ys, d};
}

int32_t fit(int64_t v, int64_t lo, int64_t hi, int64_t out_lo, int64_t out_size) {
  // Round-to-nearest affine map of [lo, hi] onto [out_lo, out_lo + out_size].
  return int32_t(out_lo + ((v - lo) * out_size * 2 + (hi - lo)) / (2 * (hi - lo)));
}

}  // namespace

std::vector<Edge3> cube_array(const CubeArrayParams& p) {
  const int64_t side = 100, pitch = 125;  // world units: neighbours overlap on the screen
  std::vector<Projected> corners;
  std::vector<std::pair<int, int>> edge_ends;
  for (int i = 0; i < p.cubes; ++i)
    for (int j = 0; j < p.cubes; ++j) {
      const int base = int(corners.size());
      for (int k = 0; k < 8; ++k)
        corners.push_back(project(i * pitch + (k & 1) * side, j * pitch + ((k >> 1) & 1) * side,
                                  ((k >> 2) & 1) * side));
      // The 12 edges of a cube: corner pairs that differ in exactly one bit.
      for (int a = 0; a < 8; ++a)
        for (int bit = 1; bit < 8; bit <<= 1)
          if (!(a & bit)) edge_ends.push_back({base + a, base + (a | bit)});
    }
  int64_t xlo = INT64_MAX, xhi = INT64_MIN, ylo = INT64_MAX, yhi = INT64_MIN, dlo = INT64_MAX,
          dhi = INT64_MIN;
  for (const Projected& c : corners) {
    xlo = std::min(xlo, c.x), xhi = std::max(xhi, c.x);
    ylo = std::min(ylo, c.y), yhi = std::max(yhi, c.y);
    dlo = std::min(dlo, c.d), dhi = std::max(dhi, c.d);
  }
  // Uniform scale: the same steps per world unit on both screen axes.
  const int64_t sx = p.width, sy = p.height;
  const bool x_limits = (xhi - xlo) * sy >= (yhi - ylo) * sx;
  const int64_t out_w = x_limits ? sx : (xhi - xlo) * sy / (yhi - ylo);
  const int64_t out_h = x_limits ? (yhi - ylo) * sx / (xhi - xlo) : sy;
  std::vector<Edge3> edges;
  edges.reserve(edge_ends.size());
  auto to_point = [&](const Projected& c) {
    return Point3{fit(c.x, xlo, xhi, p.margin, out_w), fit(c.y, ylo, yhi, p.margin, out_h),
                  fit(c.d, dlo, dhi, 0, kCoordMax)};
  };
  for (const auto& [a, b] : edge_ends)
    edges.push_back(Edge3{to_point(corners[a]), to_point(corners[b])});
  return edges;
}

}  // namespace haloplot::host
