// The open sides' measure (host_sim/pipeline/open_sides.h) against brute force: every side's
// faces counted in a map, every pair of open corners asked for the nearest one sharing no face,
// the median side from all sides sorted. The weld hint on a split cube (each face its own
// corners, face k's moved by k * 13 units) suggests an EPS at least the spread of a corner's
// copies that closes it, and on the cube's faces far apart none. Where a shell cannot be
// oriented (mesh_repair.h, ShellProblem): a fin's side is on three faces by count and the named
// line is one of theirs; a Moebius strip's named side is run the same way by both its faces.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <vector>

#include "check.h"
#include "pipeline/mesh_repair.h"
#include "pipeline/open_sides.h"

namespace haloplot::host {
namespace {

double dist(const Point3& p, const Point3& q) {
  const double dx = double(p.x) - q.x, dy = double(p.y) - q.y, dz = double(p.z) - q.z;
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

void add_face(ObjModel* m, std::vector<uint32_t> c) {
  m->faces.push_back(std::move(c));
  m->face_lines.push_back(uint32_t(m->faces.size()) * 10);
}

// Random pieces: strips of triangles sharing sides, and loose triangles, some near each other.
ObjModel random_model(std::mt19937& rng) {
  ObjModel m;
  std::uniform_int_distribution<int32_t> at(-3000, 3000), step(-120, 120), count(1, 6);
  std::uniform_int_distribution<int32_t> near(-40, 40);
  Point3 o{0, 0, 0};
  for (int piece = 0; piece < 40; ++piece) {
    // Every other piece starts near the one before it: corners of other open sides nearby.
    o = piece % 2 ? Point3{o.x + near(rng), o.y + near(rng), o.z + near(rng)}
                  : Point3{at(rng), at(rng), at(rng)};
    const int n = count(rng);
    const uint32_t first = uint32_t(m.vertices.size());
    for (int k = 0; k < n + 2; ++k)
      m.vertices.push_back(
          Point3{o.x + k * 100 + step(rng), o.y + (k % 2) * 100 + step(rng), o.z + step(rng)});
    for (int k = 0; k < n; ++k) add_face(&m, {first + k, first + k + 1, first + k + 2});
  }
  return m;
}

void check_measure(const ObjModel& m) {
  std::map<std::pair<uint32_t, uint32_t>, int> sides;
  std::vector<double> lengths;
  for (const auto& c : m.faces)
    for (size_t i = 0; i < c.size(); ++i) {
      const uint32_t a = c[i], b = c[(i + 1) % c.size()];
      ++sides[{std::min(a, b), std::max(a, b)}];
      lengths.push_back(dist(m.vertices[a], m.vertices[b]));
    }
  std::sort(lengths.begin(), lengths.end());
  const double typical = lengths[lengths.size() / 2];
  std::set<uint32_t> open;
  uint32_t open_sides = 0, nonmanifold = 0;
  for (const auto& [s, n] : sides) {
    if (n == 1) open.insert(s.first), open.insert(s.second), ++open_sides;
    nonmanifold += n > 2;
  }
  auto share = [&](uint32_t v, uint32_t w) {
    for (const auto& c : m.faces)
      if (std::count(c.begin(), c.end(), v) && std::count(c.begin(), c.end(), w)) return true;
    return false;
  };
  const double reach = std::max(1.0, typical / 2);
  std::vector<double> gaps;
  for (uint32_t v : open) {
    double best = -1;
    for (uint32_t w : open) {
      const double d = dist(m.vertices[v], m.vertices[w]);
      if (w == v || d > reach || share(v, w)) continue;
      if (best < 0 || d < best) best = d;
    }
    if (best >= 0) gaps.push_back(best);
  }
  std::sort(gaps.begin(), gaps.end());
  const OpenSides got = measure_open_sides(m);
  CHECK_EQ(got.sides, open_sides);
  CHECK_EQ(got.nonmanifold_sides, nonmanifold);
  CHECK_EQ(got.corners, uint32_t(open.size()));
  CHECK_EQ(got.typical_side, typical);
  CHECK(got.gaps == gaps);
  CHECK(!gaps.empty());  // something to compare
}

// A cube of side 1000 whose face k has its own four corners, moved by k * shift in x.
ObjModel split_cube(int32_t shift) {
  ObjModel m;
  for (uint32_t k = 0; k < 6; ++k) {
    const int32_t axis = int32_t(k / 2), side = int32_t(k % 2) * 1000;
    for (int c = 0; c < 4; ++c) {
      const int32_t u = (c == 1 || c == 2) ? 1000 : 0, w = c >= 2 ? 1000 : 0;
      Point3 p = axis == 0   ? Point3{side, u, w}
                 : axis == 1 ? Point3{u, side, w}
                             : Point3{u, w, side};
      p.x += int32_t(k) * shift;
      m.vertices.push_back(p);
    }
    add_face(&m, {4 * k, 4 * k + 1, 4 * k + 2, 4 * k + 3});
  }
  return m;
}

void check_split_cube() {
  ObjModel m = split_cube(13);
  // What a weld must join: the largest spread in x of one cube corner's copies.
  std::map<std::pair<int32_t, int32_t>, std::pair<int32_t, int32_t>> spread;  // (y, z, x/1000)
  double need = 0;
  for (const Point3& p : m.vertices) {
    const int32_t corner_x = (p.x + 500) / 1000;
    auto [it, fresh] = spread.insert({{p.y + 2000 * corner_x, p.z}, {p.x, p.x}});
    if (!fresh) it->second = {std::min(it->second.first, p.x), std::max(it->second.second, p.x)};
    need = std::max(need, double(it->second.second - it->second.first));
  }
  CHECK_EQ(need, 65.0);
  RepairReport r;
  orient_shells(&m, &r);
  const WeldHint h = weld_hint(m, measure_open_sides(m));
  CHECK(h.gaps && h.suggest);
  CHECK(h.eps >= need && h.eps < 1000 / kGapBelowSide);
  CHECK_EQ(h.before.open_sides, 24u);
  CHECK_EQ(h.after.open_sides, 0u);
  CHECK_EQ(h.after.closed_shells, 1u);
  CHECK(try_weld(m, need - 1).open_sides > 0);  // below the spread some copies stay apart
  // Faces 200 apart: no gap scale (the cube's side is 1000), nothing suggested.
  ObjModel far = split_cube(200);
  const WeldHint f = weld_hint(far, measure_open_sides(far));
  CHECK(!f.gaps && !f.suggest && f.near == 0);
}

// The faces running side a -> b or b -> a (by position), and which way.
std::vector<std::pair<uint32_t, bool>> faces_on(const ObjModel& m, const double from[3],
                                                const double to[3]) {
  auto is = [&](uint32_t v, const double p[3]) {
    const Point3& q = m.vertices[v];
    return q.x == p[0] && q.y == p[1] && q.z == p[2];
  };
  std::vector<std::pair<uint32_t, bool>> out;
  for (uint32_t f = 0; f < m.faces.size(); ++f) {
    const auto& c = m.faces[f];
    for (size_t i = 0; i < c.size(); ++i) {
      const uint32_t a = c[i], b = c[(i + 1) % c.size()];
      if (is(a, from) && is(b, to)) out.push_back({f, true});
      if (is(a, to) && is(b, from)) out.push_back({f, false});
    }
  }
  return out;
}

// Orients `m` and checks that its one unorientable shell's problem side is on `faces` faces,
// as the model has them: those faces, with whether each runs the side from `from` to `to`.
auto located_problem(ObjModel* m, uint32_t faces, RepairReport* r) {
  orient_shells(m, r);
  CHECK_EQ(r->unorientable_shells, 1u);
  CHECK_EQ(r->problem.faces_on_side, faces);
  const auto on = faces_on(*m, r->problem.from, r->problem.to);
  CHECK_EQ(on.size(), size_t(faces));
  return on;
}

void check_problems() {
  // A tetrahedron and a fin on its side 0 -> 1 (scale 1, centre 0: file = world).
  ObjModel fin;
  fin.vertices = {{0, 0, 0}, {100, 0, 0}, {0, 100, 0}, {0, 0, 100}, {50, -100, 50}};
  for (const std::vector<uint32_t>& c :
       std::vector<std::vector<uint32_t>>{{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 4, 1}})
    add_face(&fin, c);
  RepairReport r;
  const auto on = located_problem(&fin, 3, &r);
  bool line_on_side = false;
  for (const auto& [f, up] : on) line_on_side = line_on_side || fin.face_lines[f] == r.problem.line;
  CHECK(line_on_side);
  // A Moebius strip of 12 quads: its twist's side is run the same way by both its faces.
  ObjModel strip;
  const double pi = 3.14159265358979323846;
  const int n = 12;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * pi * i / n, p = pi * i / n;
    const double cx = 1000 * std::cos(t), cy = 1000 * std::sin(t);
    const double ox = 300 * std::cos(p) * std::cos(t), oy = 300 * std::cos(p) * std::sin(t),
                 oz = 300 * std::sin(p);
    strip.vertices.push_back(Point3{int32_t(std::lround(cx + ox)), int32_t(std::lround(cy + oy)),
                                    int32_t(std::lround(oz))});
    strip.vertices.push_back(Point3{int32_t(std::lround(cx - ox)), int32_t(std::lround(cy - oy)),
                                    int32_t(std::lround(-oz))});
  }
  for (uint32_t i = 0; i + 1 < n; ++i) add_face(&strip, {2 * i, 2 * i + 1, 2 * i + 3, 2 * i + 2});
  add_face(&strip, {2 * n - 2, 2 * n - 1, 0, 1});
  RepairReport s;
  const auto twist = located_problem(&strip, 2, &s);
  CHECK(twist.size() == 2 && twist[0].second == twist[1].second);
  CHECK(twist.size() == 2 && (strip.face_lines[twist[0].first] == s.problem.line ||
                              strip.face_lines[twist[1].first] == s.problem.line));
}

}  // namespace
}  // namespace haloplot::host

int main() {
  std::mt19937 rng(48);
  for (int round = 0; round < 10; ++round)
    haloplot::host::check_measure(haloplot::host::random_model(rng));
  haloplot::host::check_split_cube();
  haloplot::host::check_problems();
  return check::finish("open_sides");
}
