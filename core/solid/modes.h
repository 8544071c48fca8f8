// The drawing modes as strokes: which parts of a piece of an edge the pen draws. Shared by the
// host tool and the controller so both draw the same strokes in the same order.
//   all             every piece of every input edge
//   hidden-removed  pieces with QI 0 (and the visible parts of contour diagonals)
//   hidden-dashed   those, plus the hidden parts cut into dashes: `dash` steps drawn, `gap`
//                   steps skipped, measured along the edge from where its hidden run starts
// A hidden run is the hidden pieces of an edge that meet end to end: where it is cut inside (a
// change of QI behind the front faces, a band's border) starts no new pattern, so the dashes
// depend only on where the run starts on the edge, and a plot in bands (band/solid_band.cpp)
// draws the whole-model plot's dashes.
#pragma once
#include <stdint.h>

#include "haloplot/draw/draw.h"
#include "haloplot/status/status.h"

namespace haloplot {

enum class SolidMode : uint8_t { kAll = 0, kHiddenRemoved = 1, kHiddenDashed = 2 };

struct StrokeStyle {
  SolidMode mode = SolidMode::kHiddenRemoved;
  int32_t dash = 160, gap = 80;  // steps (2 mm and 1 mm at 80 steps per mm), both >= 1
};

// Calls emit(span) for each stroke of the piece [t0, t1) of edge e (index `edge`; a contour
// diagonal when `diagonal`). Returns the first status emit returns that is not kOk.
template <typename Emit>
Status piece_strokes(const Edge3& e, uint32_t edge, bool diagonal, int64_t t0, int64_t t1,
                     bool hidden, const StrokeStyle& style, Emit emit);

// Strokes of pieces given edge by edge and along each edge (t0 ascending, as the QI method and
// the fallback emit them), a hidden run's dashes measured from its start: a hidden piece
// (hidden-dashed, not a diagonal) is held until the next piece shows whether its run goes on,
// and finish() strokes the last one. emit(span, q): q the piece's, for a dash its run's first.
class DashedRuns {
 public:
  template <typename Emit>
  Status piece(const Edge3& e, uint32_t edge, bool diagonal, int64_t t0, int64_t t1, bool hidden,
               int32_t q, const StrokeStyle& style, Emit emit);
  template <typename Emit>
  Status finish(const StrokeStyle& style, Emit emit);
  void clear() { held_ = false; }

 private:
  bool held_ = false;
  Edge3 e_{};
  uint32_t edge_ = 0;
  int64_t t0_ = 0, t1_ = 0;
  int32_t q_ = 0;
};

// The length of the edge on paper in whole steps (at least 1): the dash scale.
int64_t paper_length(const Edge3& e);

inline Span make_stroke(const Edge3& e, uint32_t edge, int64_t t0, int64_t t1) {
  Span s{edge, t0, t1, 0, 0, 0, 0};
  span_point(e, t0, &s.x0, &s.y0);
  span_point(e, t1, &s.x1, &s.y1);
  return s;
}

template <typename Emit>
Status piece_strokes(const Edge3& e, uint32_t edge, bool diagonal, int64_t t0, int64_t t1,
                     bool hidden, const StrokeStyle& style, Emit emit) {
  if (style.mode == SolidMode::kAll && diagonal) return Status::kOk;  // not an input edge
  if (!hidden || style.mode == SolidMode::kAll) return emit(make_stroke(e, edge, t0, t1));
  if (style.mode != SolidMode::kHiddenDashed || diagonal) return Status::kOk;
  // Dashes in Q0.32 of this edge; the dash rounds up so it is never shorter than asked.
  const int64_t len = paper_length(e);
  const int64_t dash = (int64_t{style.dash} << 32) / len + 1;
  const int64_t period = dash + (int64_t{style.gap} << 32) / len;
  for (int64_t t = t0; t < t1; t += period) {
    const Status s = emit(make_stroke(e, edge, t, t + dash < t1 ? t + dash : t1));
    if (s != Status::kOk) return s;
  }
  return Status::kOk;
}

template <typename Emit>
Status DashedRuns::piece(const Edge3& e, uint32_t edge, bool diagonal, int64_t t0, int64_t t1,
                         bool hidden, int32_t q, const StrokeStyle& style, Emit emit) {
  if (held_ && hidden && !diagonal && edge == edge_ && t0 == t1_) {  // the run goes on
    t1_ = t1;
    return Status::kOk;
  }
  const Status s = finish(style, emit);
  if (s != Status::kOk) return s;
  if (hidden && !diagonal && style.mode == SolidMode::kHiddenDashed) {
    held_ = true;
    e_ = e;
    edge_ = edge;
    t0_ = t0;
    t1_ = t1;
    q_ = q;
    return Status::kOk;
  }
  return piece_strokes(e, edge, diagonal, t0, t1, hidden, style,
                       [&emit, q](const Span& span) { return emit(span, q); });
}

template <typename Emit>
Status DashedRuns::finish(const StrokeStyle& style, Emit emit) {
  if (!held_) return Status::kOk;
  held_ = false;
  const int32_t q = q_;
  return piece_strokes(e_, edge_, false, t0_, t1_, true, style,
                       [&emit, q](const Span& span) { return emit(span, q); });
}

}  // namespace haloplot
