// Where an edge passes through a face. Seen from the viewer, an edge's visibility can change
// only where it passes behind a face's side (a crossing on paper, which CUT finds), at a
// vertex on it, or where it passes through a face: in front of the face's plane on one side
// and behind it on the other. The last happens only when solids interpenetrate (overlapping
// parts of an assembly, a mesh that pierces itself, or faces that rounding to steps pushed
// through each other), and nothing on paper marks it, so the topology-free method asks for
// it here and cuts the edge there too: each piece's middle then speaks for the whole piece.
//
// Exact: with the face's plane normal n = (B - A) x (C - A), g(P) = n . (P - A) is zero on the
// plane and changes sign across it, linearly along the edge. The edge a -> b pierces the face
// where g(a) and g(b) have strictly opposite signs, at t = g(a) / (g(a) - g(b)), and only when
// that point lies in the triangle on paper (closed: a point on a side is also where the edge
// crosses that side, already a cut). Bit budget (geometry/contract.h: 21-bit differences):
// n's components are below 2^43, g below 2^66, the inside test's D * o(a) + N * k below 2^111:
// geometry/wide.h, static_asserted in pierce.cpp. The position is floor(t * 2^32), as CUT
// reports crossings, so the middle of every piece lies strictly between its true ends.
//
// A face that holds one of the edge's vertices meets it there and nowhere else (or holds it
// whole): it is skipped.
#pragma once
#include <stdint.h>

#include "haloplot/solid/face_grid.h"
#include "haloplot/solid/topology.h"

namespace haloplot {

inline constexpr int64_t kNoPierce = int64_t{1} << 40;  // beyond every Q0.32 position

// The sign of n . (p - on) (-1, 0, +1), n a plane normal of two 21-bit differences' cross
// products (components below 2^43). Exact: a 64-bit estimate with n / 8 decides it when it is
// far from zero (almost always), the 128-bit sum otherwise.
int plane_side(int64_t nx, int64_t ny, int64_t nz, const Point3& on, const Point3& p);

// floor(2^32 t) where the segment a -> b passes through the inside (or a side) of triangle
// (A, B, C), strictly between its ends; -1 when it does not. Edge-on triangles: -1.
// `how` (may be null) says more of a pierce found: whether the point lies on a side of the
// triangle (on paper), and whether a lies in front of the triangle's plane (nearer the viewer).
struct PierceSide {
  bool on_side = false;
  bool a_in_front = false;
};
int64_t pierce_q32(const Point3& a, const Point3& b, const Point3& A, const Point3& B,
                   const Point3& C, PierceSide* how = nullptr);

// The first position after `after` (Q0.32, floor) where drawn or diagonal edge e of topo
// passes through a face held in the face grid, or kNoPierce. Reads the cells the edge passes
// through; *face_tests counts the exact tests made (after the bounding-box and depth checks).
// With `front` (closed solids: only front faces hide), back faces are not asked: passing
// through one changes what hides the edge by nothing.
int64_t next_pierce(const Topology& topo, const FaceGrid& fg, const uint8_t* front, uint32_t e,
                    int64_t after, uint64_t* face_tests);

// For the QI walk (solid/qi.h): the first place after `after` where edge e passes through
// faces, and how the cover changes there walking from v0 to v1, in halves: +2 for each face
// (of those `front` marks, or every face when null) the edge goes behind, -2 for each it comes
// out in front of. `exact` is false when a face there is pierced on one of its sides (where
// the edge also meets that side in 3-D, and the crossing on paper may count it too) or more
// than kPierceFacesAtOnce faces meet at the point: the walk cannot trust the change.
inline constexpr uint32_t kPierceFacesAtOnce = 8;
struct PierceEvent {
  int64_t t;  // kNoPierce: none
  int change;
  bool exact;
};
PierceEvent next_pierce_event(const Topology& topo, const FaceGrid& fg, const uint8_t* front,
                              uint32_t e, int64_t after, uint64_t* face_tests);

}  // namespace haloplot
