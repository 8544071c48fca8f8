// Where two faces cross in space: the segment two triangles share when they pass through each
// other (solids that interpenetrate, parts of an assembly that overlap). Blender's Line Art and
// every engineering drawing draw it as an intersection line; solid/intersection_lines.h decides
// which parts of it show.
//
// Exact where it decides: the segment's ends are where a side of one triangle passes through
// the other (solid/pierce.h's exact test, asked along whichever axis the other triangle is not
// edge-on to), or a corner that lies exactly in the other's plane and inside it. Only the ends
// are rounded: each to the nearest unit (Q0.32 position first: within 1/2 + 2^-11 units per
// coordinate of the true point), and the two kept are the candidates farthest apart (they all
// lie on the line where the two planes meet, so the farthest pair is the segment).
//
// Triangles that only touch (along a side or at a corner, with no side passing strictly
// through the other) give no segment, and neither do coplanar ones (they overlap, they do not
// cross); nor triangles that share a corner by index (neighbours in one mesh meet there).
#pragma once
#include <stdint.h>

#include "haloplot/geometry/contract.h"

namespace haloplot {

// The segment where triangles p (p[0], p[1], p[2]) and q cross, ends rounded to units; false
// when they do not cross, or when the rounded segment is a point.
bool face_crossing(const Point3 p[3], const Point3 q[3], Edge3* out);

}  // namespace haloplot
