// A haloed plot of a scene with curved edges in bands, in one fixed arena (docs/bands.md,
// "Curves in bands"): the curve job (job/job.h job_prepare_curves) for a drawing whose
// crossings, chords and path do not fit the arena at once.
//
// The plot is cut into horizontal bands [y0, y1) of the scene's rows. A chord belongs to the
// band that holds its upper end (the larger rounded y), so each chord of the whole drawing has
// exactly one owner. Unlike a straight edge's piece, a chord is never carried across a border:
// DRAW cuts a visible interval into chords by the interval's width, so a band must know the
// whole interval of every edge it owns chords of, and draws its chords whole.
//
// Why a band's chords are the whole drawing's. The band's own edges are those whose control
// points' box meets its rows (every chord it owns lies on one: a curve lies in that box, and
// rounding keeps a point in an integer box). It takes every edge whose box meets the rows of
// its own edges' boxes widened by margin = reach + 1, the reach measured by a margin pass
// (curve/curve_draw.h CurveDrawStats::reach: no gap reaches farther from its crossing). Every
// gap on an own edge then comes from a crossing whose edges are there (a crossing lies on both
// its edges, within reach of the gap), every joint a gap walks across has all its edges there,
// and the crossings of two edges do not depend on the other edges present (each pair is
// refined alone; the edges keep the scene's order, so ties fall the same way). So the band's
// own edges get the whole drawing's visible intervals, and the same chords. The margin pass
// runs the crossings and DRAW in bands taking only the edges that meet their rows: each
// crossing is found in the band that holds its point, with the tangents that size its gap.
//
// Band heights come from the arena: the first attempt is the whole scene (no margin pass when
// it fits); a band that does not fit is halved and tried again, never truncated; a band that
// fitted in half the arena lets the next one double. A band one row high that still does not
// fit is kArenaTooSmall, with the bytes it asked for in stats().need_bytes.
//
// Arena, during one band:
//   [band's curves | its segments | its scene indices | hits -> ...   | crossing scratch]
//   [band's curves | its segments | its scene indices | hits | DRAW scratch | chords    ]
//   [chords | path points | path workspace                                             ]
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/band/conductor.h"
#include "haloplot/curve/curve_draw.h"

namespace haloplot {

struct CurveBandSpec {
  CurveCrossParams cross;  // the job's (job/job.h curve_job_params), in the scene's units
  CurveDrawParams draw;
  int32_t substep_bits = 0;          // the scene's units are 2^-substep_bits steps
  int32_t start_x = 0, start_y = 0;  // the pen before the first band, steps
  // The planner's clean-up of each band's chords (motion/path_plan.h). No minimum stroke: a
  // stroke a border cuts goes on in the next band and is no crumb.
  PathClean clean;
  // > 0: no band taller than this many rows (a test's thin bands).
  int32_t max_rows = 0;
  // >= 0: this margin instead of the margin pass's. Unsafe below the measured one (gaps from
  // edges left out are lost); the band test uses it to show that its check sees that.
  int32_t fixed_margin = -1;
};

class CurveBands {
 public:
  // Checks the scene and the settings (the stages' plans); nothing is drawn yet. The arena
  // starts on a kBufferAlignment (8) boundary, or kMisalignedBuffer. The scene stays the
  // caller's, read by every band.
  Status begin(const CurveBandSpec& spec, const BezierEdge3* curves, uint32_t n_curves,
               const Edge3* segments, uint32_t n_segments, void* arena, size_t arena_bytes);
  // The next band's path points, from where the previous band left the pen; n == 0 when the
  // plot is done. The points live in the arena until the next call.
  Status next(const PathPoint** points, uint32_t* n);

  // Sees every chord once (edge: the scene's, curves first; the segment in steps), in the band
  // that owns it, and each band's rows as it commits.
  void set_observer(PieceObserver o) { observer_ = o; }
  const BandStats& stats() const { return stats_; }
  bool done() const { return done_; }

  // Adapter for MotionPlanner::set_feed: the planner pulls the bands itself.
  static Status feed(void* self, const PathPoint** points, uint32_t* n) {
    return static_cast<CurveBands*>(self)->next(points, n);
  }

  struct Band;  // one attempt's arrays (internal to curve_bands.cpp)

 private:
  Status margin_pass();
  // One attempt at rows [y0, y1): with `drawing` the band's chords and path, else (the margin
  // pass) its crossings and gaps only, for their reach. *fitted false: the arena was too small.
  Status attempt(int64_t y0, int64_t y1, bool drawing, bool* fitted);
  Status gather(int64_t lo, int64_t hi, Band* b);
  Status cross_and_draw(Band* b, bool drawing);
  Status commit(Band* b);
  void box_rows(uint32_t k, int64_t* lo, int64_t* hi) const;
  int64_t grown(int64_t rows) const;  // after a band that fitted
  void note(size_t bytes) {
    if (bytes > stats_.peak_bytes) stats_.peak_bytes = bytes;
    if (bytes > used_) used_ = bytes;
  }

  CurveBandSpec spec_{};
  const BezierEdge3* curves_ = nullptr;
  const Edge3* segments_ = nullptr;
  uint32_t nc_ = 0, ns_ = 0;
  uint8_t* arena_ = nullptr;
  size_t arena_bytes_ = 0;
  int64_t row_lo_ = 0, row_hi_ = 0;  // the scene's rows, inclusive
  int64_t next_row_ = 0, height_ = 0;
  int64_t margin_ = 0;
  bool margin_known_ = false;
  bool done_ = true;
  size_t used_ = 0;  // the current attempt's bytes
  const PathPoint* points_ = nullptr;
  uint32_t n_points_ = 0;
  int32_t pen_x_ = 0, pen_y_ = 0;
  PieceObserver observer_{};
  BandStats stats_{};
};

}  // namespace haloplot
