// Polygons to triangles for the hidden-line core (solid/mesh.h says why the core wants
// triangles). Ear clipping in the polygon's own plane, exactly in integers: the plane's normal
// is Newell's (sums of products of 20-bit world coordinates), the polygon is projected along
// its largest component, and ears are tested with exact orientations. Convex polygons come out
// as the fan from their first corner. Corners keep the polygon's winding, so the triangles face
// the way the polygon did. A polygon that is not simple gets the fan (and is counted), since no
// triangulation of it is right; repeated corners are dropped first.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "geometry/contract.h"
#include "solid/mesh.h"

namespace haloplot::host {

struct TriangulateStats {
  uint32_t polygons = 0, triangles = 0, concave = 0, not_simple = 0, degenerate = 0;
};

std::vector<Triangle> triangulate(const std::vector<Point3>& world,
                                  const std::vector<std::vector<uint32_t>>& faces,
                                  TriangulateStats* stats);

}  // namespace haloplot::host
