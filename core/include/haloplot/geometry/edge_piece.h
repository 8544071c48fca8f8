// The one interval type of the stages: a part of an edge, or of a segment a stage numbers
// itself (a line on the faces, a hatch line), its ends as positions along it from its first
// vertex in Q0.32 (t = 1 is 2^32), t0 < t1. Each stage's piece is an EdgePiece and what that
// stage adds (a QI, the rounded ends, the faces a line lies on); the bands keep theirs packed in
// 16 bytes (band/band_attempt.h StoredPiece), the only other form.
#pragma once
#include <stdint.h>

namespace haloplot {

struct EdgePiece {
  uint32_t edge;
  int64_t t0, t1;
};

}  // namespace haloplot
