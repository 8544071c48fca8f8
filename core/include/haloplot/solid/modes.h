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
#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/quarter_turn.h"
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
template <typename Emit>
Status page_dashes(const Edge3& e, uint32_t edge, int64_t t0, int64_t t1, const StrokeStyle& style,
                   Emit emit) {
  // (v - ca) 2^32 for page coordinates below 2^kCoordBits: one int64.
  static_assert(kCoordBits + 1 + 32 < 63, "a page coordinate's parameter fits in int64");
  const Edge3 p = style.turned ? unturn_edge(e) : e;
  const int64_t dx = int64_t{p.b.x} - p.a.x, dy = int64_t{p.b.y} - p.a.y;
  const bool along_x = (dx < 0 ? -dx : dx) >= (dy < 0 ? -dy : dy);
  const int64_t ca = along_x ? p.a.x : p.a.y, cb = along_x ? p.b.x : p.b.y;
  if (ca == cb) return Status::kOk;  // a point on paper
  const int64_t period = int64_t{style.dash} + style.gap;
  constexpr int64_t kOneT = int64_t{1} << 32;  // t = 1 in Q0.32
  const int64_t lo = ca < cb ? ca : cb, hi = ca < cb ? cb : ca;
  const int64_t k0 = floor_div(lo, period), k1 = floor_div(hi, period);
  // Windows in the order t runs: c ascending when the edge runs up its axis.
  for (int64_t i = 0; i <= k1 - k0; ++i) {
    const int64_t k = ca < cb ? k0 + i : k1 - i;
    int64_t w0 = k * period, w1 = w0 + style.dash;
    w0 = w0 < lo ? lo : w0;
    w1 = w1 > hi ? hi : w1;
    if (w1 <= w0) continue;
    // * 2^32, not << 32: w - ca is negative on an edge running down its axis.
    int64_t a = (w0 - ca) * kOneT / (cb - ca), b = (w1 - ca) * kOneT / (cb - ca);
    if (b < a) {
      const int64_t u = a;
      a = b;
      b = u;
    }
    a = a < t0 ? t0 : a;
    b = b > t1 ? t1 : b;
    if (b <= a) continue;
    const Status s = emit(make_stroke(e, edge, a, b));
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
