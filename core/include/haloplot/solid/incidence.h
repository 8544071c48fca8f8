// The singular places of a projected mesh, found exactly: a vertex lying inside another
// edge's projection (an edge through a vertex, or a vertex on a contour), and vertices that
// project onto the same point (vertex on vertex). CUT reports only proper crossings; these
// are the touches it leaves out, and the places Heger's half, quarter and delta q.i. are for.
//
// Found with a uniform grid of vertices (about one vertex per cell): each edge walks the cells
// its projection passes (cut/grid.h) and tests the vertices there exactly, so the cost is
// linear in the edges' cell counts, not quadratic.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/memory/parts.h"
#include "haloplot/solid/topology.h"
#include "haloplot/status/status.h"

namespace haloplot {

struct Incidence {
  uint32_t edge;      // the edge whose interior passes through ...
  uint32_t vertex;    // ... this vertex's projection (not one of its endpoints)
  uint32_t t;         // floor(position along the edge * 2^32), from its v0
  uint32_t num, den;  // the exact position along the edge: num / den (0 < num < den <= 2^20)
};

struct Incidences {
  Incidence* by_edge = nullptr;  // sorted by (edge, t, vertex)
  uint32_t n = 0;
  uint32_t* edge_first = nullptr;    // [n_edges + 1] into by_edge
  uint32_t* by_vertex = nullptr;     // indices into by_edge, grouped by vertex
  uint32_t* vertex_first = nullptr;  // [n_vertices + 1] into by_vertex
  uint32_t* same_next = nullptr;     // next vertex at the same projected point (itself if alone)
  uint32_t coincident_vertices = 0;  // vertices sharing their point with another
};

// `by_vertex` false: only the records by edge (by_edge, edge_first); by_vertex, vertex_first and
// same_next stay null (the topology-free method asks them only for Kira's V.C. table).
size_t incidence_bytes(const Topology& topo, uint32_t capacity, bool by_vertex = true);
// Of those, the search's scratch: the buffer's last bytes (before the 8 of alignment), free
// again once find_incidences() returns.
size_t incidence_scratch_bytes(const Topology& topo);

// kIncidenceCapacity when more than `capacity` incidences exist (`*needed` says how many).
// `parts` (memory/parts.h): the search in parts of the vertex grid's cells and of the edges,
// which threads may run at once, in the same bytes; the arrays are the same, element for
// element, however many parts there were.
Status find_incidences(const Topology& topo, uint32_t capacity, void* buffer, size_t bytes,
                       Incidences* out, uint32_t* needed, bool by_vertex = true,
                       const Parts* parts = nullptr);

}  // namespace haloplot
