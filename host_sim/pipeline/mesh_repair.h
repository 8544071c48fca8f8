// Cleaning a model before it is projected, whatever file it came from.
//
// Welding: vertices at the same place become one vertex, so a triangle soup (STL: every
// triangle with its own three vertices) gets its topology back, each edge drawn once. "The
// same place" is the same integer world position (the model scaled to span 2^19 units: one
// unit is 1/524288 of the model's size, below any plotter's resolution), or with a tolerance
// within that distance of a vertex kept before it (in file order).
//
// Orientation: each shell (faces connected through shared sides) is made consistent: its
// faces are turned so every side shared by two faces is traversed once each way (breadth
// first from the shell's first face). A closed shell (every side on exactly two faces) is then
// turned outward by the sign of its volume; an open one keeps the winding most of its faces
// were given. A shell that cannot be oriented (a side on three or more faces, or a Moebius
// strip's twist) is left as given: its mesh is no closed oriented manifold, so the hidden
// lines are found by the method that needs no orientation (solid_pipeline.h, kAuto).
#pragma once
#include <cstdint>

#include "io/obj_file.h"

namespace haloplot::host {

struct RepairReport {
  uint32_t merged_vertices = 0;  // vertices welded into another
  uint32_t dropped_faces = 0;    // faces with fewer than three corners left after welding
  uint32_t shells = 0, closed_shells = 0;
  uint32_t flipped_faces = 0;        // faces turned to agree with their shell
  uint32_t turned_shells = 0;        // closed shells turned outward (inside out before)
  uint32_t unorientable_shells = 0;  // left as given: non-manifold sides or a twist
  uint32_t flat_edges = 0;           // drawn edges between faces within the crease angle
};

// Welds vertices within `tolerance` world units (0: the same position only). Faces, their
// lines and the drawn edges follow (edges in the order they first appeared, each once).
void weld_vertices(ObjModel* model, double tolerance, RepairReport* report);

// Orients every shell's faces as above.
void orient_shells(ObjModel* model, RepairReport* report);

// Creases: a drawn edge between exactly two faces whose normals differ by less than
// `crease_deg` degrees is no longer a drawn edge, so it is drawn only where it is a contour
// (the core treats it as a diagonal inside a polygon). 0 degrees: only between two planar
// faces in one plane facing the same way, decided exactly on the integer vertices (the
// diagonals of a flat face split into triangles). Negative: every edge kept. Run it after
// orient_shells (the normals of faces wound different ways point apart).
void drop_flat_edges(ObjModel* model, double crease_deg, RepairReport* report);

}  // namespace haloplot::host
