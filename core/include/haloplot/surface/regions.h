// Franklin 1980, steps 10-11: the planar graph of the visible segments, its regions, and the
// face each region shows.
//
//   10  Nodes are the segments' ends, exact: a mesh vertex, or the crossing of two edges as a
//       rational point (X / D, Y / D). Ends at the same point are one node (sorted exactly,
//       so node ids run in (x, y) order). Around each node the half-edges are sorted by angle;
//       a half-edge's direction is its edge's, an integer vector, so the order is exact. The
//       walk "next = the half-edge just clockwise of my twin" traces every boundary cycle with
//       its region on the left. At a cycle's lowest node (the smallest id) every half-edge
//       points right, so one corner there opens to the left: the cycle owning it is the
//       outside of a connected piece (a hole in the region around it); the others bound
//       their regions from outside.
//   11  Each cycle finds its face at one point: the middle of its longest segment, nudged an
//       infinitesimal step to the cycle's left (solid/cover.h's nudge, so the point is never
//       on an edge). The faces of the face-grid cell holding it that cover it are compared
//       exactly; the nearest names the region. Depths are compared where the planes meet the
//       segment's edge, and on a tie (the faces share the edge) by their rise along the nudge.
//
// Regions with holes are not paired with their holes: every cycle of a region names the same
// face, and hatching (surface/region_hatch.h) fills the union of a face's cycles by their
// orientation, which needs no pairing. The Euler relation V - E + bounded - holes = 0 (one
// hole cycle per connected piece) is what the tests check the cycles against.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/geometry/edge_piece.h"
#include "haloplot/solid/mesh.h"
#include "haloplot/status/status.h"
#include "haloplot/surface/franklin.h"

namespace haloplot {

// A visible segment: a piece of a drawn edge between two exact ends (FranklinPiece).
// t0, t1: Q0.32 floors of the ends along the edge.
struct RegionSegment : EdgePiece {
  PieceEnd from, to;
};

struct RegionStats {
  uint32_t segments = 0, nodes = 0;
  uint32_t zero_length = 0;  // both ends at one point (three edges through it): dropped
  uint32_t duplicates = 0;   // the same two nodes again (coincident edges): dropped
  uint32_t overlaps = 0;     // two half-edges leaving a node in one direction (never, if the
                             // cuts are consistent; counted, not fatal)
  uint32_t cycles = 0, bounded = 0, holes = 0;
  uint32_t background = 0;  // cycles whose nudged point no face covers
  uint32_t unnamed = 0;     // cycles of segments all shorter than 2^-31 of their edges
  uint64_t face_tests = 0;
};

constexpr uint32_t kRegionBackground = 0xffffffffu;
constexpr uint32_t kRegionUnnamed = 0xfffffffeu;

struct Regions {
  uint32_t n_segments = 0, n_nodes = 0, n_cycles = 0;
  const RegionSegment* segments = nullptr;
  const uint32_t* node = nullptr;   // [2 * n_segments]: the node at each end
  const uint8_t* kept = nullptr;    // [n_segments]: 0 for dropped segments
  const uint32_t* cycle = nullptr;  // [2 * n_segments]: half-edge 2s runs along the edge, 2s + 1
                                    // against it; its cycle (kRegionBackground if dropped)
  const uint32_t* cycle_face = nullptr;    // [n_cycles]: the triangle, or kRegionBackground /
                                           // kRegionUnnamed
  const uint8_t* cycle_bounded = nullptr;  // [n_cycles]: 1 outside boundary, 0 hole boundary
};

size_t regions_bytes(const SolidInput& in, uint32_t n_segments);

// `segments` must stay alive while `out` is used. kVisibilityInconsistent if an end claims a
// crossing that its edges do not have.
Status build_regions(const SolidInput& in, const RegionSegment* segments, uint32_t n_segments,
                     void* buffer, size_t bytes, Regions* out, RegionStats* stats);

}  // namespace haloplot
