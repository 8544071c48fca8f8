// The demo scene: the HALO paper's Figure 4, a regular array of cubes (28 x 28 gives 9408
// edges) seen obliquely, projected orthographically with integer arithmetic only.
#pragma once
#include <vector>

#include "geometry/contract.h"

namespace haloplot::host {

struct CubeArrayParams {
  int cubes = 28;         // cubes per side
  int32_t width = 20000;  // plot area in steps (about 250 mm at 80 steps/mm)
  int32_t height = 16000;
  int32_t margin = 400;  // lower-left corner of the plot area
};

std::vector<Edge3> cube_array(const CubeArrayParams& params);

}  // namespace haloplot::host
