// The drawing modes as strokes: which parts of a piece of an edge the pen draws. Shared by the
// host tool and the controller so both draw the same strokes in the same order.
//   all             every piece of every input edge
//   hidden-removed  pieces with QI 0 (and the visible parts of contour diagonals)
//   hidden-dashed   those, plus the hidden parts cut into dashes: `dash` steps drawn, `gap`
//                   steps skipped, measured along the edge from where its hidden run starts
//                   (half a gap in when it starts at the first corner of the edge; along a
//                   contour diagonal, from its middle: diagonal_dashes). An edge or diagonal
//                   no longer than a dash and a gap is dashed by where it lies on the page
//                   instead (page_dashes), so a curve of many short sides is dashed along it.
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

// What a piece belongs to: an input edge (its hidden runs dashed from where they start), a
// contour diagonal (a side drawn only where it is a contour: its hidden parts dashed from its
// middle), or a line on the faces (an intersection or hatch line: visible parts only).
enum class PieceKind : uint8_t { kEdge = 0, kContour = 1, kLine = 2 };

struct StrokeStyle {
  SolidMode mode = SolidMode::kHiddenRemoved;
  int32_t dash = 160, gap = 80;  // steps (2 mm and 1 mm at 80 steps per mm), both >= 1
  // The edges given are the page turned a quarter (geometry/quarter_turn.h: a band of a wide
  // drawing): page_dashes reads where they lie on the page itself.
  bool turned = false;
};

// Calls emit(span) for each stroke of the piece [t0, t1) of edge e (index `edge`, of `kind`).
// Returns the first status emit returns that is not kOk.
template <typename Emit>
Status piece_strokes(const Edge3& e, uint32_t edge, PieceKind kind, int64_t t0, int64_t t1,
                     bool hidden, const StrokeStyle& style, Emit emit);

