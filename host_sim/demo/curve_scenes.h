// Space curves as cubic Bézier edges, for the curved-edge stages (core/curve/): a trefoil
// knot, a (p, q) torus knot and a helix.
//
// Fitting: the curve is cut into n equal parameter steps and each step becomes the cubic
// Hermite segment through its two end points with the curve's derivatives there (the Bézier
// control points P0, P0 + h/3 f'(t0), P3 - h/3 f'(t1), P3). Neighbouring edges share their
// end point exactly (it is rounded once), so a knot is a closed chain of edges.
//
// Projection: orthographic by default, by projecting the 3-D control points (perspective: see
// CurveView::perspective). A rotation followed by
// dropping the depth axis is affine, and an affine map of a Bézier's control points is the
// Bézier of the mapped curve, so nothing is approximated beyond the fit itself. x and y are
// then scaled (one factor, aspect kept) into [margin, size - margin]; depth into the same
// range by its own factor (any increasing affine map of depth keeps front and back).
#pragma once
#include <cstdint>
#include <vector>

#include "haloplot/curve/bezier.h"

namespace haloplot::host {

struct CurveScene {
  std::vector<BezierEdge3> curves;
  std::vector<Edge3> segments;  // straight edges (the helix's axis)
};

struct CurveView {
  double tilt = 0;  // rotation about the x axis before projecting, radians
  double turn = 0;  // then about the (new) y axis
  int32_t size = 1 << 16;
  int32_t margin = 1 << 10;
  // Perspective: the eye's distance from the curve's centre, in world units with the rotated
  // curve's largest extent 2^19 units (as a model's --perspective D); 0 is orthographic. The
  // perspective image of a cubic is not a cubic: the image of the curve itself is fitted
  // instead, Hermite step by step, each step halved until it is within kPerspectiveFitSteps of
  // the image (64 points a step, after scaling to the view), so the edge count can grow.
  double perspective = 0;
};
inline constexpr double kPerspectiveFitSteps = 0.25;

// The trefoil (sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t): seen from above, 3 crossings.
CurveScene trefoil_knot(int edges, const CurveView& view);
// The (p, q) torus knot ((2 + cos qt) cos pt, (2 + cos qt) sin pt, -sin qt), t in [0, 2 pi]:
// seen from above, q (p - 1) crossings.
CurveScene torus_knot(int p, int q, int edges, const CurveView& view);
// A helix of `turns` turns (radius 1, rise `pitch` per turn) around the z axis, seen tilted so
// its turns cross; with_axis adds the axis as a straight edge through it.
CurveScene helix(double turns, double pitch, int edges, bool with_axis, const CurveView& view);

}  // namespace haloplot::host
