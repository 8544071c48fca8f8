// Appel's quantitative invisibility with Heger's refinements: the QI of a point is the number
// of front faces in front of it; an edge is visible where its QI is 0.
//
// Propagation (breadth first, Heger's queue): the QI is found once per connected part by a
// ray cast at a start vertex (against the faces of its grid cell, solid/face_grid.h), then
// carried along every edge. Along an edge it changes only
//   - where the edge passes behind a fold (H2 or H3) edge: +-1, the sign from the side the
//     fold's front face lies on (exact orientation). These crossings are CUT's (cut/cut.h).
//   - where the edge passes exactly through another vertex: the faces around that vertex are
//     asked before and after (half q.i.: each fold ending there contributes a half).
// Around a vertex the QI depends on the direction the next edge leaves in. Split it into
//   base(v): faces that cover v's point outright (the same for every direction), plus
//   local(v, edge): faces whose boundary passes through v's point, asked with the edge's
//     direction (solid/cover.h): v's own faces (Heger's wedge test), the faces of other
//     vertices on the same point (quarter q.i.), and of edges passing through it (delta q.i.:
//     a vertex on a contour). On an edge running along a face side the cover is a half: the
//     occluded edges, whose QI is then an odd number of halves.
// QI values are counted in halves throughout.
//
// Meshes that pierce themselves (parts that overlap, an eye set into a head): along an edge the
// QI also changes where it passes through a face, which nothing on paper marks. A propagation
// that meets conflicts is run again with those places found along every edge (find_pierces:
// solid/pierce.h, +-2 for each face the edge goes behind or comes out of), so a clean mesh
// never pays for the look (solid/hidden_lines.cpp orders the retries).
//
// Open and imperfect meshes (two-sided): on a closed, consistently oriented 2-manifold only
// front faces need counting (a back face is always behind a front face of the same solid).
// On any other mesh, an open surface, a shell that cannot be oriented, a side on three faces,
// both sides of a face show, so every face counts whichever way it turns: the QI is then the
// number of faces in front of a point, and it changes where the walk passes behind an edge by
// the faces that lie on one side of it on paper (classify.h's paper_jump: a fold, a boundary
// edge, a fin; two faces on either side cancel). The rules at vertices are the same, asked of
// every face of the star. Visible still means QI 0, so the picture of a closed solid is the same
// either way; only the counts differ. No orientation is needed, so every shell of any mesh
// takes this one method. Two paths that reach a vertex with different
// base values trigger a new ray cast there (counted: exact arithmetic should make it 0).
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/cut/cutset.h"
#include "haloplot/geometry/edge_piece.h"
#include "haloplot/memory/parts.h"
#include "haloplot/solid/face_grid.h"
#include "haloplot/solid/incidence.h"
#include "haloplot/solid/topology.h"
#include "haloplot/status/sink.h"
#include "haloplot/status/status.h"

