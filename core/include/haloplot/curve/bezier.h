// Cubic Bézier edges (the HALO paper's section 5: curved edges) and their exact pieces.
//
// A BezierEdge3 is four integer control points in the contract's range (geometry/contract.h):
// x, y in units, z a depth (larger is nearer). An orthographic projection is affine, and an
// affine map keeps a Bézier a Bézier: the host projects the 3-D control points and hands the
// projected ones here. Depth is a Bézier too, so front/back at a crossing comes from the depth
// control points evaluated at the crossing's parameter.
//
// Pieces. De Casteljau's halving at t = 1/2 averages control points three times, so each
// level needs 3 more fractional bits to stay exact. A piece therefore stores its control
// points in fixed point Q20.42 (kCurveFracBits = 3 * kCurveMaxDepth): exact down to depth
// kCurveMaxDepth = 14, the deepest a piece may go. That is deep enough: a cubic's second
// differences shrink 4x per halving, so any in-range curve is flat within 2^-6.9 units at
// depth 14 (see Flatness below). A straight edge (a segment) is a piece too, with exact zero
// flatness; it is halved by its midpoint (1 bit per level, well inside the budget).
//
// Bit budget (signed int64 unless said):
//   control point coordinate    Q20.42, in [0, 2^62)       (inside the convex hull: in range)
//   difference of two points    |d| < 2^62
//   second difference           (P0 - P1) - (P1 - P2): |.| < 2^63
//   flatness bound (unsigned)   < 2^63; a sum of two < 2^64 (uint64_t)
//   cross / dot of differences  |.| < 2^125, in Wide (128-bit, geometry/wide.h)
//   bound numerator             2 products of (uint64 < 2^64) x (< 2^62) < 2^127, in Wide
#pragma once
#include <stdint.h>

#include "haloplot/geometry/contract.h"
#include "haloplot/geometry/wide.h"

namespace haloplot {

struct BezierEdge3 {
  Point3 p[4];
};

inline bool in_range(const BezierEdge3& e) {
  return in_range(e.p[0]) && in_range(e.p[1]) && in_range(e.p[2]) && in_range(e.p[3]);
}

inline constexpr int kCurveMaxDepth = 14;
inline constexpr int kCurveFracBits = 3 * kCurveMaxDepth;
inline constexpr int kCurvePointBits = kCoordBits + kCurveFracBits;  // unsigned magnitude
static_assert(kCurvePointBits <= 62, "a fixed-point coordinate and a difference fit int64_t");
static_assert(2 * kCurvePointBits + 1 <= 126, "a cross product of differences fits Wide");
static_assert(64 + kCurvePointBits + 1 <= 127, "a parameter-bound numerator fits Wide");

// Curve parameters as unsigned Q0.32 in a uint64_t: t * 2^32, so 2^32 itself is t = 1.
inline constexpr int kCurveParamBits = 32;
inline constexpr uint64_t kCurveParamOne = uint64_t{1} << kCurveParamBits;
static_assert(kCurveMaxDepth < kCurveParamBits, "a piece's interval is a whole number of Q0.32");

struct FixPoint3 {
  int64_t x, y, z;  // Q20.42
};

// The piece of curve `curve` on parameters [index, index + 1] * 2^-level, with its exact
// control points. A straight piece keeps p[1] = p[0] and p[2] = p[3].
struct CurvePiece {
  FixPoint3 p[4];
  uint32_t curve;
  uint32_t index;
  uint8_t level;
  bool straight;
  // The curve's own ends (t = 0, t = 1): a touch there is a T-junction, never a crossing.
  bool starts_curve() const { return index == 0; }
  bool ends_curve() const { return index + 1 == (uint32_t{1} << level); }
  uint64_t t_lo() const { return uint64_t{index} << (kCurveParamBits - level); }
  uint64_t t_hi() const { return uint64_t{index + 1} << (kCurveParamBits - level); }
};

CurvePiece whole_piece(const BezierEdge3& e, uint32_t curve);
CurvePiece segment_piece(const Edge3& e, uint32_t curve);

// Exact de Casteljau halving at t = 1/2. Requires in.level < kCurveMaxDepth.
void halve(const CurvePiece& in, CurvePiece* left, CurvePiece* right);

// Per-coordinate bound on the distance between the piece and its chord at the same
// parameter: |B(s) - ((1 - s) P0 + s P3)| <= 3/4 * max(|P0 - 2 P1 + P2|, |P1 - 2 P2 + P3|)
// coordinate by coordinate, for every s in [0, 1]. (B - L vanishes at both ends and its second
// derivative is at most 6 * max |second difference|; an interpolation error bound of h^2/8 *
// max |f''| with h = 1 gives 6/8.) Rounded up, in Q20.42. Zero for a straight piece.
struct Flatness {
  uint64_t ex, ey, ez;
};
Flatness flatness(const CurvePiece& p);

// The box of the control points, which holds the piece (convex hull property). Q20.42.
struct FixBox {
  int64_t x0, y0, x1, y1;
};
FixBox box_of(const CurvePiece& p);
inline bool overlap(const FixBox& a, const FixBox& b) {
  return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
}

// Integer units to Q20.42 and back (the latter rounds to nearest).
inline int64_t to_fix(int32_t v) { return int64_t{v} << kCurveFracBits; }

}  // namespace haloplot
