// Faces in a uniform grid (each face in every cell its bounding box meets), so "which faces
// could cover this point" asks one cell instead of every face. The fallback's midpoint tests
// and the QI method's ray casts both use it. Cells are about one face each, larger where the
// faces' boxes would then meet more than kFaceGridPairsPerFace cells on average: the (cell,
// face) pairs, four bytes each, are at most that many a face, whatever the faces' sizes.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/cut/grid.h"
#include "haloplot/memory/parts.h"
#include "haloplot/solid/topology.h"
#include "haloplot/status/status.h"

namespace haloplot {

inline constexpr uint32_t kFaceGridPairsPerFace = 7;

struct FaceGrid {
  Grid grid;
  const uint32_t* first = nullptr;  // [cells + 1]
  const uint32_t* faces = nullptr;
  uint32_t pairs = 0;

  // The faces whose bounding box may hold the point (x, y) (floors of a rational point).
  const uint32_t* begin(int32_t x, int32_t y) const { return faces + first[grid.cell_of(x, y)]; }
  const uint32_t* end(int32_t x, int32_t y) const { return faces + first[grid.cell_of(x, y) + 1]; }
};

// A solid input's faces as a topology without edges: all the face grid reads.
inline Topology faces_only(const SolidInput& in) {
  Topology t;
  t.vertices = in.vertices;
  t.n_vertices = in.n_vertices;
  t.triangles = in.triangles;
  t.n_triangles = in.n_triangles;
  return t;
}

// `coarsen` > 1: cells that many times wider (and taller) than one face per cell gives, for
// fewer (cell, face) pairs at more faces a cell asks (solid/hidden_lines.cpp: a band's grid).
size_t face_grid_bytes(const Topology& topo, uint32_t coarsen = 1);  // counts (no walk)
// The same for a grid already built (no count).
size_t face_grid_bytes(const FaceGrid& fg);

// `parts` (memory/parts.h): the counting sort in parts of the faces, each with its own cursor
// into every cell, face_grid_part_bytes() each beyond the first part's, taken from the bytes
// after face_grid_bytes() (scratch, free again on return); fewer parts where fewer fit. The
// grid is the same, cell for cell and face for face, however many parts built it.
size_t face_grid_part_bytes(const Topology& topo, uint32_t coarsen = 1);
Status build_face_grid(const Topology& topo, void* buffer, size_t bytes, FaceGrid* out,
                       uint32_t coarsen = 1, const Parts* parts = nullptr);

}  // namespace haloplot
