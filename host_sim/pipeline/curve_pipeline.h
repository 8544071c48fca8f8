// The core's curve stages on the host (core/curve/): the crossings of a scene with Bézier
// edges (run_curve_cross, segment pairs included: no CUT runs on such a scene), then the curve
// DRAW (run_curve_draw): haloed visible intervals flattened into chords. Buffers sized by the
// plans; the hit array grows to the count the core asks for.
#pragma once
#include <cstdint>
#include <vector>

#include "haloplot/band/curve_bands.h"
#include "haloplot/curve/curve_draw.h"

namespace haloplot::host {

struct HostCurveDraw {
  std::vector<CurveHit> hits;
  std::vector<CurveInterval> intervals;  // edges numbered curves first, then segments
  std::vector<Span> chords;              // the same numbering, ends in the scene's units
  CurveCrossStats cross_stats;
  CurveDrawStats stats;
  size_t cross_scratch_bytes = 0, draw_scratch_bytes = 0;
  double cross_ms = 0, draw_ms = 0;
};

// `cross`'s segment_pairs is set here (no CUT runs on a scene with curves). `exact`: the exact
// halo (run_curve_draw_exact).
Status host_curve_draw(const std::vector<BezierEdge3>& curves, const std::vector<Edge3>& segments,
                       const CurveCrossParams& cross, const CurveDrawParams& params,
                       HostCurveDraw* out, bool exact = false);

// The curve job's drawing in bands (band/curve_bands.h) in an arena of `arena_bytes`, as a
// controller with that arena draws it: out->chords in steps (the observer's), sorted by edge
// and along it as the unbanded DRAW emits them, so `plot --arena` writes the same files.
Status host_banded_curve_draw(const std::vector<BezierEdge3>& curves,
                              const std::vector<Edge3>& segments, const CurveBandSpec& spec,
                              size_t arena_bytes, HostCurveDraw* out, BandStats* bands);

}  // namespace haloplot::host
