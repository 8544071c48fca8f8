// The OBJ reader: every index form (v, v/vt, v//vn, v/vt/vn), negative indices, CRLF and a
// last line with no newline, `l` polylines, statements it skips; the scaling to world units
// checked by hand; and each error with its line and reason.
#include <sstream>
#include <string>

#include "../check.h"
#include "io/obj_file.h"

using namespace haloplot;
using namespace haloplot::host;

namespace {

ObjModel parse(const std::string& text, InputError* err) {
  std::istringstream in(text);
  ObjModel m;
  *err = read_obj(in, "t.obj", &m);
  return m;
}

void cube() {
  // A cube of side 2 centred at (5, 5, 5): every form of face corner, CRLF, no last newline.
  const std::string text =
      "# cube\r\no cube\r\nv 4 4 4\r\nv 6 4 4\r\nv 6 6 4\r\nv 4 6 4\r\nv 4 4 6\r\nv 6 4 6\r\n"
      "v 6 6 6\r\nv 4 6 6\r\nvt 0 0\r\nvn 0 0 1\r\ns off\r\nusemtl x\r\n"
      "f 1 2 3 4\r\nf 5/1 6/1 7/1 8/1\r\nf 1//1 2//1 6//1 5//1\r\nf -5/1/1 -6/1/1 -2/1/1 -1/1/1\r\n"
      "f 3 4 8 7\r\nf 4 1 5 8";
  InputError err;
  const ObjModel m = parse(text, &err);
  CHECK(!err.failed());
  CHECK_EQ(m.vertices.size(), size_t{8});
  CHECK_EQ(m.faces.size(), size_t{6});
  CHECK_EQ(m.edge_pairs.size(), size_t{24});  // 12 distinct edges
  // Extent 2 -> 2^19 units, centred: every coordinate is +-2^18.
  for (const Point3& p : m.vertices)
    CHECK((p.x == 262144 || p.x == -262144) && (p.y == 262144 || p.y == -262144) &&
          (p.z == 262144 || p.z == -262144));
  CHECK(m.vertices[0].x == -262144 && m.vertices[6].z == 262144);
  // The negative face: -5 is vertex 4 (index 3), -1 is vertex 8 (index 7).
  CHECK(m.faces[3].size() == 4 && m.faces[3][0] == 3 && m.faces[3][3] == 7);
}

void lines_and_errors() {
  InputError err;
  ObjModel m = parse("v 0 0 0\nv 1 0 0\nv 1 1 0\nl 1 2 3\nl 3 2\n", &err);
  CHECK(!err.failed() && m.lines == 2 && m.edge_pairs.size() == 4);  // (1,2), (2,3): repeats merged
  m = parse("v 0 0 0\nv 1 0 0\nf 1 2 0\n", &err);
  CHECK(err.failed() && err.line == 3 && err.message().find("'0'") != std::string::npos);
  m = parse("v 0 0 0\nv 1 0 0\nf 1 2\n", &err);
  CHECK(err.failed() && err.line == 3 && err.message().find("at least 3") != std::string::npos);
  m = parse("v 0 0 zero\n", &err);
  CHECK(err.failed() && err.line == 1 && err.message().find("'zero'") != std::string::npos);
  m = parse("v 0 0 0\nf 1 2 -3\n", &err);  // forward reference
  CHECK(err.failed() && err.line == 2);
  m = parse("# nothing\n", &err);
  CHECK(err.failed() && err.message().find("no vertices") != std::string::npos);
}

}  // namespace

int main() {
  cube();
  lines_and_errors();
  return check::finish("obj");
}
