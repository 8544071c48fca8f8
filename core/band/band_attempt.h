// The conductor's working state for one try at one band, shared by its edge stages
// (conductor.cpp, band_path.cpp) and its solid stage (solid_band.cpp). Internal to core/band.
#pragma once
#include <stdint.h>

#include "haloplot/band/band_rule.h"
#include "haloplot/band/conductor.h"
#include "haloplot/geometry/quarter_turn.h"
#include "haloplot/solid/mesh.h"
#include "haloplot/sort/lower_bound.h"

namespace haloplot {
namespace band_detail {

inline uint8_t* align_up(uint8_t* p) {
  return reinterpret_cast<uint8_t*>((reinterpret_cast<uintptr_t>(p) + 7) & ~uintptr_t{7});
}
inline uint8_t* align_down(uint8_t* p) {
  return reinterpret_cast<uint8_t*>(reinterpret_cast<uintptr_t>(p) & ~uintptr_t{7});
}

// Statuses that mean "this band is too large for the arena": the conductor halves it.
inline bool does_not_fit(Status s) {
  return s == Status::kWorkspaceTooSmall || s == Status::kCrossingCapacity ||
         s == Status::kCutsetStorageTooSmall || s == Status::kSinkFull;
}

// A piece as a band keeps it until the band is committed: its band-local edge, its ends
// (t0 < 2^32, t1 >= 1) and x0 + x1 of its rounded ends (the path column). 16 bytes, the size of
// the Segment2 it becomes in place once the band fits.
struct StoredPiece {
  uint32_t local, t0, t1_minus_1;
  int32_t x_sum;
};
static_assert(sizeof(StoredPiece) == sizeof(Segment2), "pieces turn into segments in place");

struct RowPoint {
  int32_t x, y;
};
inline bool point_less(const RowPoint& p, const RowPoint& q) {
  return p.x != q.x ? p.x < q.x : p.y < q.y;
}

inline bool segment_less(const Segment2& p, const Segment2& q) {
  if (p.x0 != q.x0) return p.x0 < q.x0;
  if (p.y0 != q.y0) return p.y0 < q.y0;
  if (p.x1 != q.x1) return p.x1 < q.x1;
  return p.y1 < q.y1;
}

// Is p among the sorted points?
inline bool holds(const RowPoint* pts, uint32_t n, int32_t x, int32_t y) {
  const RowPoint p{x, y};
  const uint32_t lo = lower_bound_index(0, n, [&](uint32_t i) { return point_less(pts[i], p); });
  return lo < n && pts[lo].x == x && pts[lo].y == y;
}

// The point at t along a band's edge, rounded as the page rounds it: in a turned plot
// (geometry/quarter_turn.h) the edge is turned back first, since lerp_round rounds halves up
// and would round a turned coordinate's half the other way; the point is then turned again.
inline void frame_point(bool turned, const Edge3& e, int64_t t, int32_t* x, int32_t* y) {
  if (!turned) return span_point(e, t, x, y);
  int32_t px = 0, py = 0;
  span_point(unturn_edge(e), t, &px, &py);
  const Point3 q = turn_point(Point3{px, py, 0});
  *x = q.x;
  *y = q.y;
}

// x0 + x1 of the piece [t0, t1) of e, rounded as above: the key of its path column.
inline int32_t frame_x_sum(bool turned, const Edge3& e, int64_t t0, int64_t t1) {
  int32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  frame_point(turned, e, t0, &x0, &y0);
  frame_point(turned, e, t1, &x1, &y1);
  return x0 + x1;
}

}  // namespace band_detail
using namespace band_detail;

// One try at one band: its rows, its edges, and where DRAW's output goes.
struct BandConductor::Attempt {
  int64_t y0 = 0, y1 = 0;
  Gathered g{};
  CutSet cs;
  uint8_t* after = nullptr;  // where the CUTSET ends (or the edges, without CUT)
  const Carry* carry_in = nullptr;
  uint32_t n_carry_in = 0, carry_cursor = 0, carry_used = 0;
  Carry* carry_out = nullptr;
  const CarryRun* carry_runs_in = nullptr;  // a solid's: the runs beside the carry
  CarryRun* carry_runs_out = nullptr;
  // Each carried piece's lower end, rounded (for joining): the edge stage's; a solid's band
  // leaves it null and the commit finds the ends on the band's edges.
  RowPoint* carry_points = nullptr;
  uint32_t n_carry_out = 0, carry_capacity = 0;
  StoredPiece* pieces = nullptr;
  uint32_t n_pieces = 0, piece_capacity = 0;
  // A solid's lines on its faces and contour diagonals: their segments, stacked down from
  // lines_end; a stored piece whose local index is g.n + k lies on lines_end[-1 - k].
  const Edge3* lines_end = nullptr;
  uint32_t n_lines = 0;
  size_t need = 0;      // bytes asked for by the stage that did not fit
  size_t gathered = 0;  // a solid's band: the arena's bytes while its input was gathered
  SolidInput in{};      // a solid's band: its faces and drawn edges, local vertex indices
  bool turned = false;  // the band is in the page turned a quarter (BandSpec::turn_wide)

  // DRAW's sink: keep what this band owns, carry what runs past its top (band_rule.h).
  static Status on_span(void* ctx, const Span& s) {
    Attempt& a = *static_cast<Attempt*>(ctx);
    const Edge3& e = a.g.edges[s.edge];
    const uint32_t id = a.g.id(s.edge);
    const int64_t up = upper_end(e, s.t0, s.t1), low = lower_end(e, s.t0, s.t1);
    if (row_compare(e, up, a.y0) < 0) return Status::kOk;  // below: an earlier band drew it
    int64_t lower = low;
    if (row_compare(e, low, a.y0) < 0) {  // began below this band: continue the carried piece
      while (a.carry_cursor < a.n_carry_in && a.carry_in[a.carry_cursor].edge < id)
        ++a.carry_cursor;
      if (a.carry_cursor == a.n_carry_in || a.carry_in[a.carry_cursor].edge != id)
        return Status::kBandCarryLost;
      lower = int64_t{a.carry_in[a.carry_cursor++].lower} + (rising(e) ? 0 : 1);
      ++a.carry_used;
    }
    if (row_compare(e, up, a.y1) >= 0) {                       // runs past the top
      if (row_compare(e, low, a.y1) >= 0) return Status::kOk;  // wholly above: a later band's
      if (a.n_carry_out == a.carry_capacity) return Status::kBandCarryLost;  // one per edge
      span_point(e, lower, &a.carry_points[a.n_carry_out].x, &a.carry_points[a.n_carry_out].y);
      a.carry_out[a.n_carry_out++] = Carry{id, uint32_t(lower - (rising(e) ? 0 : 1))};
      return Status::kOk;
    }
    if (a.n_pieces == a.piece_capacity) return Status::kSinkFull;
    const int64_t t0 = rising(e) ? lower : up, t1 = rising(e) ? up : lower;
    Segment2 g;
    span_point(e, t0, &g.x0, &g.y0);
    span_point(e, t1, &g.x1, &g.y1);
    a.pieces[a.n_pieces++] = StoredPiece{s.edge, uint32_t(t0), uint32_t(t1 - 1), g.x0 + g.x1};
    return Status::kOk;
  }
};

}  // namespace haloplot
