// Kira's outline detection: the outlines are the boundary of the region the whole picture
// covers, and they run along contour (H3) edges only. Each contour edge becomes a vector with
// its front face on the right and is cut into unit segments at its crossings with other contour
// edges (CUT's, both ways). Circuits are traced from an unused segment: at a crossing the
// trace turns onto the partner edge, at a vertex it takes the contour vector starting there.
// A circuit with an invisible segment (QI > 0) cannot be an outline; for the others one
// segment is asked the necessary and sufficient condition (no face at all just outside it)
// and the answer holds for the whole circuit.
//
// Peculiar vertices: type A (two or more contour vectors end there): a segment arriving there
// is asked the condition itself, and the circuit is abandoned if it fails. Type B (two or more
// start there): the most counterclockwise turn is taken. A trace that cannot close (a dead
// end, a loop that misses its start, or a contour edge with a singular touch: another vertex
// on it or on its end, where edges may overlap collinearly and CUT reports no crossing) leaves
// its segments to be asked one by one: slower, never wrong.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/cut/cutset.h"
#include "haloplot/geometry/edge_piece.h"
#include "haloplot/solid/incidence.h"
#include "haloplot/solid/qi.h"
#include "haloplot/solid/topology.h"
#include "haloplot/status/sink.h"
#include "haloplot/status/status.h"

namespace haloplot {

struct OutlineStats {
  uint32_t contour_edges = 0;
  uint32_t contour_crossings = 0;  // H3 with H3
  uint32_t unit_segments = 0;
  uint32_t circuits = 0;   // closed circuits traced
  uint32_t potential = 0;  // circuits with no invisible segment
  uint32_t outlines = 0;   // circuits that passed the condition
  uint32_t outline_segments = 0;
  uint32_t condition_tests = 0;  // necessary-and-sufficient tests made
  uint32_t one_by_one = 0;       // segments asked individually after a trace failed
  // Kira's peculiar vertices: where two or more contour vectors end (type A) or start (type B);
  // the V.C. table cannot be used there.
  uint32_t contours_end_twice = 0, contours_start_twice = 0;
};

using OutlineSegment = EdgePiece;  // Q0.32 from the edge's v0

using OutlineSink = Sink<OutlineSegment>;

size_t outline_bytes(const Topology& topo, const CutSet& cutset, const Incidences& inc);

// Needs classify() (front, classes), CUT over all edges and the QI state.
Status find_outlines(const Topology& topo, const uint8_t* front, const CutSet& cutset,
                     const Incidences& inc, const QiState& qi, void* buffer, size_t bytes,
                     OutlineSink sink, OutlineStats* stats);

}  // namespace haloplot
