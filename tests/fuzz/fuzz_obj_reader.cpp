// The OBJ reader, the triangulation and the view transform under arbitrary bytes: the reader
// must return (an error with a line, or a model), never crash; a model it accepts must
// triangulate into real triangles and project without error, every coordinate in range.
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "haloplot/view/projection.h"
#include "io/obj_file.h"
#include "pipeline/triangulate.h"

using namespace haloplot;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  host::ObjModel m;
  if (host::read_obj(in, "fuzz", &m).failed()) return 0;
  std::vector<Point3> screen(m.vertices.size());
  View v;
  if (!ok(project_points(v, m.vertices.data(), uint32_t(screen.size()), screen.data())))
    std::abort();  // the reader's scaling keeps every vertex within the view's range
  for (const Point3& p : screen)
    if (!in_range(p.x) || !in_range(p.y) || !in_range(p.z)) std::abort();
  // Its polygons triangulate into real triangles (three distinct vertices each, all in range)
  // or are counted as not simple; never a fault.
  host::TriangulateStats ts;
  for (const Triangle& t : host::triangulate(m.vertices, m.faces, &ts))
    for (int k = 0; k < 3; ++k)
      if (t.v[k] >= m.vertices.size() || t.v[k] == t.v[(k + 1) % 3]) std::abort();
  if (ts.not_simple > 0 && ts.first_not_simple < 0) std::abort();
  std::vector<Edge3> edges(m.edge_pairs.size() / 2);
  if (!ok(edges_from_indices(screen.data(), uint32_t(screen.size()), m.edge_pairs.data(),
                             uint32_t(edges.size()), edges.data())))
    std::abort();
  return 0;
}
