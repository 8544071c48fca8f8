// Model files on the host: Wavefront OBJ (io/obj_file.h), STL (binary and ASCII) and PLY
// (ASCII, binary little and big endian), told apart by their extension (any case) and checked
// against their content, so a file that is not what its name says is refused by name. Every
// reader gives the same ObjModel (integer world vertices, faces, edges), so what follows the
// reading (welding, orientation repair, projection, hidden lines) is the same for all three.
//
// STL: `solid`/`facet normal`/`outer loop`/`vertex x y z`/`endloop`/`endfacet`/`endsolid`
// (keywords in any case, several solids in one file), or the binary form (an 80-byte header, a
// little-endian uint32 triangle count, then 50 bytes a triangle: a normal, three vertices as
// floats and a 16-bit attribute). The normals and attributes are skipped: the winding says
// which side is out. Every triangle has its own three vertices (weld them: mesh_repair.h).
//
// PLY: the header's `format`, `element` and `property` lines (`comment`, `obj_info` and other
// lines skipped), then the `vertex` element's x, y, z and the `face` element's list property
// `vertex_indices` (or `vertex_index`); every other property and element is read past. The
// data is ASCII (one element item a line) or binary of either byte order.
//
// Errors: `FILE:LINE: what` for text, `FILE: byte N: what` for binary data.
#pragma once
#include <string>

#include "io/input_error.h"
#include "io/obj_file.h"

namespace haloplot::host {

enum class MeshFormat { kObj, kStl, kPly };

// The format an extension names (.obj, .stl, .ply in any case); false for anything else.
bool mesh_format_of(const std::string& path, MeshFormat* format);
inline bool is_mesh_path(const std::string& path) {
  MeshFormat f;
  return mesh_format_of(path, &f);
}

// The readers on a whole file's bytes. `name` is the file as messages name it.
InputError read_stl(const std::string& bytes, const std::string& name, ObjModel* out);
InputError read_ply(const std::string& bytes, const std::string& name, ObjModel* out);

// Reads `path` by its extension after checking the content is that format (a PLY file named
// .stl, an STL named .obj, ... is refused, saying what it is).
InputError read_mesh_file(const std::string& path, ObjModel* out);

}  // namespace haloplot::host
