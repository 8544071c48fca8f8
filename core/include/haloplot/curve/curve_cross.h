// Crossings of projected cubic Bézier edges with each other, with themselves (a knot crosses
// itself) and with straight edges: the HALO paper's section 5, items 2-4.
//
// How:
//  1. Every curve is halved (curve/bezier.h, exact) until each piece is flat within
//     flat_tol or at max_depth: these pieces and their boxes are what CUT's grid will hold.
//  2. Pieces are paired by box overlap with a sweep over their boxes sorted by left edge.
//     (CUT's grid is built for many short straight edges of similar length; here a few curves
//     give a few hundred pieces per curve, and the sweep needs no cell size. Putting pieces in
//     the grid comes with curves in CUT.) Segment-segment pairs are skipped: CUT has them.
//  3. A box-overlapping pair is refined by halving the less flat piece until one of:
//     - the boxes are apart, or one piece's control points lie strictly outside the other's
//       fat line (the strip parallel to its chord holding its control points): no crossing;
//     - the chords cross properly and the bound below is within t_tol on both curves: a
//       crossing, at the chords' crossing;
//     - both pieces are at max_depth (or straight) without a proper chord crossing, boxes
//       still overlapping: a touch (the curves come within the max-depth flatness of each
//       other; tangency is reported this way, deterministically, not as a crossing).
//       At max_depth a chord crossing is a crossing even if its bound exceeds t_tol.
//  4. Raw records of one pair of curves whose parameter intervals overlap on both curves are
//     one cluster (the same crossing seen by neighbouring pieces, or a tangency seen as two
//     chord crossings). Along the first curve, a crossing record with the same sense (which
//     way the other curve crosses) as the one before is the same crossing again: distinct
//     neighbouring crossings of two curves alternate. An odd number of distinct crossings is
//     one crossing, an even number (or only touches) is a touch.
//
// Parameter bound of a crossing. Pieces A, B with chords L_A(s) = A0 + s dA, L_B(u) and
// per-coordinate flatness e_A, e_B (|B_A(s) - L_A(s)| <= e_A coordinate-wise). At the true
// crossing B_A(s*) = B_B(u*), so L_A(s*) - L_B(u*) = r with |r.x| <= e_A.x + e_B.x, likewise y;
// at the chord crossing L_A(s') = L_B(u'). Subtracting, dA (s* - s') - dB (u* - u') = r, and
// Cramer's rule gives |s* - s'| <= (|r.x| |dB.y| + |r.y| |dB.x|) / |cross(dA, dB)|, and |u* - u'|
// the same with dA. On the whole curve that is divided by 2^level; 2 more units of Q0.32 cover
// rounding. It holds for the true crossing inside the two pieces. Front/back: the depth
// chords at s', u' differ from the true depths by at most e_A.z + |dA.z| |s* - s'| (and the
// same for B); when the depth difference does not exceed both errors, `front` is 0.
//
// A cluster's crossing keeps the bound of its tightest record, widened to cover every record
// in the cluster: when touch records join it (max_depth pieces next to a crossing that sits
// exactly at a piece end), the bound grows to a max_depth piece, 2^-14 of the parameter.
//
// Ties. A chord end exactly on the other chord's line, or exactly on a fat line's edge, is
// decided by Simulation of Simplicity (one curve moved by an infinitesimal), so a crossing at
// piece ends of both curves (a dyadic parameter on each: easy to build with symmetric
// curves) is found once, and collinear chords (an overlap) do not cross.
//
// Meetings at end points. Pieces that meet at a point that is a curve's own end (curves joined
// end to start, a curve ending on another) or the same point of one curve (consecutive pieces)
// are never a crossing there, but may cross elsewhere (a curve folding back along a segment it
// ends on, a loop): they are halved until the path through the point is monotone along its
// chord, and dropped at max_depth. A crossing whose bound reaches a curve's end is such an
// end-point meeting (HALO ignores crossings at end points): a touch. A piece flat within
// flat_tol that is not monotone along its own chord is halved and checked for a loop inside.
// So a loop or fold is missed only within a max_depth piece (2^-14 of the parameter).
//
// Memory: plan_curve_cross() counts the pieces and says how many scratch bytes
// run_curve_cross() needs (the pieces, their boxes, the sweep order and a refinement stack of
// 2 * kCurveMaxDepth + 2 piece pairs and a loop check's stack of kCurveMaxDepth + 2 pieces);
// the hits go into the caller's array. No recursion but the flattening's, at most max_depth
// calls deep.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/curve/bezier.h"
#include "haloplot/status/status.h"

