#include "io/edges_file.h"

#include <fstream>
#include <ostream>

#include "io/line_reader.h"
#include "io/substep_header.h"

namespace haloplot::host {

InputError read_edges(std::istream& in, const std::string& name, std::vector<Edge3>* edges,
                      int32_t* substep_bits) {
  edges->clear();
  LineReader reader(in);
  std::vector<std::string> f;
  std::string comments;
  while (reader.next(&f, &comments)) {
    if (f.size() != 6)
      return {
          name, reader.line(),
          "expected 6 integers (x1 y1 z1 x2 y2 z2), found " + std::to_string(f.size()) + " fields"};
    int64_t v[6];
    for (int i = 0; i < 6; ++i)
      if (!parse_int(f[i], 0, kCoordMax, &v[i]))
        return {name, reader.line(),
                "field " + std::to_string(i + 1) + " '" + excerpt(f[i]) +
                    "' is not an integer in [0, 1048575]"};
    edges->push_back(Edge3{{int32_t(v[0]), int32_t(v[1]), int32_t(v[2])},
                           {int32_t(v[3]), int32_t(v[4]), int32_t(v[5])}});
  }
  if (!reader.error().empty()) return {name, reader.line(), reader.error()};
  if (in.bad()) return {name, 0, "read error"};
  int32_t units = 0;
  std::string why;
  if (!read_substep_header(comments, &units, &why)) return {name, 0, why};
  if (substep_bits != nullptr) *substep_bits = units;
  return {};
}

InputError read_edges_file(const std::string& path, std::vector<Edge3>* edges,
                           int32_t* substep_bits) {
  std::ifstream in(path);
  if (const InputError e = open_problem(path, in); e.failed()) return e;
  return read_edges(in, path, edges, substep_bits);
}

void write_edges(std::ostream& out, const std::vector<Edge3>& edges, const std::string& header) {
  out << header;
  for (const Edge3& e : edges)
    out << e.a.x << ' ' << e.a.y << ' ' << e.a.z << ' ' << e.b.x << ' ' << e.b.y << ' ' << e.b.z
        << '\n';
}

}  // namespace haloplot::host
