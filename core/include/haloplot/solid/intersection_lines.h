// Intersection lines: the parts of every face crossing (solid/face_crossing.h) that show.
//
// Pairs: two faces can cross only where their boxes overlap on paper, so the pairs are read
// from the face grid, each in one cell only (the cell of the boxes' common lower-left corner)
// and only when their boxes overlap in depth too. With `front` (closed solids) a crossing on a
// back face is skipped: the ray to it runs inside that face's own solid, so a front face of
// that solid hides it.
//
// What shows of each segment: solid/segment_pass.h, its own two faces left out. Pieces are
// numbered in the order the segments are found (cells, then pairs); with rows, only their
// parts in a band's rows.
#pragma once
#include <stdint.h>

#include "haloplot/solid/segment_pass.h"

namespace haloplot {

struct IntersectionStats : LineCounts {
  uint64_t pairs = 0;     // face pairs asked the exact question (boxes overlap, no shared corner)
  uint64_t segments = 0;  // pairs that cross
};

// Every crossing of topo's faces in the grid, piece by piece. `front`: each triangle's facing
// when the faces make closed solids (only front faces hide; the grid may hold those alone);
// null: both sides of every face.
Status draw_intersections(const Topology& topo, const uint8_t* front, const FaceGrid& fg,
                          LineSink sink, IntersectionStats* stats, LineRows rows = LineRows{});

}  // namespace haloplot
