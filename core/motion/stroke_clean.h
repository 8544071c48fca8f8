// Stroke clean-up, run by the path planner (motion/path_plan.h) on each plan's spans, in whole
// plot steps, before they are joined: what real models hand the pen and a plotter should not
// draw.
//   - Zero-length spans (dots) are dropped, every one, alone or not: a pen-down move that goes
//     nowhere is a lift and a put-down for a blot, never a line. A span is a dot when its
//     rounded ends coincide; a line shorter than a step is below what the pen can draw.
//   - Collinear spans whose extents overlap (near-duplicate faces, coincident edges of separate
//     parts) are drawn once, as their union: an exact integer test on the rounded spans, no
//     tolerance. Spans that only touch end to end stay apart (joining chains them; merging them
//     would hide the shared point from a third span that ends there).
// In place, and no span moves: a union takes the place of its first span (in input order,
// in that span's direction), the other spans of its run become dots at their first end, and
// the planner then skips every dot. So the clean-up needs no copy of the spans (a controller's
// arena holds the same plans as before), a plan's groups (layers) stay where they were, and
// input with nothing to clean plans exactly as before. The union's ends are ends of the merged
// spans: no new coordinate is made.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/motion/path_plan.h"

namespace haloplot {

// The collinearity test's bit budget: coordinates within +-2^kCleanCoordBits (plot steps are
// within 2^20), so a difference (and a line's primitive direction (a, b)) fits in
// kCleanCoordBits + 2 bits signed, the line's offset b*x - a*y and position a*x + b*y in
// 2 * kCleanCoordBits + 3, and an overlap's squared length (length_floor) in
// 2 * kCleanCoordBits + 3 unsigned. A span outside the budget is kept as given (never merged).
inline constexpr int kCleanCoordBits = 29;
static_assert(kCleanCoordBits + 2 <= 32, "a line's direction must fit in int32_t");
static_assert(2 * kCleanCoordBits + 3 <= 63, "line offset, position, squared length: int64_t");

// Workspace bytes clean_spans() needs for n spans: 40 a span, less than the planner's links,
// chains and endpoint sort that it shares its place with (motion/path_plan.cpp), so the
// clean-up adds nothing to path_plan_bytes().
size_t stroke_clean_bytes(uint32_t n);

// Cleans spans[0, n) in place, and counts the dots and merges in *st (dots_dropped,
// overlaps_merged, overlap_length). `workspace` starts on a kBufferAlignment (8) boundary.
Status clean_spans(Segment2* spans, uint32_t n, void* workspace, size_t workspace_bytes,
                   PathStats* st);

}  // namespace haloplot
