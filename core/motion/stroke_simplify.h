// Stroke simplification (PathClean::simplify, off by default), run by the path planner on the
// path it writes: a dense mesh's contours come as chains of many short segments, each a move
// the plotter starts and stops, where a few longer ones draw the same line within a tolerance.
//
// Each pen-down run keeps its first and last points. From the last kept point a, the run is
// followed as far as every point between a and the candidate b lies within `tolerance` steps of
// the segment a-b (a point beyond an end, of that end); the point before the first candidate
// that fails is kept and becomes a. So every dropped point is within the tolerance of the
// drawn line, exactly (integers, no rounding), which test stroke_simplify reads back from the
// G-code. A point on the edge of the strokes' box is always kept, so the box (where the host
// places the drawing on its page) does not move. The look ahead stops kWindow points on, so the
// work is linear in the points.
#pragma once
#include <stdint.h>

#include "haloplot/motion/path_plan.h"

namespace haloplot {

inline constexpr uint32_t kSimplifyWindow = 32;

// The distance test's bit budget: coordinates within +-2^kCleanCoordBits (stroke_clean.h), so
// differences within 2^(kCleanCoordBits + 1), dot products and squared lengths below
// 2^(2 kCleanCoordBits + 3), a cross product likewise; cross^2 and tolerance^2 * length^2 are
// Wide (geometry/wide.h). A point outside the budget is kept.
inline constexpr int kSimplifyCoordBits = 29;
static_assert(2 * (kSimplifyCoordBits + 1) + 1 <= 63, "dot and cross products fit in int64_t");
static_assert(2 * (2 * kSimplifyCoordBits + 3) <= 127, "cross^2 fits in a Wide");

// Simplifies points[0, n) in place (pen-up points and each run's ends kept); returns the new
// count and adds the dropped points to *dropped.
uint32_t simplify_strokes(PathPoint* points, uint32_t n, uint32_t tolerance, uint32_t* dropped);

}  // namespace haloplot
