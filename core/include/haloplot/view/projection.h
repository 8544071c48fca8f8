// The view transform: world vertices to plot steps, in fixed point (the README's convention).
//
//   x' = x cos(az) - y sin(az),  y1 = x sin(az) + y cos(az)
//   screen y' = z cos(el) + y1 sin(el),  depth d = z sin(el) - y1 cos(el)   (larger d = nearer)
//
// then fitted uniformly into the plot area (the same steps per world unit on both axes,
// centred on neither: the lower-left corner sits at the margin) and depth scaled to
// [0, 2^20). With View::perspective = D, the eye sits on the view axis at depth D and a point
// at depth d is scaled by D / (D - d) before the fit, depth included: d D / (D - d) orders
// nearer and farther as d does, and is linear along every projected edge (the projective
// depth), so the depths CUT and the hidden-line tests interpolate are the scene's.
//
// Numbers: world coordinates within +-2^20; sin and cos in Q2.30 (view/trig.h); the rotated
// values are exact products in int64 (< 2^53) and are fitted with one rounding per output.
// Perspective divides once, in 128 bits, to Q16 world units (points at least kEyeClearance
// from the eye plane keep the quotient below 2^59). Error against exact real arithmetic: at
// most 1/2 step from the final rounding plus 2^-9 step from the trigonometry, the division
// and the fit's pre-shift (tested against long double, near the eye plane too).
#pragma once
#include <stdint.h>

#include "haloplot/geometry/contract.h"
#include "haloplot/status/status.h"

namespace haloplot {

inline constexpr int32_t kWorldLimit = int32_t{1} << 20;  // |world coordinate| <= this

struct View {
  int32_t azimuth_mdeg = 30000;  // millidegrees
  int32_t elevation_mdeg = 40000;
  int32_t width = 20000, height = 16000;  // plot area, steps
  int32_t margin = 400;                   // lower-left corner of the plot area
  // Perspective: the eye on the view axis at this depth (world units, in front of the world
  // origin); 0 is orthographic. A point at depth d maps to (x', y', d) * D / (D - d).
  int32_t perspective = 0;
  // Sub-step bits s: the projected scene is fitted in units of 2^-s steps (the plot area times
  // 2^s, which must stay inside the coordinate range), so every topological decision is made
  // on the model 2^s times finer than the pen moves; only emitted positions are rounded to
  // steps (geometry/units.h). 0: whole steps.
  int32_t substep_bits = 0;
};

// The sub-step bits the host tool and job files fit an .obj scene with unless told otherwise
// (where the plot area leaves room), chosen on the resolution axis of docs/reports/accuracy.md: the
// drawing follows the model there at a cost within a few per cent of whole steps. View{}
// itself stays in whole steps: a caller of the core asks for units explicitly.
inline constexpr int32_t kDefaultSubstepBits = 5;

// Points nearer the eye plane than this (world units) are refused: the perspective divisor
// would magnify them beyond the format (kCoordinateOutOfRange).
inline constexpr int32_t kEyeClearance = 1;

// Validates the view (plot area, times 2^substep_bits, inside the coordinate range).
Status validate(const View& v);

// Projects n world points into plot steps. `out` may be `world` itself (two passes: the
// first finds the bounds, the second writes). kCoordinateOutOfRange names a world point
// beyond kWorldLimit; kBadParameter a bad view. A single point, or points all on one screen
// line, map to the margin on the degenerate axis.
Status project_points(const View& view, const Point3* world, uint32_t n, Point3* out);

// The same with sine and cosine in Q16.16 (kTrigBits = 16: 17-bit constants, products that
// need no splitting, error up to about 2^-16 of the scene's extent) or Q2.30 (30, the
// default above). The accuracy benchmark measures both (docs/reports/accuracy.md).
template <int kTrigBits>
Status project_points_with(const View& view, const Point3* world, uint32_t n, Point3* out);

// Edges from vertex index pairs (2 per edge); kBadParameter for an index beyond n_points.
Status edges_from_indices(const Point3* points, uint32_t n_points, const uint32_t* pairs,
                          uint32_t n_edges, Edge3* out);

}  // namespace haloplot
