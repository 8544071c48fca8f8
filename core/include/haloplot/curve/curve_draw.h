// DRAW for curved edges (the HALO paper's DRAW, D2.1-D2.5, on cubic Bézier edges and the
// straight edges among them): from the crossings run_curve_cross() found, a halo gap wherever
// an edge passes behind another, the visible parameter intervals of every edge, and each
// interval flattened into chords for the plotter.
//
// The gap. At a crossing where edge A (at t) passes behind edge B (at u), the paper's
// effective half-gap is L = W / sin(theta) of arc length along A, theta the angle between the
// tangents A'(t) and B'(u): L = W |A'| |B'| / |cross(A', B')|. DRAW walks L of arc along A from
// t - t_err back and from t + t_err on (t_err: the crossing's parameter bound); the gap lies
// between the two ends.
//
// The walk (docs/curves.md): steps whose sub-cubic's arc lies between its chord c and control
// polygon p, counted as (2c + p) / 3 and halved until p - c <= c 2^-14 + 2^-20 units; the last
// step by bisection to 1/64 unit. Each side's arc is within 2^-14.5 L + 2^-20.6 units a step +
// 1/64 unit of L, plus the shift t_err allows and the tangents' errors (their parameters' bound
// and their 30-bit rounding, a relative 2^-26 / sin(theta)).
//
// Joints. Where exactly two edge ends meet at the same 3-D point and the chain goes on there
// (the tangents on either side point the same way within 45 degrees), the edges are one line
// for the halos: a gap side running off one edge's end goes on along the next for the arc left,
// across as many joints as it takes, so a knot's halos do not stop at the joints of its fit.
// Elsewhere (a corner, a branch, a chain's end) a gap is clipped at the edge's end, as in the
// straight DRAW.
//
// Crossings at joints. Two chains can cross exactly at a joint of each (a symmetric fit puts
// a knot's crossings there); run_curve_cross() sees only edge ends meeting, never a crossing.
// Two joints at one projected point at different depths cross when their directions alternate
// around it (exact integer sides); the joint behind gets W / sin(theta) of arc on both its
// edges, theta from the tangents at the joint (the front chain's side with the smaller angle).
// An edge passing through another chain's joint at a dyadic parameter of its own (a piece end
// of its exact halving) is found (the joints in its x range by a binary search) and decided
// the same way.
//
// Chords. A visible interval of width w (in t) on a curve is cut into n equal chords with
// n = ceil(w sqrt(3 D_c / (4 tol))), D_c the largest second-difference coordinate, so each
// chord lies within tol of its piece of curve, coordinate by coordinate (the flatness bound of
// curve/bezier.h, which scales with h^2 on a sub-interval of width h); the chord ends are the
// curve's points rounded to the nearest unit (within 1/2 unit, coordinate by coordinate). A
// straight edge's visible interval is one chord, its ends rounded as the straight DRAW rounds.
//
// Edges are numbered as in run_curve_cross(): the curves, then the segments. The hits must be
// run_curve_cross()'s, sorted by curve. No heap: plan_curve_draw() says how much scratch
// run_curve_draw() needs (the joints' table, a halving stack and one edge's gaps).
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/curve/curve_cross.h"
#include "haloplot/draw/draw.h"
#include "haloplot/geometry/edge_piece.h"
#include "haloplot/status/sink.h"

namespace haloplot {

struct CurveDrawParams {
  int32_t halo = 0;            // W, in the edges' units, [0, 2^20); 0 draws every edge whole
  uint32_t chord_tol_q8 = 64;  // chord tolerance in 1/256 units, [1, 2^16]; default 1/4
};

// A visible piece of a curved edge: the curve's number and its parameter interval, Q0.32
// (kCurveParamOne is t = 1), as every stage's pieces are.
using CurveInterval = EdgePiece;
using CurveIntervalSink = Sink<CurveInterval>;

struct CurveDrawPlan {
  uint32_t n_curves = 0, n_segments = 0;
  uint32_t n_hits = 0;
  uint32_t most_hits = 0;  // the most hits on one edge
  size_t scratch_bytes = 0;
  uint32_t front_points = 0;  // plan_curve_draw_exact(): the front strand's points a run
  CurveDrawParams params;
};

struct CurveDrawStats {
  uint64_t gaps = 0;             // halo gaps cut (crossings where an edge is behind)
  uint64_t carried = 0;          // gaps continued across a joint
  uint64_t joint_crossings = 0;  // crossings at a chain's joint (counted among gaps)
  uint64_t undecided = 0;        // crossings whose front could not be called: no gap
  uint64_t intervals = 0;        // visible intervals
  uint64_t chords = 0;           // chords emitted
  uint64_t hidden = 0;           // edges the halos removed entirely
  uint32_t joints = 0;           // joints where halos carry on
  // Units, rounded up: no gap reaches farther than this from the point of its crossing (its
  // arc, the shift its parameter bound allows, the walk's error); kCurveReachUnbounded when a
  // gap has no end (tangents parallel as rounded). Bands widen by it (band/curve_bands.h).
  uint64_t reach = 0;
};
inline constexpr uint64_t kCurveReachUnbounded = uint64_t{1} << 40;

// Check the input (hits sorted by curve, indices in range, params in range) and size the
// scratch.
Status plan_curve_draw(const BezierEdge3* curves, uint32_t n_curves, const Edge3* segments,
                       uint32_t n_segments, const CurveHit* hits, uint32_t n_hits,
                       const CurveDrawParams& params, CurveDrawPlan* plan);

// The visible intervals (to `intervals`, if given) and their chords (to `chords`, as Spans:
// edge = the edge's number, t0 and t1 the chord's parameters, the ends in units), edge by
// edge and along each edge. A sink's status other than kOk stops the run with it.
Status run_curve_draw(const CurveDrawPlan& plan, const BezierEdge3* curves, const Edge3* segments,
                      const CurveHit* hits, uint32_t n_hits, void* scratch, size_t scratch_bytes,
                      SpanSink chords, const CurveIntervalSink* intervals, CurveDrawStats* stats);

// The exact halo (docs/curves.md, "The exact halo"): as run_curve_draw(), but each gap removes
// exactly what of the edge behind lies within W of the front strand around the crossing (to
// 1/64 unit), walked from the crossing, instead of W / sin(theta) of arc. Its plan adds the
// front strand's scratch. Host only so far (the controller's jobs take the paper's gap).
Status plan_curve_draw_exact(const BezierEdge3* curves, uint32_t n_curves, const Edge3* segments,
                             uint32_t n_segments, const CurveHit* hits, uint32_t n_hits,
                             const CurveDrawParams& params, CurveDrawPlan* plan);
Status run_curve_draw_exact(const CurveDrawPlan& plan, const BezierEdge3* curves,
                            const Edge3* segments, const CurveHit* hits, uint32_t n_hits,
                            void* scratch, size_t scratch_bytes, SpanSink chords,
                            const CurveIntervalSink* intervals, CurveDrawStats* stats);

}  // namespace haloplot
