// The demo scene on the host: the core's freestanding generator
// (core/include/haloplot/scene/cube_array.h) into a vector.
#pragma once
#include <vector>

#include "haloplot/scene/cube_array.h"

namespace haloplot::host {

using haloplot::CubeArrayParams;

inline std::vector<Edge3> cube_array(const CubeArrayParams& params) {
  std::vector<Edge3> edges(cube_array_edges(params));
  if (!ok(haloplot::cube_array(params, edges.data(), uint32_t(edges.size())))) edges.clear();
  return edges;
}

}  // namespace haloplot::host
