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
//
// In parts (memory/parts.h), when a runner and a buffer are given: the cells split into parts
// of about equal face lists, each part asks its pairs and finds what shows of its segments
// into its share of the buffer, and the pieces then go to the sink from the calling thread in
// the order one part gives them, numbered alike. A part whose share fills up stops at the cell
// it was in, and that cell and the rest of its part are drawn on the calling thread in their
// turn: a small buffer costs time, never a piece.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/memory/parts.h"
#include "haloplot/solid/segment_pass.h"

namespace haloplot {

struct IntersectionStats : LineCounts {
  uint64_t pairs = 0;     // face pairs asked the exact question (boxes overlap, no shared corner)
  uint64_t segments = 0;  // pairs that cross
  // In parts: the parts whose share of the buffer filled up (they handed the rest of their
  // cells to the calling thread). The one count that depends on the parts.
  uint32_t parts_full = 0;
};

// The parts to draw in and their buffer (any size: what does not fit is drawn on the calling
// thread). Null runner or buffer: one part, here, with no buffer.
using LineParts = PartsBuffer;
inline constexpr uint32_t kMaxLineParts = 64;  // parts (4 a thread), whatever the runner's count

// Every crossing of topo's faces in the grid, piece by piece. `front`: each triangle's facing
// when the faces make closed solids (only front faces hide; the grid may hold those alone);
// null: both sides of every face. The pieces, their order and the stats (but parts_full) do
// not depend on the parts (when the sink fails, the stats may count pairs past the piece it
// refused).
Status draw_intersections(const Topology& topo, const uint8_t* front, const FaceGrid& fg,
                          LineSink sink, IntersectionStats* stats, LineRows rows = LineRows{},
                          LineParts parts = LineParts{});

}  // namespace haloplot
