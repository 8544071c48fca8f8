// The demo scene, freestanding so the firmware can build it on the chip: the HALO paper's
// Figure 4, a regular array of cubes (28 x 28 gives 9408 edges) seen obliquely, projected
// orthographically with integer arithmetic only.
//
// View: azimuth 30 degrees, elevation 40 degrees, as Q16 constants (cos 30 = 0.8660,
// sin 30 = 0.5, cos 40 = 0.7660, sin 40 = 0.6428), with the README's convention:
//   x' = x cos(az) - y sin(az);  y1 = x sin(az) + y cos(az)
//   screen y' = z cos(el) + y1 sin(el);  depth d = z sin(el) - y1 cos(el)   (larger d = nearer)
#pragma once
#include <stdint.h>

#include "haloplot/geometry/contract.h"
#include "haloplot/status/status.h"

namespace haloplot {

struct CubeArrayParams {
  int32_t cubes = 28;     // cubes per side, 1..200
  int32_t width = 20000;  // plot area in steps (about 250 mm at 80 steps/mm)
  int32_t height = 16000;
  int32_t margin = 400;  // lower-left corner of the plot area
};

inline uint32_t cube_array_edges(const CubeArrayParams& p) {
  return 12u * uint32_t(p.cubes) * uint32_t(p.cubes);
}

// Writes cube_array_edges(p) edges; kBadParameter if capacity is short or p is out of range.
Status cube_array(const CubeArrayParams& p, Edge3* out, uint32_t capacity);

// The same edges one at a time, for a plot that never holds the scene (band/edge_source.h):
// fit() measures the array once (O(cubes^2)); edge(i) is edge i of cube_array()'s order.
class CubeArrayEdges {
 public:
  Status fit(const CubeArrayParams& p);
  uint32_t size() const { return n_; }
  Edge3 edge(uint32_t i) const;

 private:
  Point3 to_point(int32_t i, int32_t j, int corner) const;
  int32_t cubes_ = 0;
  uint32_t n_ = 0;
  int64_t xlo_ = 0, xhi_ = 1, ylo_ = 0, yhi_ = 1, dlo_ = 0, dhi_ = 1;
  int64_t out_w_ = 0, out_h_ = 0, margin_ = 0;
};

}  // namespace haloplot
