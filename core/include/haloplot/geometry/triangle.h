// A face as every stage sees it: three corners by index and the polygon it came from. Here, at
// the bottom, so the view (the model's facing, view/facing.h) and the solid stages
// (solid/mesh.h) both read it without one including the other.
#pragma once
#include <stdint.h>

namespace haloplot {

inline constexpr uint32_t kNoFace = 0xffffffffu;

struct Triangle {
  uint32_t v[3];
  uint32_t polygon;  // the input face it came from; sides shared inside one polygon are diagonals
};

}  // namespace haloplot
