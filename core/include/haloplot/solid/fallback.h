// The topology-free method (Franklin 1980's step 10): cut every drawn edge, and every diagonal
// that is a contour (H3; counting both sides of every face, any edge whose faces lie on one side
// of it on paper: classify.h's paper_contour), wherever it passes behind another edge, through a
// vertex or through a face (solid/pierce.h), and test the middle of each piece against the faces
// in the grid cell that holds it. It needs no edge-face links, so it is what a band of a banded
// plot gets (its faces are local), and it is the independent cross-check of the QI propagation.
//
// Kira's savings, when the mesh is manifold and classified (use_classes):
//   - H1 and H2 edges are hidden whole without a test (they cannot be seen on a closed solid);
//   - the vertex condition in visibility (V.C.): the first test of a piece that touches an
//     ordinary vertex decides every other piece touching it. Peculiar vertices (two or more
//     contour vectors ending, type A, or starting, type B, there) and vertices with singular
//     neighbours (another vertex or an edge on the same point) never use it.
// The middle of a piece is a Q0.32 position, so a piece needs at least two positions of length
// (2^-31 of the edge, under 2^-10 steps) to have one strictly inside; shorter ones are reported
// with the QI of the piece before them (counted in FallbackStats::short_pieces).
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/cut/cutset.h"
#include "haloplot/geometry/edge_piece.h"
#include "haloplot/solid/face_grid.h"
#include "haloplot/solid/incidence.h"
#include "haloplot/solid/topology.h"
#include "haloplot/status/status.h"

namespace haloplot {

struct FallbackParams {
  bool any_facing = false;  // count back faces too (open or non-manifold surfaces: both sides show)
  bool use_classes = false;  // Kira: skip H1/H2 edges (needs classify())
  bool use_vc = false;       // Kira: the V.C. table (needs classify())
  // A band's rows [row_lo, row_hi) only (band/band_rule.h): each sloped edge is cut where it
  // enters and leaves them (row_border) and only the pieces between are tested and emitted; a
  // level edge is whole in the band that holds its row. Every face that can cover a point of
  // those pieces meets rows [row_lo, row_hi]: a band's input must hold them all. Pieces are
  // emitted as cut, not merged (FallbackPiece::tested says which ones were tested).
  bool window = false;
  int32_t row_lo = 0, row_hi = 0;
  // Kira's outlines without the QI: every visible piece of a contour edge (H3), or of an edge
  // with one face (an open surface's rim; counting both sides, of every contour on paper), is cut
  // wherever it crosses another edge either way or meets a vertex, and each part is asked Kira's
  // condition (solid/outline.h: no face at all just outside it, away from its faces). The runs that
  // pass go to FallbackSink::outline.
  bool outline = false;
};

struct FallbackStats {
  uint64_t pieces = 0;
  uint64_t tests = 0;        // midpoint tests made
  uint64_t face_tests = 0;   // face-against-point predicates inside those tests
  uint64_t vc_saved = 0;     // tests the V.C. table answered
  uint64_t class_saved = 0;  // pieces of H1/H2 edges, hidden by class
  uint64_t short_pieces = 0;
  uint64_t outline_tests = 0;  // Kira's condition asked by the outline pass
  uint64_t pierces = 0;        // cuts where an edge passes through a face (solid/pierce.h)
  uint64_t pierce_tests = 0;   // exact edge-through-face tests made to find them
  // Kira's peculiar vertices: where two or more contour vectors end (type A) or start (type B);
  // the V.C. table cannot be used there.
  uint32_t contours_end_twice = 0, contours_start_twice = 0;
  uint32_t grid_cells = 0, cell_faces = 0;
};

struct FallbackPiece : EdgePiece {
  int32_t q;    // halves of cover; kQiUnknown when a class or the V.C. decided
  bool hidden;  // q != 0, or the class or V.C. said so
  // False for a piece too short to hold a test point: it took the q of the piece before it.
  // A band (window) emits every piece unmerged, so its caller can merge across the borders.
  bool tested;
};

struct FallbackSink {
  Status (*emit)(void* context, const FallbackPiece& piece);
  void* context;
  Status (*outline)(void* context, const FallbackPiece& run);  // may be null
};

// Scratch bytes for the face grid and the tables (walks the faces once to count cell pairs),
// and, with outlines, the positions where contour edges pass in front of others.
// With `shared_grid` the caller builds the face grid (and may use it after: the intersection
// lines ask the same faces), and it takes no bytes here.
size_t fallback_bytes(const Topology& topo, bool shared_grid = false);
size_t fallback_outline_bytes(const Topology& topo, const CutSet& cutset, bool any_facing);

// `cutset` is CUT over topo's edges in topo's order; `front` may be null unless classes or
// V.C. are asked for (then classify() must have run). `grid`: every face of topo in a face
// grid the caller built (null: built here, in the buffer).
Status run_fallback(const Topology& topo, const uint8_t* front, const CutSet& cutset,
                    const Incidences& inc, const FallbackParams& params, void* buffer, size_t bytes,
                    FallbackSink sink, FallbackStats* stats, const FaceGrid* grid = nullptr);

}  // namespace haloplot
