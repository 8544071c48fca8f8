// The one interval type of the stages: a part of an edge, or of a segment a stage numbers
// itself (a line on the faces, a hatch line), its ends as positions along it from its first
// vertex in Q0.32 (t = 1 is 2^32), t0 < t1. Each stage's piece is an EdgePiece and what that
// stage adds (a QI, the rounded ends, the faces a line lies on); the bands keep theirs packed in
// 16 bytes (band/band_attempt.h StoredPiece), the only other form. Two records look alike and
// are not pieces in this sense: a solid band's stack of one edge's pieces holds t0, t1 without
// the edge (band/solid_band.cpp RawPiece: the edge is the stack's), and the 2-D view's visible
// spans carry exact ratios along a polygon's side, not positions (view2d VisibleSpan).
#pragma once
#include <stdint.h>

namespace haloplot {

struct EdgePiece {
  uint32_t edge;
  int64_t t0, t1;
};

}  // namespace haloplot
