#include "io/polygon_file.h"

#include <fstream>

#include "io/line_reader.h"

namespace haloplot::host {

InputError read_polygon(std::istream& in, const std::string& name, std::vector<Point2>* out) {
  out->clear();
  LineReader reader(in);
  std::vector<std::string> f;
  while (reader.next(&f)) {
    if (f.size() != 2)
      return {name, reader.line(),
              "expected 2 integers (x y), found " + std::to_string(f.size()) + " fields"};
    int64_t v[2];
    for (int i = 0; i < 2; ++i)
      if (!parse_int(f[i], -kView2dLimit, kView2dLimit, &v[i]))
        return {name, reader.line(),
                "field " + std::to_string(i + 1) + " '" + excerpt(f[i]) +
                    "' is not an integer in [-1048576, 1048576]"};
    out->push_back(Point2{int32_t(v[0]), int32_t(v[1])});
  }
  if (!reader.error().empty()) return {name, reader.line(), reader.error()};
  if (in.bad()) return {name, 0, "read error"};
  if (out->size() < 3)
    return {name, reader.line(),
            "a polygon needs at least 3 vertices, found " + std::to_string(out->size())};
  return {};
}

InputError read_polygon_file(const std::string& path, std::vector<Point2>* out) {
  std::ifstream in(path);
  if (const InputError e = open_problem(path, in); e.failed()) return e;
  return read_polygon(in, path, out);
}

}  // namespace haloplot::host
