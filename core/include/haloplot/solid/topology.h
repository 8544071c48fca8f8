// The mesh's topology from its triangles: every edge with its two faces, the stars of every
// vertex (its edges and its faces), and the checks the QI method relies on.
//
// Appel's propagation is only right on a closed, consistently oriented 2-manifold: each edge
// between exactly two faces that traverse it in opposite directions. build_topology() counts
// every way a mesh breaks that (MeshCheck) instead of guessing; the caller then uses the
// topology-free fallback (solid/fallback.h) and says why.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/memory/parts.h"
#include "haloplot/solid/mesh.h"
#include "haloplot/status/status.h"

namespace haloplot {

struct MeshCheck {
  uint32_t boundary_edges = 0;     // triangle sides with one face: the surface is open
  uint32_t nonmanifold_edges = 0;  // sides shared by three or more faces
  uint32_t misoriented_edges = 0;  // two faces traverse the side the same way
  uint32_t loose_edges = 0;        // drawn edges on no face (`l` lines)
  bool manifold() const {
    return boundary_edges == 0 && nonmanifold_edges == 0 && misoriented_edges == 0;
  }
};

struct Topology {
  const Point3* vertices = nullptr;
  uint32_t n_vertices = 0;
  const Triangle* triangles = nullptr;
  uint32_t n_triangles = 0;
  SolidEdge* edges = nullptr;  // drawn edges first (input order), then diagonals
  uint32_t n_edges = 0;
  uint32_t n_drawn = 0;
  // Stars: the edges and the faces at vertex v are [first[v], first[v + 1]) of each list.
  uint32_t* vertex_edge_first = nullptr;
  uint32_t* vertex_edges = nullptr;
  uint32_t* vertex_face_first = nullptr;
  uint32_t* vertex_faces = nullptr;
  MeshCheck check;
  size_t kept_bytes = 0;     // the buffer's first bytes the topology lives in (the rest is free)
  size_t scratch_bytes = 0;  // the build's scratch, at the buffer's top while it ran

  Edge3 edge3(uint32_t e) const { return Edge3{vertices[edges[e].v0], vertices[edges[e].v1]}; }
};

// Bytes build_topology() needs for this input, at most: the arrays it keeps (sized by the
// number of edges, found by the build) from the buffer's start, and its scratch at the top.
// Once it returns, the Topology lives in the first kept_bytes and the rest is free again; the
// build says how much scratch it took (Topology::scratch_bytes, at most this query's).
size_t topology_bytes(const SolidInput& in);
size_t topology_scratch_bytes(const SolidInput& in);  // of those, the scratch at the top

// kBadParameter names an index beyond the vertices, an edge from a vertex to itself, a repeated
// drawn edge or a triangle with a repeated corner; kWorkspaceTooSmall a short buffer.
struct TopologyOptions {
  bool stars = true;  // the vertex stars (QI, the V.C. table and outline tracing read them)
  // A band of a banded plot: a triangle side that is not a drawn edge becomes a diagonal only
  // when it meets rows [row_lo, row_hi] (inclusive); sides beyond them have no edge
  // , since nothing in the band's rows can cross them.
  bool rows = false;
  int32_t row_lo = 0, row_hi = 0;
  // A runner for the build's parts (memory/parts.h), or null: one part. The topology is the
  // same, array for array, whatever the parts; in parts the build takes no more than
  // topology_bytes() either (it uses the spare room there when it has it).
  const Parts* parts = nullptr;
};
Status build_topology(const SolidInput& in, void* buffer, size_t bytes, Topology* out,
                      const TopologyOptions& options = TopologyOptions{});

// The stars of a topology built without them (TopologyOptions::stars false), carved from
// `buffer` (topology_star_bytes() bytes at most; kWorkspaceTooSmall when shorter): the same
// arrays the build would have made. hidden_lines() adds them after CUT, on pages CUT's scratch
// used, so they are not held through CUT (on a 1M-triangle mesh, 28 of its peak's MB). In
// parts when `parts` has a runner: the same stars.
size_t topology_star_bytes(const Topology& topo);
Status build_topology_stars(Topology* topo, void* buffer, size_t bytes,
                            const Parts* parts = nullptr);

// A band's run (solid/hidden_lines.h, HiddenParams::band) draws no diagonal and reads no star:
// a diagonal matters there only as an edge that drawn edges pass behind. One whose two faces lie
// on opposite sides of it on paper (a regular side, both faces' projected areas of one sign and
// not 0, and of one facing when `facing` is given) changes nothing along an edge passing behind
// it: where one face stops covering, the other begins, at the same depth order. Those are
// dropped from the edge list (the drawn edges and the other diagonals keep their order), and
// their bytes given back: kept_bytes shrinks. A topology with stars is left as it is (the stars
// name edges by index).
void drop_flat_diagonals(Topology* topo, const uint8_t* facing);

}  // namespace haloplot