// Strokes of pieces given edge by edge and along each edge (t0 ascending, as the QI method and
// the fallback emit them), a hidden run's dashes measured from its start: a hidden piece
// (hidden-dashed, of an input edge) is held until the next piece shows whether its run goes on,
// and finish() strokes the last one. emit(span, q): q the piece's, for a dash its run's first.
class DashedRuns {
 public:
  template <typename Emit>
  Status piece(const Edge3& e, uint32_t edge, PieceKind kind, int64_t t0, int64_t t1, bool hidden,
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
  Span s{{edge, t0, t1}, 0, 0, 0, 0};
  span_point(e, t0, &s.x0, &s.y0);
  span_point(e, t1, &s.x1, &s.y1);
  return s;
}

// A contour diagonal's hidden part [t0, t1) as dashes laid out from the diagonal's middle, one
// centred there and the rest a period apart both ways, wherever the part starts: a diagonal is
// found afresh in every band of a banded plot (its number, the way it runs and, in a band
// turned a quarter, its coordinates are the band's), and the middle alone is the same in all of
// them, so every band draws the whole-model plot's dashes.
template <typename Emit>
Status diagonal_dashes(const Edge3& e, uint32_t edge, int64_t t0, int64_t t1, int64_t dash,
                       int64_t period, Emit emit) {
  constexpr int64_t kHalf = int64_t{1} << 31;
  const int64_t half_dash = (dash + 1) / 2;  // the same either way along the diagonal
  // Dash k covers [kHalf - half_dash + k period, kHalf + half_dash + k period).
  const int64_t first = kHalf - half_dash;
  int64_t k = (t0 - first) / period - 1;  // at or before the first dash meeting [t0, t1)
  for (;; ++k) {
    const int64_t d0 = first + k * period;
    if (d0 >= t1) break;
    const int64_t a = d0 < t0 ? t0 : d0, b = d0 + 2 * half_dash > t1 ? t1 : d0 + 2 * half_dash;
    if (b <= a) continue;
    const Status s = emit(make_stroke(e, edge, a, b));
    if (s != Status::kOk) return s;
  }
  return Status::kOk;
}

// The hidden part [t0, t1) of a short edge or diagonal (no longer than a dash and a gap on
// paper) as the dashes of the page's own pattern: drawn where c mod (dash + gap) < dash, c the
// page coordinate along the edge's longer axis. A curve divided into sides shorter than a dash
// (a dense mesh's contour or crease) would otherwise get a whole dash on every side, drawn solid;
// this pattern goes on from one side into the next wherever they meet (the same point, the same
// c), so the curve is dashed along it, each dash 1 to 1.42 times as long as asked (as the curve
// runs along an axis or at 45 degrees). Where the longer axis changes between two sides the
// pattern jumps once. It depends on the point alone, not on the edge's number, direction or
// band, so every band draws the whole-model plot's dashes.
// The dashes page_dashes() draws: at most kPageDashes ranges of t in [t0, t1), ascending (the
// edge is no longer than one period on its longer axis, so it meets at most three windows).
// Out of line: every sink that strokes pieces shares one copy on the chip.
constexpr int kPageDashes = 3;
int page_dash_ranges(const Edge3& e, int64_t t0, int64_t t1, const StrokeStyle& style,
                     int64_t ranges[kPageDashes][2]);

template <typename Emit>
Status page_dashes(const Edge3& e, uint32_t edge, int64_t t0, int64_t t1, const StrokeStyle& style,
                   Emit emit) {
  int64_t r[kPageDashes][2];
  const int n = page_dash_ranges(e, t0, t1, style, r);
  for (int i = 0; i < n; ++i) {
    const Status s = emit(make_stroke(e, edge, r[i][0], r[i][1]));
    if (s != Status::kOk) return s;
  }
  return Status::kOk;
}

template <typename Emit>
Status piece_strokes(const Edge3& e, uint32_t edge, PieceKind kind, int64_t t0, int64_t t1,
                     bool hidden, const StrokeStyle& style, Emit emit) {
  const bool all = style.mode == SolidMode::kAll;
  if (all && kind != PieceKind::kEdge) return Status::kOk;  // not an input edge
  if (!hidden || all) return emit(make_stroke(e, edge, t0, t1));
  if (style.mode != SolidMode::kHiddenDashed || kind == PieceKind::kLine) return Status::kOk;
  const int64_t len = paper_length(e);
  if (len <= int64_t{style.dash} + style.gap) return page_dashes(e, edge, t0, t1, style, emit);
  // Dashes in Q0.32 of this edge; the dash rounds up so it is never shorter than asked.
  const int64_t dash = (int64_t{style.dash} << 32) / len + 1;
  const int64_t period = dash + (int64_t{style.gap} << 32) / len;
  if (kind == PieceKind::kContour) return diagonal_dashes(e, edge, t0, t1, dash, period, emit);
  // A run that starts at the first corner of the edge begins with half a gap: the hidden edges
  // that leave one corner would otherwise each begin with a whole dash there, drawn as one
  // stroke twice as long; where an edge comes out from behind a face the run begins with a
  // dash. (Both depend on the edge alone, so a band decides as the whole plot does.)
  const int64_t lead = t0 == 0 ? (period - dash) / 2 : 0;
  for (int64_t t = t0 + lead; t < t1; t += period) {
    const Status s = emit(make_stroke(e, edge, t, t + dash < t1 ? t + dash : t1));
    if (s != Status::kOk) return s;
  }
  return Status::kOk;
}

template <typename Emit>
Status DashedRuns::piece(const Edge3& e, uint32_t edge, PieceKind kind, int64_t t0, int64_t t1,
                         bool hidden, int32_t q, const StrokeStyle& style, Emit emit) {
  const bool run = hidden && kind == PieceKind::kEdge;
  if (held_ && run && edge == edge_ && t0 == t1_) {  // the run goes on
    t1_ = t1;
    return Status::kOk;
  }
  const Status s = finish(style, emit);
  if (s != Status::kOk) return s;
  if (run && style.mode == SolidMode::kHiddenDashed) {
    held_ = true;
    e_ = e;
    edge_ = edge;
    t0_ = t0;
    t1_ = t1;
    q_ = q;
    return Status::kOk;
  }
  return piece_strokes(e, edge, kind, t0, t1, hidden, style,
                       [&emit, q](const Span& span) { return emit(span, q); });
}

template <typename Emit>
Status DashedRuns::finish(const StrokeStyle& style, Emit emit) {
  if (!held_) return Status::kOk;
  held_ = false;
  const int32_t q = q_;
  return piece_strokes(e_, edge_, PieceKind::kEdge, t0_, t1_, true, style,
                       [&emit, q](const Span& span) { return emit(span, q); });
}

}  // namespace haloplot
