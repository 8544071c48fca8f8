// Test references shared by the solid tests and the solid band benchmark: strokes as (edge,
// Q0.32 ends) joined into runs, and Kira's outline by brute force. Host-only.
#pragma once
#include <algorithm>
#include <cstdint>
#include <tuple>
#include <vector>

#include "pipeline/solid_pipeline.h"
#include "solid/cover.h"

namespace solid_refs {

using Stroke = std::tuple<uint32_t, int64_t, int64_t>;  // edge, t0, t1

// Adjacent strokes of one edge joined: the canonical form of a set of intervals.
inline std::vector<Stroke> joined(std::vector<Stroke> v) {
  std::sort(v.begin(), v.end());
  std::vector<Stroke> out;
  for (const Stroke& s : v) {
    if (!out.empty() && std::get<0>(out.back()) == std::get<0>(s) &&
        std::get<2>(out.back()) == std::get<1>(s))
      std::get<2>(out.back()) = std::get<2>(s);
    else
      out.push_back(s);
  }
  return out;
}

// Is position m (Q0.32) of edge ed on an outline, by definition: the picture's faces (any
// facing, any depth) lie on one side of it and not on the other? Every face is asked on both
// sides.
inline bool on_boundary(const haloplot::host::SolidScene& scene, const haloplot::Edge3& ed,
                        int64_t m) {
  const int64_t dx = ed.b.x - ed.a.x, dy = ed.b.y - ed.a.y;
  haloplot::CoverPoint p;
  p.d = int64_t{1} << 32;
  p.x = int64_t{ed.a.x} * p.d + dx * m;
  p.y = int64_t{ed.a.y} * p.d + dy * m;
  int side[2] = {0, 0};
  for (int sgn = 0; sgn < 2; ++sgn) {
    p.dir_x = int32_t(sgn ? dy : -dy);
    p.dir_y = int32_t(sgn ? -dx : dx);
    for (const haloplot::Triangle& t : scene.triangles)
      side[sgn] += haloplot::projection_cover_halves(scene.vertices[t.v[0]], scene.vertices[t.v[1]],
                                                     scene.vertices[t.v[2]], p);
  }
  return (side[0] == 0) != (side[1] == 0);
}

}  // namespace solid_refs
