// Wavefront OBJ on the host: `v x y z [w | r g b]` (trailing fields such as vertex colours are
// ignored), `f` n-gons (indices in the v, v/vt, v//vn and
// v/vt/vn forms, negative indices counting back from the last vertex), `l` polylines; other
// statements (vt, vn, o, g, s, usemtl, mtllib, ...) are skipped. Comments, blank lines, CRLF
// and a last line without a newline are fine. Errors name the file, the line and the reason.
//
// The model becomes integer world coordinates for the core: centred on its bounding box and
// scaled uniformly so its largest extent spans 2^19 units (within the view's +-2^20). Edges
// are the distinct undirected vertex pairs of the face boundaries and lines, in the order they
// first appear: the edge order every output uses.
#pragma once
#include <cstdint>
#include <istream>
#include <string>
#include <vector>

#include "haloplot/geometry/contract.h"
#include "io/coordinate_rounding.h"
#include "io/input_error.h"

namespace haloplot::host {

struct ObjModel {
  std::vector<Point3> vertices;              // integer world coordinates (see above)
  std::vector<uint32_t> edge_pairs;          // 2 vertex indices per edge
  std::vector<std::vector<uint32_t>> faces;  // vertex indices per face, as given
  std::vector<uint32_t> face_lines;          // the line each face was read from
  // The region each face belongs to (its first face; mesh_repair.h, find_regions):
  // hatched as one surface. Empty: each face is its own.
  std::vector<uint32_t> face_region;
  uint32_t lines = 0;            // `l` statements read
  double scale = 1;              // world units per unit of the file
  double centre[3] = {0, 0, 0};  // the file's bounding-box centre (file units)
  double magnitude = 0;          // the largest |coordinate| in the file
  double rounding =
      0;  // how far a stored coordinate may be off (file units; coordinate_rounding.h)
};

InputError read_obj(std::istream& in, const std::string& name, ObjModel* out);

// The file's coordinates (x y z per vertex) into out->vertices, centred on their bounding box
// and scaled as above (out->scale: world units per file unit); out->rounding is `rounding`'s
// bound at the file's largest magnitude. Every reader ends with it.
void place_vertices(const std::vector<double>& xyz, const CoordinateRounding& rounding,
                    ObjModel* out);
// out->edge_pairs anew from the faces' sides, in the order they first appear (formats with no
// lines: STL, PLY; and after welding).
void edges_from_faces(ObjModel* model);

// Which axis of the file points up. Most OBJ files are Y-up (Blender's and Maya's export
// default, LightWave's files); haloplot's world is Z-up (the view's convention, core/view).
enum class UpAxis { kX, kY, kZ, kMinusX, kMinusY, kMinusZ };
// "x", "y", "z", "-x", "-y" or "-z"; false for anything else.
bool parse_up_axis(const std::string& text, UpAxis* out);
// The model in haloplot's Z-up world, turned by the quarter or half turn that takes the named
// axis to +Z (a rotation, never a mirror: a sign flip and a swap of the integer coordinates,
// exact, with the centring and scale unchanged). A file point (x, y, z) becomes
//   y: (x, -z, y)   -y: (x, z, -y)   (about the x axis)
//   x: (-z, y, x)   -x: (z, y, -x)   (about the y axis)
//   z: (x, y, z)    -z: (x, -y, -z)  (-z: a half turn about the x axis)
void make_z_up(ObjModel* model, UpAxis up);
// The same turn of one point or direction (file axes to world axes).
void turn_z_up(UpAxis up, const double in[3], double out[3]);
InputError read_obj_file(const std::string& path, ObjModel* out);

}  // namespace haloplot::host
