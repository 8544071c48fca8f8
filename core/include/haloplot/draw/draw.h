// DRAW (paper D1-D2.5): given a CUTSET and a halo width, emit the visible spans of every edge.
// DRAW reads only the CUTSET, so a new halo width reruns DRAW alone, never CUT.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/cut/cutset.h"
#include "haloplot/draw/halo.h"
#include "haloplot/draw/precision.h"
#include "haloplot/geometry/edge_piece.h"
#include "haloplot/status/sink.h"
#include "haloplot/status/status.h"

namespace haloplot {

// A visible piece of an edge: positions t0 < t1 in Q0.32 along it (t = 1 is 2^32), and the
// same ends rounded to the nearest step, which is all a plotter needs.
struct Span : EdgePiece {
  int32_t x0, y0, x1, y1;
};

// Where spans go (status/sink.h): the firmware streams them straight into the motion planner
// without a buffer, the host collects them.
using SpanSink = Sink<Span>;

struct DrawParams {
  int32_t halo = 0;  // halo width W in steps, in [0, 2^20); 0 draws every edge whole
  HaloMode mode = HaloMode::kPaper;
};

struct DrawStats {
  uint64_t gaps = 0;          // halo gaps applied
  uint64_t spans = 0;         // spans emitted
  uint64_t hidden_edges = 0;  // edges the halos removed entirely
  bool reach_short = false;   // exact mode, W > CUT's reach: near misses beyond reach unseen
};

// Scratch DRAW needs for this CUTSET: one Gap per record of the busiest edge.
size_t draw_scratch_bytes(const CutSet& cutset);

// DRAW with a precision policy (draw/precision.h): instantiated for every pairing of the
// square-root and position policies there.
template <typename Precision>
Status draw_with(const CutSet& cutset, const DrawParams& params, void* scratch,
                 size_t scratch_bytes, SpanSink sink, DrawStats* stats);

// The gap one CUTSET record cuts into its behind edge, as DRAW applies it: sized by the mode,
// rounded outward to the position grid and clipped to the edge (empty: lo > hi, e.g. a near
// miss under the paper's mode). The band conductor (band/) sizes its margins with it.
template <typename Precision = DefaultDrawPrecision>
Gap record_gap(const CutSet& cutset, const Crossing& record, const DrawParams& params);

// DRAW in the default precision: exact roots, Q0.32 positions. `scratch` starts on a
// kBufferAlignment (8) boundary, or DRAW returns kMisalignedBuffer (status/status.h).
Status draw(const CutSet& cutset, const DrawParams& params, void* scratch, size_t scratch_bytes,
            SpanSink sink, DrawStats* stats);

// Round a position along an edge to steps (paper: the only place rounding happens).
void span_point(const Edge3& e, int64_t t32, int32_t* x, int32_t* y);

}  // namespace haloplot
