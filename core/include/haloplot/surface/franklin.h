// Franklin 1980, "A linear time exact hidden surface algorithm", steps 2-9: the hidden lines
// of a scene of faces with a uniform grid whose cells remember their closest blocking face.
//
//   2-4  a B x B grid over the scene, B = floor(c * min(sqrt(N), 1 / L)), N edges of average
//        projected length L (the screen taken as 1 x 1);
//   5-6  each face goes to the cells of its bounding box, unless the cell's blocking face is in
//        front of it at the cell's four corners (two planes: if one is behind the other at
//        the four corners it is behind throughout the cell); a face whose projection holds
//        all four corners becomes the cell's blocking face; a face in no cell is deleted;
//   7    each edge goes to the cells it passes, unless its part in the cell (clipped exactly)
//        is behind the blocking face at both ends; an edge in no cell is deleted;
//   8    each cell intersects its edges pair by pair, keeping a crossing only in the cell that
//        holds it (exactly), and cuts both edges there (the hidden-surface part needs both);
//   9    every edge is cut at its crossings and at the vertices lying on it, and the middle of
//        each piece is tested against the blocking face and the faces of its cell.
//
// Faces are triangles (solid/mesh.h): convex, as the paper assumes, and exactly planar with
// integer corners; the host splits polygons (concave ones by exact ear clipping). No face
// orientation or topology is used: any face in front hides (so open and non-manifold meshes
// work). Every test is exact integer arithmetic (solid/cover.h for the midpoint tests).
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/cut/grid.h"
#include "haloplot/geometry/edge_piece.h"
#include "haloplot/memory/sized_stage.h"
#include "haloplot/solid/mesh.h"
#include "haloplot/status/sink.h"
#include "haloplot/status/status.h"

namespace haloplot {

struct FranklinParams {
  // The paper's c in Q8.8. A face can only block a cell smaller than itself: with c = 1 the
  // cells are as large as the faces and almost none block (p = ((c - 1) / (c + 1))^2 in the
  // paper's analysis); its own runs used about 2 (N = 1000, L = 0.16, B = 12).
  uint32_t c_q8 = 512;
  // Emit every piece between consecutive cuts instead of runs of equal visibility: the
  // regions step (surface/regions.h) needs a node wherever any edge is cut, and pieces shorter
  // than 2^-32 of their edge (still exactly ordered) so that no boundary is left open.
  bool every_piece = false;
};

struct FranklinStats {
  uint32_t b = 0, cells = 0, blocking_cells = 0;
  uint64_t face_cells = 0;         // (face, cell) pairs kept
  uint64_t face_cells_culled = 0;  // (face, cell) pairs behind the cell's blocking face
  uint32_t faces_deleted = 0;      // step 5c: faces in no cell (certainly hidden)
  uint64_t edge_cells = 0, edge_cells_culled = 0;
  uint32_t edges_deleted = 0;  // step 7b
  uint64_t pairs_tested = 0, crossings = 0;
  uint64_t pieces = 0, midpoint_tests = 0, face_tests = 0;
  uint32_t incidences = 0;
};

// Where a piece ends, exactly: at mesh vertex u (w == kNoVertex), or where its edge crosses
// the segment from vertex u to vertex w (another edge, or a triangle side that is not drawn).
struct PieceEnd {
  static constexpr uint32_t kNoVertex = 0xffffffffu;
  uint32_t u = 0, w = kNoVertex;
};

// An end's exact position along drawn edge e (edge_pairs[2e] -> edge_pairs[2e + 1]) as
// num / den, 0 <= num <= den, 0 < den < 2^41.
struct PiecePosition {
  int64_t num, den;
};
PiecePosition piece_end_position(const SolidInput& in, uint32_t e, const PieceEnd& end);

// t0, t1: Q0.32 along the edge from its first vertex (floors of the exact ends).
struct FranklinPiece : EdgePiece {
  bool hidden;
  PieceEnd from, to;
};

using FranklinSink = Sink<FranklinPiece>;

// Bytes for the run with room for `crossing_capacity` crossings and `incidence_capacity`
// vertex-on-edge incidences (walks every face's and edge's cells once: O(N)).
size_t franklin_bytes(const SolidInput& in, const FranklinParams& p, uint32_t crossing_capacity,
                      uint32_t incidence_capacity);

// kCrossingCapacity / kIncidenceCapacity: stats->crossings / stats->incidences say the counts.
Status franklin_hidden_lines(const SolidInput& in, const FranklinParams& p,
                             uint32_t crossing_capacity, uint32_t incidence_capacity, void* buffer,
                             size_t bytes, FranklinSink sink, FranklinStats* stats);

// Franklin's hidden lines as a sized stage (memory/sized_stage.h): needs.crossings and
// needs.incidences are the capacities.
struct FranklinStage {
  const SolidInput* in;
  FranklinParams params;
  FranklinSink sink;
  FranklinStats* stats;
  size_t bytes(const StageNeeds& needs) const {
    return franklin_bytes(*in, params, needs.crossings, needs.incidences);
  }
  Status run(const StageNeeds& needs, void* buffer, size_t bytes, StageNeeds* want) {
    const Status s = franklin_hidden_lines(*in, params, needs.crossings, needs.incidences, buffer,
                                           bytes, sink, stats);
    want->crossings = need_count(stats->crossings);
    want->incidences = stats->incidences;
    return s;
  }
};

}  // namespace haloplot