namespace haloplot {

// Curves and segments together, and pieces, are counted in 31 bits.
inline constexpr uint32_t kMaxCurveCount = 0x7fffffffu;

struct CurveCrossParams {
  // Initial pieces: flat within this, per coordinate, Q20.42 (default 1/4 unit). They only
  // pair curves up (and will be CUT's grid entries): a crossing's precision comes from the
  // refinement, so a coarser tolerance means fewer pieces, the same crossings and bounds
  // (docs/curves.md has the measurements).
  uint64_t flat_tol = uint64_t{1} << (kCurveFracBits - 2);
  // A crossing is refined until its parameter bound is within this on both curves, Q0.32
  // (default 2^-24 of the curve's parameter range), or max_depth is reached.
  uint64_t t_tol = uint64_t{1} << 8;
  uint8_t max_depth = kCurveMaxDepth;  // at most kCurveMaxDepth
  // Cross segments with segments too. Off, CUT has them (a straight scene goes through CUT);
  // the curve DRAW of a scene with curves and segments (curve/curve_draw.h) needs them here.
  bool segment_pairs = false;
};

enum class CurveHitKind : uint8_t { kCrossing, kTouch };

// One crossing or touch as seen from `curve`. Every crossing appears twice, once from each
// curve (a self-crossing twice on the same curve). Parameters are Q0.32 (kCurveParamOne is
// t = 1); curves are numbered BezierEdge3 first, then the segments.
struct CurveHit {
  uint64_t t = 0;          // on `curve`
  uint64_t other_t = 0;    // on `other`
  uint64_t t_err = 0;      // the true parameter is within t +/- t_err
  uint64_t other_err = 0;  // and other_t +/- other_err
  uint32_t curve = 0, other = 0;
  CurveHitKind kind = CurveHitKind::kCrossing;
  // +1: `curve` is in front of `other` here; -1: behind; 0: the depths are too close to call
  // (within their error bound), or a touch.
  int8_t front = 0;
  // Crossings: which way `other` crosses `curve`, the sign of cross(tangent of curve, tangent
  // of other) (from the chords); 0 for a touch.
  int8_t sense = 0;
};

struct CurveCrossPlan {
  uint32_t n_curves = 0, n_segments = 0;
  uint32_t pieces = 0;
  size_t scratch_bytes = 0;
  CurveCrossParams params;
};

struct CurveCrossStats {
  uint32_t pieces = 0;
  uint64_t box_pairs = 0;    // piece pairs from the sweep with overlapping boxes
  uint64_t pair_visits = 0;  // refinement calls
  uint64_t raw = 0;          // raw crossing and touch records (before clustering)
  uint32_t crossings = 0, touches = 0;
  uint64_t needed = 0;  // on kCrossingCapacity: the hit capacity a retry needs
};

// Check the input (every control point and endpoint in range, params in range) and count the
// pieces: O(pieces), nothing stored.
Status plan_curve_cross(const BezierEdge3* curves, uint32_t n_curves, const Edge3* segments,
                        uint32_t n_segments, const CurveCrossParams& params, CurveCrossPlan* plan);

// Find every crossing and touch. Hits are sorted by (curve, t, other). A hit array too small
// for the raw records, or for the final hits, is kCrossingCapacity with stats->needed set;
// *n_hits is then 0.
Status run_curve_cross(const CurveCrossPlan& plan, const BezierEdge3* curves, const Edge3* segments,
                       void* scratch, size_t scratch_bytes, CurveHit* hits, uint32_t capacity,
                       uint32_t* n_hits, CurveCrossStats* stats);

}  // namespace haloplot
