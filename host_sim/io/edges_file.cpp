#include "io/edges_file.h"

#include <cctype>
#include <fstream>
#include <ostream>

#include "io/line_reader.h"
#include "io/substep_header.h"

namespace haloplot::host {

namespace {

inline constexpr const char* kBezierWord = "bezier";

// n integers in [0, 2^20) from f[first..], numbered for the message as fields first + 1...
std::string parse_coords(const std::vector<std::string>& f, size_t first, size_t n, int32_t* v) {
  for (size_t i = 0; i < n; ++i) {
    int64_t x = 0;
    if (!parse_int(f[first + i], 0, kCoordMax, &x))
      return "field " + std::to_string(first + i + 1) + " '" + excerpt(f[first + i]) +
             "' is not an integer in [0, 1048575]";
    v[i] = int32_t(x);
  }
  return "";
}

Edge3 edge_of(const int32_t* v) { return Edge3{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}}; }

// The lines of either kind; curves == nullptr refuses Bézier records.
// What a file not named .edges was taken for, said with its first refusal: a model without its
// extension (an STL named `part`) is read as an .edges scene and fails on its first line.
std::string not_edges_hint(const std::string& name) {
  const size_t dot = name.rfind('.'), slash = name.rfind('/');
  std::string ext = dot == std::string::npos || (slash != std::string::npos && dot < slash)
                        ? ""
                        : name.substr(dot + 1);
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == "edges") return "";
  return " (a file not named .edges is read as an .edges scene: give a model its extension, "
         ".obj, .stl or .ply)";
}

InputError read_lines(std::istream& in, const std::string& name, EdgesWithCurves* out, bool curves,
                      int32_t* substep_bits) {
  LineReader reader(in);
  std::vector<std::string> f;
  std::string comments;
  uint32_t index = 0;
  while (reader.next(&f, &comments)) {
    int32_t v[12];
    std::string why;
    if (!f.empty() && f[0] == kBezierWord) {
      if (!curves)
        return {name, reader.line(),
                "a Bézier edge ('bezier' record): this command takes straight edges only"};
      if (f.size() != 13)
        return {name, reader.line(),
                "expected 'bezier' and 12 integers (4 control points x y z), found " +
                    std::to_string(f.size() - 1) + " fields after it"};
      why = parse_coords(f, 1, 12, v);
      if (!why.empty()) return {name, reader.line(), why};
      out->curves.push_back(BezierEdge3{
          {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, {v[6], v[7], v[8]}, {v[9], v[10], v[11]}}});
      out->curve_index.push_back(index++);
      continue;
    }
    if (f.size() != 6)
      return {name, reader.line(),
              "expected 6 integers (x1 y1 z1 x2 y2 z2), found " + std::to_string(f.size()) +
                  " fields" + (index == 0 ? not_edges_hint(name) : "")};
    why = parse_coords(f, 0, 6, v);
    if (!why.empty()) return {name, reader.line(), why};
    out->edges.push_back(edge_of(v));
    out->edge_index.push_back(index++);
  }
  if (!reader.error().empty()) return {name, reader.line(), reader.error()};
  if (in.bad()) return {name, 0, "read error"};
  int32_t units = 0;
  std::string why;
  if (!read_substep_header(comments, &units, &why)) return {name, 0, why};
  if (substep_bits != nullptr) *substep_bits = units;
  return {};
}

}  // namespace

InputError read_edges(std::istream& in, const std::string& name, std::vector<Edge3>* edges,
                      int32_t* substep_bits) {
  EdgesWithCurves all;
  const InputError e = read_lines(in, name, &all, false, substep_bits);
  edges->swap(all.edges);
  if (e.failed()) edges->clear();
  return e;
}

InputError read_edges_with_curves(std::istream& in, const std::string& name, EdgesWithCurves* out,
                                  int32_t* substep_bits) {
  *out = EdgesWithCurves();
  const InputError e = read_lines(in, name, out, true, substep_bits);
  if (e.failed()) *out = EdgesWithCurves();
  return e;
}

InputError read_edges_with_curves_file(const std::string& path, EdgesWithCurves* out,
                                       int32_t* substep_bits) {
  std::ifstream in(path);
  if (!in) return {path, 0, "cannot open"};
  return read_edges_with_curves(in, path, out, substep_bits);
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

void write_edges_with_curves(std::ostream& out, const std::vector<BezierEdge3>& curves,
                             const std::vector<Edge3>& edges, const std::string& header) {
  out << header;
  for (const BezierEdge3& c : curves) {
    out << kBezierWord;
    for (const Point3& p : c.p) out << ' ' << p.x << ' ' << p.y << ' ' << p.z;
    out << '\n';
  }
  write_edges(out, edges, "");
}

}  // namespace haloplot::host
