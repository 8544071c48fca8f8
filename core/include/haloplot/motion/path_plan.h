// Path planning: turn DRAW's visible spans into pen strokes a plotter can draw quickly.
//   0. Clean (motion/stroke_clean.h, unless PathClean::on is false), in place: drop
//      zero-length spans, draw collinear overlapping spans once (as their union).
//   1. Join spans that share an endpoint (exact integer equality) into polylines.
//   2. Order the polylines greedily: from the pen's position, go to the nearest free polyline
//      end, found by ring search in a uniform grid; flip the polyline if its far end was nearer.
//   2b. Drop strokes (joined chains) shorter than PathClean::min_stroke: crumbs a pen cannot
//      draw as lines, each a lift and a put-down for a blot.
//   3. Improve the order by 2-opt: reverse a run of the tour when that shortens the two pen-up
//      moves at its ends (runs of up to 48 polylines, at most 4 passes: linear in the tour).
//   4. With PathClean::simplify, leave out points of each stroke within that of the line drawn
//      instead (motion/stroke_simplify.h).
// The output is a list of path points: travel to a point with the pen up, or draw to it.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/status/status.h"

namespace haloplot {

struct Segment2 {
  int32_t x0, y0, x1, y1;
};

// Where the pen stands, in plot steps: one value, so a plan's start is not two int32_t side
// by side that could be swapped.
struct PenAt {
  int32_t x, y;
};

struct PathPoint {
  int32_t x, y;
  uint8_t pen_down;  // 1: draw from the previous point to here; 0: travel here pen up
};

struct PathStats {
  uint32_t polylines = 0;
  uint64_t pen_up_length = 0;        // planned order, plot steps (sum of rounded lengths)
  uint64_t naive_pen_up_length = 0;  // spans drawn one by one in input order
  uint64_t pen_down_length = 0;
  uint32_t pen_lifts = 0;  // pen-up moves between strokes in the planned order
  // The clean-up's work (motion/stroke_clean.h): zero-length spans dropped, spans drawn inside
  // another collinear one (and the length they would have drawn twice), strokes dropped as
  // shorter than PathClean::min_stroke (and their length). Lengths in plot steps.
  uint32_t dots_dropped = 0, overlaps_merged = 0, crumbs_dropped = 0;
  uint32_t points_simplified = 0;  // path points left out by PathClean::simplify
  uint64_t overlap_length = 0, crumb_length = 0;
};

// What the planner cleans from the strokes before it plans them (motion/stroke_clean.h).
// Every consumer of the path (the controller's job, the band conductor, the host's files)
// gets the same clean-up by planning through plan_path().
struct PathClean {
  bool on = true;  // false: the spans are planned exactly as given (a test's control)
  // Plot steps: a stroke (a chain of joined spans) shorter than this is dropped; 0 keeps all.
  uint32_t min_stroke = 0;
  // Plot steps: points of a stroke within this of the line drawn instead are left out
  // (motion/stroke_simplify.h); 0 keeps every point.
  uint32_t simplify = 0;
};

// Adds b's counts to a's (the layers of a plan, the columns of a band).
void add_path_stats(PathStats* a, const PathStats& b);

// Workspace bytes plan_path() needs for n spans, and the most path points it can write (2n).
size_t path_plan_bytes(uint32_t n_spans);
inline uint32_t path_points_max(uint32_t n_spans) { return 2 * n_spans; }

// Where the pen goes after this plan, when the caller knows (the next column of a band): the
// 2-opt then also counts the move from the tour's last end to there.
struct PathEnd {
  bool known = false;
  int32_t x = 0, y = 0;
};

// Plan from pen position `start`. `out` must hold path_points_max(n) points. With
// clean.on the spans are cleaned in place first (motion/stroke_clean.h: merged spans and dots
// left as dots, none moved); with it off they are planned as given, a dot as a dot.
// `workspace` starts on a kBufferAlignment (8) boundary, or the plan returns kMisalignedBuffer.
Status plan_path(Segment2* spans, uint32_t n, PenAt start, void* workspace, size_t workspace_bytes,
                 PathPoint* out, uint32_t out_capacity, uint32_t* out_count, PathStats* stats,
                 PathEnd end = PathEnd{}, PathClean clean = PathClean{});

// Line kinds drawn one after another, a pen each (the plot SVG's layers): visible edges,
// hidden dashes, intersection lines, hatching, outlines. A count per layer, in that order.
constexpr uint32_t kMaxLayers = 5;
struct LayerCounts {
  uint32_t n = 0;  // layers in use; 0: the whole input is one layer
  uint32_t count[kMaxLayers] = {};
};

// plan_path() for spans grouped by layer (layers.count[k] spans of layer k, one group after
// the other): each layer planned on its own, the first from (start_x, start_y), each next
// from where the previous one ended, so no layer's strokes mix with another's and a pen can be
// changed between them. A non-empty layer after another starts with a pen-up point even where
// the previous one ended (the pen lifts for the change). *points_per_layer (may be null): how
// many of the path points each layer wrote (0 for a layer whose strokes were all cleaned
// away). With layers.n <= 1 this is plan_path() exactly.
// The stats add up over the layers (naive_pen_up_length: the input order as given).
Status plan_path_layers(Segment2* spans, uint32_t n, const LayerCounts& layers, int32_t start_x,
                        int32_t start_y, void* workspace, size_t workspace_bytes, PathPoint* out,
                        uint32_t out_capacity, uint32_t* out_count, LayerCounts* points_per_layer,
                        PathStats* stats, PathClean clean = PathClean{});

// Spans in units of 2^-s steps (geometry/units.h) to whole steps, in place: the one rounding
// between a scene fitted finer than the pen moves and the path.
void round_to_steps(Segment2* spans, uint32_t n, int substep_bits);

// Length of (dx, dy) rounded down to whole plot steps.
uint32_t length_floor(int64_t dx, int64_t dy);

}  // namespace haloplot