namespace haloplot {

inline constexpr int32_t kQiUnknown = -0x7fffffff;

struct QiStats {
  uint32_t components = 0;  // parts of the mesh graph, each seeded by a ray cast
  uint32_t ray_casts = 0;   // initialisations (seeds plus re-initialisations)
  uint32_t conflicts = 0;   // a vertex reached with two different QIs (re-initialised)
  uint32_t edges_walked = 0;
  uint64_t crossings = 0;   // Appel's rule: passing behind a fold edge, +-1
  uint64_t wedge = 0;       // an edge starts or ends under one of its own vertex's faces
  uint64_t delta = 0;       // a vertex on a contour (fold edge through the vertex's point)
  uint64_t quarter = 0;     // vertex on vertex: another vertex's faces at the same point
  uint64_t half = 0;        // an edge passing exactly through a vertex changed its QI
  uint64_t occluded = 0;    // pieces lying along a face side (odd number of halves)
  uint64_t degenerate = 0;  // edges seen end-on (a point on paper): QI carried unchanged
  // A mesh that pierces itself: a propagation met first_conflicts conflicts, so it ran again
  // stopping where edges pass through faces (solid/pierce.h); set by the caller.
  uint32_t first_conflicts = 0;
  uint64_t pierces = 0;       // places where an edge passes through faces
  uint64_t pierce_tests = 0;  // exact edge-through-face tests made to find them
};

struct QiState {
  int32_t* base = nullptr;     // [n_vertices], in halves, kQiUnknown before it is reached
  int32_t* q_at_v0 = nullptr;  // [n_edges]: the QI at the start of each edge, leaving v0
  FaceGrid grid;               // every face, for the ray casts (the intersection lines reuse it)
  bool two_sided = false;      // every face counts, from either side (qi_two_sided)
  bool pierces = false;        // the walks stop where edges pass through faces too
};

// Does the QI count both sides of every face: the mesh is not a closed oriented manifold.
inline bool qi_two_sided(const Topology& topo) { return !topo.check.manifold(); }

// The propagation in parts, which threads may run at once (memory/parts.h): vertices by
// number, part_vertices to a part, and each edge with its v0. A part seeds its own ray casts and
// walks its own edges; an edge that ends in another part leaves the QI it arrives with, which is
// checked against that vertex's own once every part is done (a difference is a conflict, as two
// paths in one part disagreeing is). The split depends on the mesh alone, never on the runner,
// so the QI, its statistics and the picture are the same however many threads ran it. A mesh
// smaller than one part propagates as one, as it always did. Parts of 2^15 vertices: a part is
// then worth far more than starting a thread, and the extra ray casts (one per part and piece
// of it, each against one grid cell's faces) stay a few dozen on a million-triangle model.
inline constexpr uint32_t kQiPartVertices = uint32_t{1} << 15;

struct QiSplit {
  uint32_t part_vertices = kQiPartVertices;  // tests split small meshes
  const Parts* parts = nullptr;              // null: the parts one after another, here
};

size_t qi_bytes(const Topology& topo, uint32_t part_vertices = kQiPartVertices);

// The QI's face grid (QiState::grid) lies at the front of propagate_qi()'s buffer. kBuild builds
// it there (in the split's parts, with the buffer's unwritten arrays after it as the parts'
// scratch); kKeep takes the one an earlier propagate_qi() built in this same buffer for this
// same topology (`*out` as that call left it): the grid reads no facing, so the runs after the
// first (solid/hidden_lines.cpp: the projected facing, then the pierces) need not build it again.
enum class QiGrid : uint8_t { kBuild, kKeep };

// `cutset` must be CUT's result over topo's edges in topo's order (reach 0); `front` is from
// classify(). Any mesh: two-sided when it is not a closed oriented manifold.
// `find_pierces`: the walks also stop where edges pass through faces (a mesh that pierces
// itself; the caller asks for it once a propagation without has met conflicts). kKeep with a
// grid not at the buffer's front: kBadParameter.
Status propagate_qi(const Topology& topo, const uint8_t* front, const CutSet& cutset,
                    const Incidences& inc, void* buffer, size_t bytes, QiState* out, QiStats* stats,
                    bool find_pierces = false, QiSplit split = {}, QiGrid grid = QiGrid::kBuild);

// A piece of an edge with one QI: positions in Q0.32 along the edge from v0 (t1 <= 2^32).
struct QiPiece : EdgePiece {
  int32_t q;  // halves: 0 visible, 2 behind one front face, odd: along a face side
};

using QiSink = Sink<QiPiece>;

// The pieces of every drawn edge, in edge order, then along each edge; then those of the
// contour diagonals (qi_contour_diagonal), numbered from topo.n_drawn up: a triangulated
// polygon that is not flat, or edges left out as smooth (a crease angle), show the silhouette
// along a diagonal, and a hidden-line drawing needs that line.
// Neighbouring pieces with the same QI are merged; empty pieces are left out.
// In parts (`parts`, memory/parts.h) where the walks stop at pierces (state.pierces: each edge
// then asks the faces of its cells, and that walk is the emission's cost; without, the walks
// are cheap and the sink's own work is most of it): rounds of edges, each round's edges in
// ranges, each part keeping its pieces in its share of the buffer (used again every round);
// the sink is then called from this thread in the order above. A part whose share fills up
// stops at its edge, and that edge and the rest of its range are walked here in their turn.
// The pieces do not depend on the parts.
Status emit_qi_pieces(const Topology& topo, const uint8_t* front, const CutSet& cutset,
                      const Incidences& inc, const QiState& state, QiSink sink,
                      PartsBuffer parts = PartsBuffer{});

// A diagonal (not drawn) that is a contour: H3 on a closed solid; two-sided, any edge whose
// faces lie on one side on paper (classify.h's paper_contour).
bool qi_contour_diagonal(const Topology& topo, const QiState& state, uint32_t e);

// The pieces of one edge (any edge, drawn or not), the same way.
Status emit_edge_qi_pieces(const Topology& topo, const uint8_t* front, const CutSet& cutset,
                           const Incidences& inc, const QiState& state, uint32_t edge, QiSink sink);

}  // namespace haloplot
