#include "io/cut_file.h"

#include <fstream>
#include <ostream>

#include "io/line_reader.h"

namespace haloplot::host {

std::string decimal_position(int32_t a, int32_t d, uint32_t t32) {
  // a + d * t / 2^32 in thousandths, rounded half up; exact in 128 bits on the host.
  const __int128 scaled =
      (static_cast<__int128>(a) << 32) * 1000 + static_cast<__int128>(d) * t32 * 1000;
  const __int128 thousandths = (scaled + (static_cast<__int128>(1) << 31)) >> 32;
  const long long v = static_cast<long long>(thousandths);
  const long long whole = v >= 0 ? v / 1000 : -((-v + 999) / 1000);
  const long long frac = v - whole * 1000;
  std::string f = std::to_string(frac);
  return std::to_string(whole) + "." + std::string(3 - f.size(), '0') + f;
}

void write_cut(std::ostream& out, const CutSet& set, const std::string& extra_header) {
  out << "# haloplot cutset v1\n" << extra_header << "# reach " << set.reach << "\n";
  for (uint32_t i = 0; i < set.n_edges; ++i) {
    const Edge3& e = set.edges[i];
    out << "e " << i << ' ' << e.a.x << ' ' << e.a.y << ' ' << e.a.z << ' ' << e.b.x << ' ' << e.b.y
        << ' ' << e.b.z << '\n';
  }
  for (uint32_t i = 0; i < set.n_edges; ++i) {
    const Edge3& e = set.edges[i];
    for (uint32_t k = 0; k < set.count(i); ++k) {
      const Crossing& c = set.begin(i)[k];
      out << "c " << c.behind << ' ' << c.front_edge() << ' '
          << decimal_position(e.a.x, e.b.x - e.a.x, c.t) << ' '
          << decimal_position(e.a.y, e.b.y - e.a.y, c.t) << ' ' << c.t << ' '
          << (c.near_miss() ? "near" : "cross") << '\n';
    }
  }
}

InputError read_cut(std::istream& in, const std::string& name, LoadedCut* out) {
  *out = LoadedCut{};
  LineReader reader(in);
  std::vector<std::string> f;
  std::string comments;
  bool in_crossings = false;
  int64_t reach = 0;
  while (reader.next(&f, &comments)) {
    const int line = reader.line();
    if (f[0] == "e") {
      if (in_crossings) return {name, line, "'e' line after the first 'c' line"};
      if (f.size() != 8) return {name, line, "an 'e' line needs an index and 6 integers"};
      int64_t v[7];
      if (!parse_int(f[1], 0, kMaxEdges, &v[0]) || v[0] != int64_t(out->edges.size()))
        return {name, line,
                "edge index '" + excerpt(f[1]) + "' out of order (expected " +
                    std::to_string(out->edges.size()) + ")"};
      for (int i = 1; i < 7; ++i)
        if (!parse_int(f[i + 1], 0, kCoordMax, &v[i]))
          return {name, line, "'" + excerpt(f[i + 1]) + "' is not an integer in [0, 1048575]"};
      out->edges.push_back(Edge3{{int32_t(v[1]), int32_t(v[2]), int32_t(v[3])},
                                 {int32_t(v[4]), int32_t(v[5]), int32_t(v[6])}});
    } else if (f[0] == "c") {
      in_crossings = true;
      if (f.size() < 7) return {name, line, "a 'c' line needs BEHIND FRONT X Y T KIND"};
      const int64_t n = int64_t(out->edges.size());
      int64_t behind, front, t;
      if (!parse_int(f[1], 0, n - 1, &behind))
        return {name, line, "BEHIND '" + excerpt(f[1]) + "' is not an edge index"};
      if (!parse_int(f[2], 0, n - 1, &front) || front == behind)
        return {name, line, "FRONT '" + excerpt(f[2]) + "' is not another edge's index"};
      if (!parse_int(f[5], 0, 0xffffffffLL, &t))
        return {name, line, "T '" + excerpt(f[5]) + "' is not an integer in [0, 2^32)"};
      if (f[6] != "cross" && f[6] != "near")
        return {name, line, "KIND '" + excerpt(f[6]) + "' is neither 'cross' nor 'near'"};
      Crossing c{uint32_t(behind), uint32_t(front) | (f[6] == "near" ? Crossing::kNearBit : 0u),
                 uint32_t(t)};
      if (!out->crossings.empty()) {
        const Crossing& p = out->crossings.back();
        const bool ordered =
            p.behind < c.behind ||
            (p.behind == c.behind && (p.t < c.t || (p.t == c.t && p.front < c.front)));
        if (!ordered)
          return {name, line,
                  "records must be grouped by BEHIND and ordered along it by (T, FRONT)"};
      }
      out->crossings.push_back(c);
    } else {
      return {name, line, "unknown record '" + excerpt(f[0]) + "' (expected 'e' or 'c')"};
    }
  }
  if (!reader.error().empty()) return {name, reader.line(), reader.error()};
  if (in.bad()) return {name, 0, "read error"};
  const size_t at = comments.find("# reach ");
  if (at != std::string::npos) {
    const std::string value = comments.substr(at + 8, comments.find('\n', at) - at - 8);
    if (!parse_int(value, 0, kCoordMax, &reach)) return {name, 0, "bad '# reach' header"};
  }
  out->set.reach = int32_t(reach);
  out->first.assign(out->edges.size() + 1, 0);
  for (const Crossing& c : out->crossings) ++out->first[c.behind + 1];
  for (size_t e = 0; e < out->edges.size(); ++e) out->first[e + 1] += out->first[e];
  out->bind();
  return {};
}

InputError read_cut_file(const std::string& path, LoadedCut* out) {
  std::ifstream in(path);
  if (!in) return {path, 0, "cannot open"};
  return read_cut(in, path, out);
}

}  // namespace haloplot::host
