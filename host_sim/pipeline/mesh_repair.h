// Cleaning a model before it is projected, whatever file it came from.
//
// Welding: vertices at the same place become one vertex, so a triangle soup (STL: every
// triangle with its own three vertices) gets its topology back, each edge drawn once. "The
// same place" is the same integer world position (the model scaled to span 2^19 units: one
// unit is 1/524288 of the model's size, below any plotter's resolution), or with a tolerance
// within that distance of a vertex kept before it (in file order). By default the distance is
// weld_distance below: corners that could be one point of the exporter's, each stored within
// the file's rounding of it. A face's corners are then reduced as a closed walk: repeats and
// spikes (a, b, a: out and straight back, no area) go, and a face left with fewer than three
// corners is dropped.
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
#include "pipeline/open_sides.h"

namespace haloplot::host {

// One place where the first shell that cannot be oriented shows why, for the message: a side
// on three or more faces, or else a side its two faces run the same way as the file gives them
// (a shell that cannot be oriented has one: else the file's own winding would orient it; where
// the file is wound consistently but for a seam, a Moebius strip's, it is on the seam).
struct ShellProblem {
  uint32_t faces_on_side = 0;  // 0: no such shell; 2: a twist; 3 or more: that many faces
  uint32_t line = 0;           // the model-file line of a face on the side (0: not known)
  double from[3] = {0, 0, 0}, to[3] = {0, 0, 0};  // the side's ends (file coordinates)
  double unit = 0;  // one world unit in the file's units: how near from and to are to the file's
};

struct RepairReport {
  uint32_t merged_vertices = 0;  // vertices welded into another
  uint32_t dropped_faces = 0;    // faces with fewer than three corners left after welding
  uint32_t shells = 0, closed_shells = 0;
  uint32_t flipped_faces = 0;        // faces turned to agree with their shell
  uint32_t turned_shells = 0;        // closed shells turned outward (inside out before)
  uint32_t unorientable_shells = 0;  // left as given: non-manifold sides or a twist
  uint32_t flat_edges = 0;           // drawn edges between faces within the crease angle
  // Of those, the ones only --crease DEG left out (not flat but for the rounding): a bend of a
  // smooth surface, whose contours only the hidden-line modes draw in their place.
  uint32_t bent_edges = 0;
  // Without a crease angle: drawn edges kept between faces less than kGentleDegrees apart (a
  // smooth surface's facets, which --crease would leave out), of kept_edges drawn in all.
  uint32_t gentle_edges = 0, kept_edges = 0;
  ShellProblem problem;  // where the first shell that cannot be oriented shows it
  // Filled in by the reader where asked (scene_input.h, read_model): the open sides measured
  // and the weld they suggest (open_sides.h).
  bool measured = false;
  bool measure_open = true;  // asked by the caller: false where no shells message is said
  OpenSides open;
  WeldHint weld;
  // With --weld EPS given and a shell not closed: the file welded at EPS and at the default
  // weld_distance, compared (a weld too wide makes sides on three faces of a model's fins).
  bool compared = false;
  WeldTrial with_given, with_default;
};

// How far a vertex may lie from where the exporter meant it, per coordinate, in world units:
// the file's rounding (io/coordinate_rounding.h) times the model's scale, plus the half unit
// place_vertices rounds each world coordinate by.
double vertex_rounding(const ObjModel& model);
// The default weld distance: two stored corners of one point are each within vertex_rounding
// of it in every coordinate, so within 2 * that per coordinate, 2 * sqrt(3) * that apart. At
// least 1.7 world units (about 3 millionths of the model's size), so corners that round to
// neighbouring world positions are joined too.
double weld_distance(const ObjModel& model);

// Welds vertices within `tolerance` world units (0: the same position only). Faces, their
// lines and the drawn edges follow (edges in the order they first appeared, each once).
void weld_vertices(ObjModel* model, double tolerance, RepairReport* report);

// Orients every shell's faces as above.
void orient_shells(ObjModel* model, RepairReport* report);

// Which edges count as flat (--crease).
struct CreaseRule {
  bool keep_all = false;  // --crease off: every edge drawn
  double deg = 0;         // faces whose normals are within this angle (degrees); 0: none
  double rounding = 0;    // vertex_rounding (world units); 0: only exactly coplanar faces
};

// Creases: a drawn edge between exactly two faces that face the same way and count as flat
// is no longer a drawn edge, so it is drawn only where it is a contour (the core treats it as
// a diagonal inside a polygon). An edge on one face (a boundary) or on three or more is always
// kept. Flat, any of:
// - exactly: both faces planar, in one plane, facing the same way (decided on the integer
//   vertices: the diagonals of a flat face split into triangles);
// - rule.deg > 0: their normals differ by less than rule.deg degrees;
// - rule.rounding > 0: they could be one flat polygon but for the rounding of their vertices:
//   normals less than 90 degrees apart, and every corner of each lies within what rounding can
//   produce of the other's plane. With every coordinate within d = rule.rounding of a
//   configuration where both are in one plane, the plane's twice-area normal n (Newell's, k
//   corners, D the sum of the distances |v[i+1] - v[i-1]| around it) is off by at most
//   E = sqrt(3) d D + 9 k d^2, and a corner p's n . (p - a), a the shared side's first end, is
//   at most 2 sqrt(3) d |n| + E (|p - a| + 6 sqrt(3) d) (the first-order terms and the rest,
//   each bounded; exact integers on the left, doubles on the right). A distance, not an angle:
//   a sliver's plane is only known to an angle as wide as the rounding over its height, and
//   the bound says so, so a sliver in a flat face leaves no line; a sliver no higher than the
//   rounding that lies along a real crease leaves it out too (its corners are on both planes).
// Run it after orient_shells (the normals of faces wound different ways point apart).
void drop_flat_edges(ObjModel* model, const CreaseRule& rule, RepairReport* report);
// What counts as a gentle bend for RepairReport::gentle_edges (the plot's hint to use --crease).
inline constexpr double kGentleDegrees = 10;

// Regions: faces joined through sides on exactly two faces that are not drawn edges (left out
// by drop_flat_edges: flat but for the rounding, or within --crease) make one region, a surface
// the drawn lines bound: a flat cap exported as a fan of slivers, a float32 box's triangulated
// sides, a smooth body between its creases at --crease 40. It is hatched with one family of
// lines, not a fan of directions. model->face_region[f] is the region's first face. Run it
// after drop_flat_edges.
void find_regions(ObjModel* model);

}  // namespace haloplot::host
