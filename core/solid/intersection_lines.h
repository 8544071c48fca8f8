// Intersection lines: the parts of every face crossing (solid/face_crossing.h) that show.
//
// Pairs: two faces can cross only where their boxes overlap on paper, so the pairs are read
// from the face grid, each in one cell only (the cell of the boxes' common lower-left corner)
// and only when their boxes overlap in depth too. With `front` (closed solids) a crossing on a
// back face is skipped: the ray to it runs inside that face's own solid, so a front face of
// that solid hides it.
//
// Visibility, as the topology-free method decides an edge's (solid/fallback.h): along the
// segment, what covers it can change only where it crosses a face's side on paper, meets a
// face's corner, or passes through a face (solid/pierce.h), so it is cut there (Q0.32, floor)
// and the middle of each piece asks every face of its cell but the segment's own two
// (solid/cover.h). No memory of its own: the cuts are found one after another, in order.
#pragma once
#include <stdint.h>

#include "solid/face_grid.h"
#include "solid/topology.h"
#include "status/status.h"

namespace haloplot {

struct IntersectionPiece {
  uint32_t index;    // the segment's number, in the order they are found (cells, then pairs)
  uint32_t face[2];  // the two triangles that cross
  const Edge3* segment;
  int64_t t0, t1;  // Q0.32 along the segment
  int32_t q;       // halves of cover
  bool hidden;
};

struct IntersectionSink {
  Status (*emit)(void* context, const IntersectionPiece& piece);
  void* context;
};

// A band's rows (band/band_rule.h): each segment is cut where it enters and leaves rows
// [lo, hi) (geometry/rows.h) and only the pieces between are tested and emitted. A piece the
// lower border cut too short to hold a test point is asked at the border itself, inside the
// piece it was cut from, so the band's pieces are the whole run's pieces cut at the borders.
// Every face that can cover a point of those rows meets them: the band's input holds it.
struct IntersectionRows {
  bool on = false;
  int32_t lo = 0, hi = 0;
};

struct IntersectionStats {
  uint64_t pairs = 0;     // face pairs asked the exact question (boxes overlap, no shared corner)
  uint64_t segments = 0;  // pairs that cross
  uint64_t pieces = 0, tests = 0, face_tests = 0;
};

// Every crossing of topo's faces in the grid, piece by piece. `front`: each triangle's facing
// when the faces make closed solids (only front faces hide; the grid may hold those alone);
// null: both sides of every face.
Status draw_intersections(const Topology& topo, const uint8_t* front, const FaceGrid& fg,
                          IntersectionSink sink, IntersectionStats* stats,
                          IntersectionRows rows = IntersectionRows{});

}  // namespace haloplot
