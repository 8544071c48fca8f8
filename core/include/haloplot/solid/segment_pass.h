// What shows of a segment lying on faces of the model (an intersection line on its two faces,
// a hatch line on its face), decided as the topology-free method decides an edge's
// (solid/fallback.h): along the segment, what covers it can change only where it crosses a
// face's side on paper, meets a face's corner, or passes through a face (solid/pierce.h), so it
// is cut there (Q0.32, floor) and the middle of each piece asks every face of its grid cell
// but the segment's own (solid/cover.h). Pieces of equal cover are merged. No memory of its
// own: the cuts are found a batch at a time, in order, from one look along the segment's cells.
#pragma once
#include <stdint.h>

#include "haloplot/cut/grid.h"
#include "haloplot/geometry/edge_piece.h"
#include "haloplot/solid/face_grid.h"
#include "haloplot/solid/topology.h"
#include "haloplot/status/sink.h"
#include "haloplot/status/status.h"

namespace haloplot {

// edge: the segment's number, as its pass numbers it; t0, t1: Q0.32 along the segment.
struct LinePiece : EdgePiece {
  uint32_t face[2];  // the faces it lies on (face[1] kNoFace for a hatch line)
  const Edge3* segment;
  int32_t q;  // halves of cover
  bool hidden;
};

using LineSink = Sink<LinePiece>;

// A band's rows (band/band_rule.h): the segment is cut where it enters and leaves rows
// [lo, hi) (geometry/rows.h) and only the pieces between are tested and emitted. A piece
// either border cut too short to hold a test point is asked at the border itself, inside the
// piece it was cut from, so the band's pieces are the whole run's pieces cut at the borders.
// Every face that can cover a point of those rows or of the row above meets them: the band's
// input holds it.
struct LineRows {
  bool on = false;
  int32_t lo = 0, hi = 0;
};

struct LineCounts {
  uint64_t pieces = 0, tests = 0, face_tests = 0;
};

// A box around three points (a face, or a segment with b given twice).
struct FaceBox {
  int32_t x0, x1, y0, y1, z0, z1;
};
inline FaceBox box_of(const Point3& a, const Point3& b, const Point3& c) {
  return FaceBox{min_i32(a.x, min_i32(b.x, c.x)), max_i32(a.x, max_i32(b.x, c.x)),
                 min_i32(a.y, min_i32(b.y, c.y)), max_i32(a.y, max_i32(b.y, c.y)),
                 min_i32(a.z, min_i32(b.z, c.z)), max_i32(a.z, max_i32(b.z, c.z))};
}
inline bool overlap_on_paper(const FaceBox& a, const FaceBox& b) {
  return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
}

// Every corner of triangle u on the plane of triangle t (exact 3-D orientations).
bool coplanar_faces(const Topology& topo, uint32_t t, uint32_t u);

struct SegmentPass {
  const Topology& topo;
  const uint8_t* front;  // only front faces hide (closed solids); null: every face, both sides
  const FaceGrid& fg;
  LineCounts* st;
  Edge3 s;
  uint32_t own[2];
  // Not kNoFace: the faces of this polygon that are coplanar with own[0] are the segment's own
  // too (a hatch line lies on its whole flat polygon; a bent polygon's other half can fold
  // over it, and is asked like any face).
  uint32_t own_polygon = kNoFace;
  // With `front` (closed solids): the faces that share a side with triangles [own_first,
  // own_end) are not asked either. Two front faces of a closed, consistently oriented solid that
  // share a side lie on opposite sides of it on paper, so such a neighbour covers nothing of the
  // polygon; it could only cover where a line's rounded end overhangs its polygon, and a hidden
  // sliver there would leave a dot of ink before it. Without `front` (both sides hide: open
  // meshes) a neighbour is passed where it lies strictly across the side it shares on paper and
  // none of [own_first, own_end) reaches over that side's line: then it covers none of them.
  uint32_t own_first = 0, own_end = 0;

  // Cut, test, merge equal neighbours, emit: the whole segment, or its part in the rows.
  Status run(uint32_t index, LineSink sink, LineRows rows) const;

  bool asks(uint32_t k) const;
  bool neighbour(uint32_t k) const;
  bool own_faces_short_of(const Point3& a, const Point3& b, int across) const;
  static constexpr int kBatch = 16;
  int next_cuts(int64_t after, int64_t cuts[kBatch]) const;
  int32_t cover_at(int64_t m) const;
};

}  // namespace haloplot
