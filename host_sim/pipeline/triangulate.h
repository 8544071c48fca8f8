// Polygons to triangles for the hidden-line core (solid/mesh.h says why the core wants
// triangles). Ear clipping in the polygon's own plane, exactly in integers: the plane's normal
// is Newell's (sums of products of 20-bit world coordinates), the polygon is projected along
// its largest component, and ears are tested with exact orientations. Convex polygons come out
// as the fan from their first corner. Corners keep the polygon's winding, so every triangle
// faces the way the polygon does. Repeated corners and a loop given twice are dropped first;
// a boundary that touches itself (a keyhole bridge to an inner boundary, traversed there and
// back) is clipped as one weakly simple polygon. A boundary that crosses itself has no right
// triangulation: it is counted (first_not_simple names it) for the caller to refuse, and no
// triangle of its undone part is made. A polygon with no area (all corners on a line) is
// counted as degenerate and gives no triangle.
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "haloplot/geometry/contract.h"
#include "haloplot/solid/mesh.h"

namespace haloplot::host {

struct TriangulateStats {
  uint32_t polygons = 0, triangles = 0, concave = 0, not_simple = 0, degenerate = 0;
  int64_t first_not_simple = -1;  // the first face whose boundary crosses itself
};

// Each triangle's polygon is its face, or with `regions` (one per face, ObjModel::face_region)
// its face's region, a region's triangles one run (solid/mesh.h: a polygon is a run).
std::vector<Triangle> triangulate(const std::vector<Point3>& world,
                                  const std::vector<std::vector<uint32_t>>& faces,
                                  const std::vector<uint32_t>& regions, TriangulateStats* stats);
inline std::vector<Triangle> triangulate(const std::vector<Point3>& world,
                                         const std::vector<std::vector<uint32_t>>& faces,
                                         TriangulateStats* stats) {
  return triangulate(world, faces, {}, stats);
}

}  // namespace haloplot::host
