#include "io/cut_file.h"

#include <fstream>
#include <ostream>

#include "io/line_reader.h"
#include "io/substep_header.h"

namespace haloplot::host {

void LoadedCut::bind() {
  set.edges = edges.data();
  set.n_edges = static_cast<uint32_t>(edges.size());
  set.first = first.data();
  set.crossings = crossings.data();
  set.n_crossings = static_cast<uint32_t>(crossings.size());
}

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

namespace {

using i128 = __int128;

// Does a 'cross' record tell the truth? Edge p (BEHIND) and edge q (FRONT) must cross in the
// projection at p's parameter T (the floor of the exact t in Q0.32, as CUT writes it), with q
// nearer there. Exact: cross products of 21-bit differences, compared in 128 bits.
std::string check_cross(const Edge3& p, const Edge3& q, uint32_t t32) {
  const int64_t dpx = int64_t(p.b.x) - p.a.x, dpy = int64_t(p.b.y) - p.a.y;
  const int64_t dqx = int64_t(q.b.x) - q.a.x, dqy = int64_t(q.b.y) - q.a.y;
  const int64_t wx = int64_t(q.a.x) - p.a.x, wy = int64_t(q.a.y) - p.a.y;
  int64_t den = dpx * dqy - dpy * dqx;                         // cross(dp, dq)
  int64_t tn = wx * dqy - wy * dqx, un = wx * dpy - wy * dpx;  // t = tn/den, u = un/den
  if (den == 0) return "the two edges are parallel in the projection: they do not cross";
  if (den < 0) den = -den, tn = -tn, un = -un;
  if (tn < 0 || tn > den || un < 0 || un > den) return "the two edges do not cross";
  if (tn == den || ((i128(tn) << 32) / den) != i128(t32))
    return "T " + std::to_string(t32) + " is not where they cross (" +
           std::to_string(uint64_t((i128(tn) << 32) / den)) + ")";
  // Depths at the crossing, over den: q must be nearer (a larger z is nearer).
  const i128 zp = i128(p.a.z) * den + i128(int64_t(p.b.z) - p.a.z) * tn;
  const i128 zq = i128(q.a.z) * den + i128(int64_t(q.b.z) - q.a.z) * un;
  if (zq <= zp) return "FRONT is not in front of BEHIND where they cross";
  return "";
}

// X and Y as write_cut() writes them: an integer, a point and three decimals.
bool is_position(const std::string& s) {
  size_t i = s[0] == '-' ? 1 : 0;
  const size_t dot = s.find('.');
  if (dot == std::string::npos || dot == i || s.size() - dot != 4) return false;
  for (size_t k = i; k < s.size(); ++k)
    if (k != dot && (s[k] < '0' || s[k] > '9')) return false;
  return true;
}

// e INDEX AX AY AZ BX BY BZ: the next edge, in index order.
InputError read_edge_record(const std::vector<std::string>& f, const std::string& name, int line,
                            LoadedCut* out) {
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
  return {};
}

// c BEHIND FRONT X Y T KIND: a crossing, checked against the edges (X and Y where T lies on
// BEHIND, a 'cross' where the two really cross) and against the record before it (grouped by
// BEHIND, ordered along it). *near is set by a 'near' record.
InputError read_crossing_record(const std::vector<std::string>& f, const std::string& name,
                                int line, LoadedCut* out, bool* near) {
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
  if (f.size() != 7)
    return {name, line, "a 'c' line has 7 fields, not " + std::to_string(f.size())};
  for (int k : {3, 4})
    if (!is_position(f[k]))
      return {name, line,
              std::string(k == 3 ? "X" : "Y") + " '" + excerpt(f[k]) +
                  "' is not a position in steps with three decimals"};
  const Edge3& e = out->edges[size_t(behind)];
  if (f[3] != decimal_position(e.a.x, e.b.x - e.a.x, uint32_t(t)) ||
      f[4] != decimal_position(e.a.y, e.b.y - e.a.y, uint32_t(t)))
    return {name, line, "X Y " + f[3] + " " + f[4] + " is not where T " + f[5] + " lies on BEHIND"};
  if (f[6] == "cross") {
    const std::string why = check_cross(e, out->edges[size_t(front)], uint32_t(t));
    if (!why.empty()) return {name, line, why};
  } else {
    *near = true;
  }
  Crossing c{uint32_t(behind), uint32_t(front) | (f[6] == "near" ? Crossing::kNearBit : 0u),
             uint32_t(t)};
  if (!out->crossings.empty()) {
    const Crossing& p = out->crossings.back();
    const bool ordered = p.behind < c.behind ||
                         (p.behind == c.behind && (p.t < c.t || (p.t == c.t && p.front < c.front)));
    if (!ordered)
      return {name, line, "records must be grouped by BEHIND and ordered along it by (T, FRONT)"};
  }
  out->crossings.push_back(c);
  return {};
}

// The header: the format and its version first, then the reach the records were found with
// (which 'near' records need), and the sub-step units.
InputError read_cut_header(const std::string& comments, const std::string& name, bool near_records,
                           LoadedCut* out) {
  const std::string kHeader = "# haloplot cutset v";
  if (comments.compare(0, kHeader.size(), kHeader) != 0)
    return {name, 1, "not a haloplot CUTSET: the first line must be '# haloplot cutset v1'"};
  const std::string version = comments.substr(kHeader.size(), comments.find('\n') - kHeader.size());
  if (version != "1")
    return {name, 1, "CUTSET version '" + excerpt(version) + "' is not one this tool reads (v1)"};
  int64_t reach = 0;
  const size_t at = comments.find("# reach ");
  if (at != std::string::npos) {
    const std::string value = comments.substr(at + 8, comments.find('\n', at) - at - 8);
    if (!parse_int(value, 0, kCoordMax, &reach)) return {name, 0, "bad '# reach' header"};
  }
  if (near_records && reach == 0)
    return {name, 0,
            "'near' records with reach 0: near misses are only found within a reach "
            "(the '# reach R' header)"};
  out->set.reach = int32_t(reach);
  std::string why;
  if (!read_substep_header(comments, &out->substep_bits, &why)) return {name, 0, why};
  return {};
}

}  // namespace

InputError read_cut(std::istream& in, const std::string& name, LoadedCut* out) {
  *out = LoadedCut{};
  LineReader reader(in);
  std::vector<std::string> f;
  std::string comments;
  bool in_crossings = false, near_records = false;
  while (reader.next(&f, &comments)) {
    const int line = reader.line();
    InputError e;
    if (f[0] == "e") {
      if (in_crossings) return {name, line, "'e' line after the first 'c' line"};
      e = read_edge_record(f, name, line, out);
    } else if (f[0] == "c") {
      in_crossings = true;
      e = read_crossing_record(f, name, line, out, &near_records);
    } else {
      return {name, line, "unknown record '" + excerpt(f[0]) + "' (expected 'e' or 'c')"};
    }
    if (e.failed()) return e;
  }
  if (!reader.error().empty()) return {name, reader.line(), reader.error()};
  if (in.bad()) return {name, 0, "read error"};
  const InputError header = read_cut_header(comments, name, near_records, out);
  if (header.failed()) return header;
  // The crossings are grouped by the edge behind: each edge's first record.
  out->first.assign(out->edges.size() + 1, 0);
  for (const Crossing& c : out->crossings) ++out->first[c.behind + 1];
  for (size_t e = 0; e < out->edges.size(); ++e) out->first[e + 1] += out->first[e];
  out->bind();
  return {};
}

InputError read_cut_file(const std::string& path, LoadedCut* out) {
  std::ifstream in(path);
  if (const InputError e = open_problem(path, in); e.failed()) return e;
  return read_cut(in, path, out);
}

}  // namespace haloplot::host
