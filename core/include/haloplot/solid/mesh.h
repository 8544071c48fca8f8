// A solid model as the hidden-line stages see it: projected vertices (the numeric contract of
// geometry/contract.h), the edges to draw in output order, and the faces as triangles.
//
// Why triangles: a triangle with integer vertices is exactly planar, so "is this face in
// front of that point" is an exact integer question. A polygon whose corners were rounded to
// plot steps is in general no longer planar. The host splits polygons into triangles (keeping
// the polygon id); a triangle side inside a polygon is a diagonal, never drawn, but it still
// carries the QI from vertex to vertex like any other edge.
//
// Orientation: a triangle's corners run counter-clockwise seen from outside the solid (the
// Wavefront OBJ convention). In plot coordinates (y up, viewer at +z) a front face is
// counter-clockwise on the paper.
#pragma once
#include <stdint.h>

#include "haloplot/geometry/contract.h"
#include "haloplot/geometry/triangle.h"

namespace haloplot {

struct SolidInput {
  const Point3* vertices = nullptr;  // projected, in range
  uint32_t n_vertices = 0;
  const uint32_t* edge_pairs = nullptr;  // 2 vertex indices per drawn edge: the output order
  uint32_t n_edges = 0;
  const Triangle* triangles = nullptr;
  uint32_t n_triangles = 0;
  // Optional: each triangle's facing as the model decides it (1 front, 0 back), for slivers
  // whose projected area rounding could flip (view/facing.h); null: the projected area.
  const uint8_t* facing = nullptr;
};

// Loutrel's edge classes (as Kira uses them), from the two faces of an edge:
//   H1  both faces back: never visible
//   H2  one front, one back, concave: a fold hidden by its own back face
//   H3  one front, one back, convex: a contour (silhouette) edge
//   H4  both faces front: potentially visible, never a contour
// Edges with fewer or more than two faces, and `l` lines, are kLoose: the fallback's business.
enum class EdgeClass : uint8_t { kH1 = 1, kH2 = 2, kH3 = 3, kH4 = 4, kLoose = 0 };

inline bool is_fold(EdgeClass c) { return c == EdgeClass::kH2 || c == EdgeClass::kH3; }
inline bool potentially_visible(EdgeClass c) {
  return c == EdgeClass::kH3 || c == EdgeClass::kH4 || c == EdgeClass::kLoose;
}

struct SolidEdge {
  uint32_t v0, v1;
  // face[0] runs v0 -> v1 in its own corner order, face[1] runs v1 -> v0 (kNoFace if none).
  uint32_t face[2];
  EdgeClass cls;
  bool drawn;    // an input edge (polygon side or line), not a diagonal
  bool regular;  // exactly two faces, running it in opposite directions (manifold here)
};

}  // namespace haloplot
