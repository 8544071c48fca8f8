#include "io/obj_file.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>

#include "io/line_reader.h"
#include "io/pair_set.h"

namespace haloplot::host {
namespace {

// One face or line corner: the vertex index before the first '/', 1-based or negative.
bool parse_index(std::string_view corner, size_t n_vertices, uint32_t* out, std::string* why) {
  const std::string_view v = corner.substr(0, corner.find('/'));
  int64_t i = 0;
  if (!parse_int_field(v, -int64_t(n_vertices), int64_t(n_vertices), &i) || i == 0) {
    *why = "vertex index '" + excerpt(std::string(v)) + "' is not in 1.." +
           std::to_string(n_vertices) + " or -1..-" + std::to_string(n_vertices) +
           " (vertices defined so far)";
    return false;
  }
  *out = uint32_t(i > 0 ? i - 1 : int64_t(n_vertices) + i);
  return true;
}

}  // namespace

InputError read_obj(std::istream& in, const std::string& name, ObjModel* out) {
  *out = ObjModel{};
  std::vector<double> xyz;
  LineReader reader(in);
  std::vector<std::string_view> f;
  PairSet seen;
  auto add_edge = [&](uint32_t a, uint32_t b) {
    if (a == b) return;
    if (seen.insert(pair_key(a, b))) out->edge_pairs.insert(out->edge_pairs.end(), {a, b});
  };
  std::vector<uint32_t> idx;
  CoordinateRounding rounding;
  while (reader.next(&f)) {
    const std::string_view k = f[0];
    if (k == "v") {
      if (f.size() < 4)
        return {name, reader.line(), "a vertex needs x y z (then w, or r g b, may follow)"};
      double c[3];
      for (int i = 0; i < 3; ++i)
        if (!parse_finite(f[1 + i], &c[i]))
          return {name, reader.line(),
                  "coordinate '" + excerpt(std::string(f[1 + i])) + "' is not a number"};
      for (int i = 0; i < 3; ++i) rounding.note_text(f[1 + i]);
      xyz.insert(xyz.end(), c, c + 3);
    } else if (k == "f" || k == "l") {
      const size_t need = k == "f" ? 3 : 2;
      if (f.size() - 1 < need)
        return {name, reader.line(),
                std::string(k == "f" ? "a face" : "a line") + " needs at least " +
                    std::to_string(need) + " vertices, found " + std::to_string(f.size() - 1)};
      idx.clear();
      for (size_t i = 1; i < f.size(); ++i) {
        uint32_t v;
        std::string why;
        if (!parse_index(f[i], xyz.size() / 3, &v, &why)) return {name, reader.line(), why};
        idx.push_back(v);
      }
      for (size_t i = 0; i + 1 < idx.size(); ++i) add_edge(idx[i], idx[i + 1]);
      if (k == "f") {
        add_edge(idx.back(), idx.front());
        out->faces.emplace_back(idx.begin(), idx.end());
        out->face_lines.push_back(uint32_t(reader.line()));
      } else {
        ++out->lines;
      }
    }
  }
  if (!reader.error().empty()) return {name, reader.line(), reader.error()};
  if (in.bad()) return {name, 0, "read error"};
  if (xyz.empty()) return {name, reader.line(), "no vertices"};
  place_vertices(xyz, rounding, out);
  return {};
}

void place_vertices(const std::vector<double>& xyz, const CoordinateRounding& rounding,
                    ObjModel* out) {
  // Centre and scale uniformly: the largest extent spans 2^19 world units.
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int a = 0; a < 3 && !xyz.empty(); ++a) {
    lo[a] = hi[a] = xyz[size_t(a)];
    for (size_t i = size_t(a); i < xyz.size(); i += 3)
      lo[a] = std::min(lo[a], xyz[i]), hi[a] = std::max(hi[a], xyz[i]);
  }
  const double extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
  const double scale = extent > 0 ? double(1 << 19) / extent : 1.0;
  out->scale = scale;
  out->magnitude = 0;
  for (double c : xyz) out->magnitude = std::max(out->magnitude, std::fabs(c));
  out->rounding = rounding.bound(out->magnitude);
  for (int a = 0; a < 3; ++a) out->centre[a] = (lo[a] + hi[a]) / 2;
  out->vertices.clear();
  out->vertices.reserve(xyz.size() / 3);
  for (size_t i = 0; i < xyz.size(); i += 3) {
    int32_t c[3];
    for (int a = 0; a < 3; ++a)
      c[a] = int32_t(std::lround((xyz[i + size_t(a)] - (lo[a] + hi[a]) / 2) * scale));
    out->vertices.push_back(Point3{c[0], c[1], c[2]});
  }
}

void edges_from_faces(ObjModel* model) {
  model->edge_pairs.clear();
  PairSet seen;
  for (const std::vector<uint32_t>& f : model->faces)
    for (size_t i = 0; i < f.size(); ++i) {
      const uint32_t a = f[i], b = f[(i + 1) % f.size()];
      if (a != b && seen.insert(pair_key(a, b)))
        model->edge_pairs.insert(model->edge_pairs.end(), {a, b});
    }
}

InputError read_obj_file(const std::string& path, ObjModel* out) {
  std::ifstream in(path, std::ios::binary);
  if (const InputError e = open_problem(path, in); e.failed()) return e;
  return read_obj(in, path, out);
}

bool parse_up_axis(const std::string& text, UpAxis* out) {
  static const char* const kNames[6] = {"x", "y", "z", "-x", "-y", "-z"};
  for (int i = 0; i < 6; ++i)
    if (text == kNames[i]) {
      *out = UpAxis(i);
      return true;
    }
  return false;
}

namespace {

// The turn as a signed permutation: world axis a is sign[a] times file axis from[a].
struct Turn {
  int from[3], sign[3];
};

Turn turn_of(UpAxis up) {
  switch (up) {
    case UpAxis::kX:
      return {{2, 1, 0}, {-1, 1, 1}};
    case UpAxis::kY:
      return {{0, 2, 1}, {1, -1, 1}};
    case UpAxis::kZ:
      return {{0, 1, 2}, {1, 1, 1}};
    case UpAxis::kMinusX:
      return {{2, 1, 0}, {1, 1, -1}};
    case UpAxis::kMinusY:
      return {{0, 2, 1}, {1, 1, -1}};
    case UpAxis::kMinusZ:
      return {{0, 1, 2}, {1, -1, -1}};
  }
  return {{0, 1, 2}, {1, 1, 1}};
}

}  // namespace

void turn_z_up(UpAxis up, const double in[3], double out[3]) {
  const Turn t = turn_of(up);
  for (int a = 0; a < 3; ++a) out[a] = t.sign[a] * in[t.from[a]];
}

void make_z_up(ObjModel* model, UpAxis up) {
  const Turn t = turn_of(up);
  for (Point3& p : model->vertices) {
    const int32_t c[3] = {p.x, p.y, p.z};
    p = Point3{t.sign[0] * c[t.from[0]], t.sign[1] * c[t.from[1]], t.sign[2] * c[t.from[2]]};
  }
}

}  // namespace haloplot::host
