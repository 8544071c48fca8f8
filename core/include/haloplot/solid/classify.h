// Step 1 and 2 of Kira's program flow: faces front or back, edges into Loutrel's classes.
// A face seen exactly edge-on counts as back, Heger's convention, which keeps every contour on
// the side nearer the viewer.
#pragma once
#include <stdint.h>

#include "haloplot/solid/topology.h"

namespace haloplot {

struct ClassCounts {
  uint32_t front_faces = 0, back_faces = 0;
  uint32_t h[5] = {0, 0, 0, 0, 0};  // h[0]: loose edges, h[1..4]: H1..H4
};

// Writes front[t] (1 front, 0 back) and every edge's class; returns the counts.
// `facing` (may be null): the model's facing per triangle, used instead of the projected area.
ClassCounts classify(Topology* topo, uint8_t* front, const uint8_t* facing = nullptr);

// True when the edge between faces f0 and f1 (f0 runs v0 -> v1) is convex: f1's far corner
// lies behind f0's plane, seen from outside. Exact (a 3-D orientation in 128 bits).
bool convex_edge(const Topology& topo, uint32_t edge);

// The side of a fold edge (one front, one back face; v0 -> v1 on paper) its front face lies
// on: +1 left, -1 right. Exact. The QI's crossing sign, Kira's contour vectors and the V.C.
// table's peculiar vertices all ask it.
int front_face_side(const Topology& topo, const uint8_t* front, uint32_t edge);

// How the faces of an edge lie on paper, whatever their orientation: the sum over its faces of
// +1 for a face on the left of v0 -> v1, -1 on the right, 0 for one seen edge-on. Every face
// counts, the third and later of a non-manifold edge too (found in v0's star; without stars,
// the two the edge keeps). 0: crossing the edge on paper leaves as many faces over a point as
// before (two faces on either side, the interior of a surface); otherwise the edge is where a
// surface's image ends, a contour on paper (a fold, a boundary, a fin). Exact.
int paper_jump(const Topology& topo, uint32_t edge);

// H3 as paper shows it: a regular edge whose faces' projected areas have opposite signs (one
// counter-clockwise, the other clockwise or edge-on) and that is convex. It differs from the
// class only where the model's facing (SolidInput::facing) overrules a sliver's rounded area;
// the outlines, the boundary of what paper covers, ask this one. *side (may be null): the side
// of v0 -> v1 its counter-clockwise face lies on, +1 left, -1 right.
bool paper_h3(const Topology& topo, uint32_t edge, int* side = nullptr);

// A contour that the model's facing hides from the class: paper_h3, next to a face seen exactly
// edge-on after rounding (its projected area 0) that the model calls front. The silhouette
// then runs along the edge-on face's other side, the two on one line on paper, and the class
// puts the contour on that other side, where the face beside it lies along it: drawn only from
// here. (A sliver whose rounded area flipped sign is not one: the model is right about it.)
bool edge_on_contour(const Topology& topo, uint32_t edge);

// Is the edge a contour on paper for a drawing that counts both sides of every face (an open
// or non-manifold mesh, solid/qi.h's two-sided mode): paper_jump() != 0.
inline bool paper_contour(const Topology& topo, uint32_t edge) {
  return paper_jump(topo, edge) != 0;
}

}  // namespace haloplot
