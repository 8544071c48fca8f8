// Triangulation diagonals and contours, by the model and by a run (host-only reference).
//   - model_contour_diagonals: the diagonals (triangle sides two triangles of one polygon
//     share) whose two triangles face opposite ways on the exact screen of a ray-cast camera,
//     in double precision from the unrounded vertices: contours of the model itself.
//   - drawn_contour_diagonals: the visible length, in steps, of a run's H3 diagonals (QI), and
//     the part of it on diagonals the model does not have as contours (spurious: a sliver
//     that rounding flipped).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "pipeline/solid_pipeline.h"
#include "reference/ray_cast.h"

namespace contour_diagonals {

using Pair = std::pair<uint32_t, uint32_t>;

inline std::set<Pair> model_contour_diagonals(const ray_cast::Scene& truth,
                                              const std::vector<haloplot::Triangle>& tris) {
  std::map<Pair, std::vector<uint32_t>> sides;
  for (uint32_t t = 0; t < tris.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      uint32_t a = tris[t].v[k], b = tris[t].v[(k + 1) % 3];
      if (a > b) std::swap(a, b);
      sides[{a, b}].push_back(t);
    }
  auto front = [&](uint32_t t) {
    double x[3], y[3];
    for (int k = 0; k < 3; ++k) truth.screen_of(tris[t].v[k], &x[k], &y[k]);
    return (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]) > 0;
  };
  std::set<Pair> out;
  for (const auto& kv : sides) {
    if (kv.second.size() != 2) continue;
    const uint32_t t0 = kv.second[0], t1 = kv.second[1];
    if (tris[t0].polygon != tris[t1].polygon) continue;  // a drawn side
    if (front(t0) != front(t1)) out.insert(kv.first);
  }
  return out;
}

struct Drawn {
  double total = 0, spurious = 0;  // steps
};

// The run's visible H3 diagonals; the scene's vertices in units of 2^-substep_bits steps.
inline Drawn drawn_contour_diagonals(const haloplot::host::SolidScene& scene,
                                     const haloplot::host::SolidRun& run,
                                     const std::set<Pair>& model) {
  std::map<std::tuple<int32_t, int32_t, int32_t>, uint32_t> at;
  for (uint32_t v = 0; v < scene.vertices.size(); ++v) {
    const haloplot::Point3& p = scene.vertices[v];
    at.emplace(std::make_tuple(p.x, p.y, p.z), v);
  }
  auto id = [&](const haloplot::Point3& p) {
    const auto it = at.find(std::make_tuple(p.x, p.y, p.z));
    return it == at.end() ? UINT32_MAX : it->second;
  };
  const double unit = std::ldexp(1.0, -scene.substep_bits);
  Drawn d;
  for (const haloplot::host::SolidPiece& p : run.contour_diagonals) {
    if (p.hidden) continue;
    const haloplot::Edge3& e = run.edges[p.edge];
    const double len = std::hypot(double(e.b.x - e.a.x), double(e.b.y - e.a.y)) * unit;
    const double seen = len * double(p.t1 - p.t0) / 4294967296.0;
    d.total += seen;
    const uint32_t a = std::min(id(e.a), id(e.b)), b = std::max(id(e.a), id(e.b));
    if (!model.count({a, b})) d.spurious += seen;
  }
  return d;
}

}  // namespace contour_diagonals
