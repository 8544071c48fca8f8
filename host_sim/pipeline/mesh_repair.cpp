#include "pipeline/mesh_repair.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>
#include <utility>

#include "io/pair_set.h"

namespace haloplot::host {
namespace {

// A vertex's cell: its coordinates' quotients by the cell's side (rounded toward zero, so the
// cells next to 0 are wider), compared in (x, y, z) order. Moving every cell by one offset
// keeps that order: the neighbours in one direction of cells in order come in order.
struct CellPos {
  int64_t x, y, z;
  bool operator<(const CellPos& o) const {
    return x != o.x ? x < o.x : y != o.y ? y < o.y : z < o.z;
  }
  bool operator==(const CellPos& o) const { return x == o.x && y == o.y && z == o.z; }
};

// Where a vertex may be welded to: an earlier vertex within the tolerance. `rank` is the
// order the search of weld_map below meets it in: the neighbouring cells in (dx, dy, dz) order
// (the earlier vertex's cell less the later one's), each cell's vertices in file order.
struct WeldCandidate {
  uint32_t later, rank, earlier;
  bool operator<(const WeldCandidate& o) const {
    return later != o.later ? later < o.later
           : rank != o.rank ? rank < o.rank
                            : earlier < o.earlier;
  }
};

// Every pair of vertices within `tolerance` whose cells are at most `reach` apart in each
// axis, as a candidate of the later one: the vertices sorted by cell, and each cell's
// vertices paired with its own and with those of the 13 neighbours after it in key order (a
// pointer per neighbour direction, moving forward with the cell). Each pair of cells is met
// once; a clean mesh has few pairs.
std::vector<WeldCandidate> close_pairs(const std::vector<Point3>& v, int64_t cell, int64_t reach,
                                       double tolerance) {
  struct Entry {
    CellPos key;
    uint32_t vertex;
  };
  std::vector<Entry> e(v.size());
  for (uint32_t i = 0; i < v.size(); ++i)
    e[i] = Entry{CellPos{v[i].x / cell, v[i].y / cell, v[i].z / cell}, i};
  std::sort(e.begin(), e.end(), [](const Entry& a, const Entry& b) {
    return a.key == b.key ? a.vertex < b.vertex : a.key < b.key;
  });
  std::vector<uint32_t> first;  // the cells: entries [first[c], first[c + 1])
  for (uint32_t i = 0; i < e.size(); ++i)
    if (i == 0 || !(e[i].key == e[i - 1].key)) first.push_back(i);
  const uint32_t cells = uint32_t(first.size());
  first.push_back(uint32_t(e.size()));
  const double tol2 = tolerance * tolerance;
  std::vector<WeldCandidate> out;
  // Vertices a (cell A) and b (cell B, B - A = d): a candidate of the later one.
  auto pair = [&](uint32_t a, uint32_t b, int64_t dx, int64_t dy, int64_t dz) {
    const double ex = double(v[b].x) - v[a].x, ey = double(v[b].y) - v[a].y,
                 ez = double(v[b].z) - v[a].z;
    if (ex * ex + ey * ey + ez * ez > tol2) return;
    if (a < b)  // b is later: its cell less a's is -d
      out.push_back({b, uint32_t((1 - dx) * 9 + (1 - dy) * 3 + (1 - dz)), a});
    else
      out.push_back({a, uint32_t((1 + dx) * 9 + (1 + dy) * 3 + (1 + dz)), b});
  };
  struct Direction {
    int64_t dx, dy, dz;
    uint32_t at;  // the first cell not before this cell moved by (dx, dy, dz)
  };
  std::vector<Direction> forward;
  for (int64_t dx = -reach; dx <= reach; ++dx)
    for (int64_t dy = -reach; dy <= reach; ++dy)
      for (int64_t dz = -reach; dz <= reach; ++dz)
        if (std::make_tuple(dx, dy, dz) > std::make_tuple(0, 0, 0))
          forward.push_back({dx, dy, dz, 0});
  for (uint32_t c = 0; c < cells; ++c) {
    const CellPos key = e[first[c]].key;
    for (uint32_t i = first[c]; i < first[c + 1]; ++i)
      for (uint32_t j = i + 1; j < first[c + 1]; ++j) pair(e[i].vertex, e[j].vertex, 0, 0, 0);
    for (Direction& d : forward) {
      const CellPos want{key.x + d.dx, key.y + d.dy, key.z + d.dz};
      while (d.at < cells && e[first[d.at]].key < want) ++d.at;
      if (d.at == cells || !(e[first[d.at]].key == want)) continue;
      for (uint32_t i = first[c]; i < first[c + 1]; ++i)
        for (uint32_t j = first[d.at]; j < first[d.at + 1]; ++j)
          pair(e[i].vertex, e[j].vertex, d.dx, d.dy, d.dz);
    }
  }
  return out;
}

// For each vertex, the vertex it becomes: the first kept one at its place (in the order the
// cells around it are searched: (dx, dy, dz) from -1 to 1, each cell's vertices in file order)
// or itself. Decided in file order, so a candidate counts only when it was kept itself.
std::vector<uint32_t> weld_map(const std::vector<Point3>& v, double tolerance) {
  std::vector<uint32_t> to(v.size());
  const int64_t cell = std::max<int64_t>(1, int64_t(std::ceil(tolerance)));
  std::vector<WeldCandidate> near = close_pairs(v, cell, tolerance > 0 ? 1 : 0, tolerance);
  std::sort(near.begin(), near.end());
  size_t k = 0;
  for (uint32_t i = 0; i < v.size(); ++i) {
    to[i] = i;
    for (; k < near.size() && near[k].later == i; ++k)
      if (to[i] == i && to[near[k].earlier] == near[k].earlier) to[i] = near[k].earlier;
  }
  return to;
}

// A face's corners after welding, read as a closed walk, reduced to the walk's outline: a
// corner the same as the one before it adds nothing, and a corner between two of one vertex
// (a, b, a) is a spike of no area, the walk out to b and straight back. Welding a small quad's
// opposite corners leaves a, b, a, c: no area at all, and a face running sides a-b and a-c
// both ways, which the orientation would take for a side on three or more faces and call the
// whole shell one that cannot be oriented (the hidden lines, which drop faces of no area, found
// it a closed solid). Corners keep their order; the first kept one comes first. Returns the
// corners left (c is cut to them).
size_t reduce_corners(std::vector<uint32_t>* corners) {
  std::vector<uint32_t>& c = *corners;
  size_t n = 0;  // a stack: each corner written at or before where it was read
  for (size_t i = 0; i < c.size(); ++i) {
    const uint32_t v = c[i];
    if (n > 0 && c[n - 1] == v) continue;
    if (n > 1 && c[n - 2] == v) {  // the top was a spike
      --n;
      continue;
    }
    c[n++] = v;
  }
  size_t s = 0;  // where the end meets the start
  for (bool changed = true; changed && n - s >= 2;) {
    changed = true;
    if (c[n - 1] == c[s])
      --n;  // the last repeats the first
    else if (n - s >= 3 && c[n - 2] == c[s])
      --n;  // the last is a spike
    else if (n - s >= 3 && c[n - 1] == c[s + 1])
      ++s;  // the first is a spike
    else
      changed = false;
  }
  c.erase(c.begin() + std::ptrdiff_t(n), c.end());
  c.erase(c.begin(), c.begin() + std::ptrdiff_t(s));
  return c.size();
}

}  // namespace

void weld_vertices(ObjModel* model, double tolerance, RepairReport* report) {
  const std::vector<uint32_t> to = weld_map(model->vertices, tolerance);
  std::vector<uint32_t> index(to.size());
  uint32_t kept = 0;
  for (uint32_t i = 0; i < to.size(); ++i) {
    if (to[i] == i) {
      index[i] = kept;
      model->vertices[kept++] = model->vertices[i];  // kept < i or kept == i: moves down
    } else {
      index[i] = index[to[i]];
      ++report->merged_vertices;
    }
  }
  model->vertices.resize(kept);
  // Faces renumbered in place and reduced; those left with fewer than three corners dropped
  // (the rest move down, with their lines).
  size_t out = 0, out_lines = 0;
  const size_t n_lines = model->face_lines.size();  // the first faces' lines (all, or none)
  for (size_t f = 0; f < model->faces.size(); ++f) {
    std::vector<uint32_t>& c = model->faces[f];
    for (uint32_t& v : c) v = index[v];
    const size_t n = reduce_corners(&c);
    if (n < 3) {
      ++report->dropped_faces;
      continue;
    }
    if (f < n_lines) model->face_lines[out_lines++] = model->face_lines[f];
    if (out != f) model->faces[out] = std::move(c);
    ++out;
  }
  model->faces.resize(out);
  model->face_lines.resize(out_lines);
  std::vector<uint32_t> edges;
  edges.reserve(model->edge_pairs.size());
  PairSet seen;
  for (size_t e = 0; e + 1 < model->edge_pairs.size(); e += 2) {
    const uint32_t a = index[model->edge_pairs[e]], b = index[model->edge_pairs[e + 1]];
    if (a == b || !seen.insert(pair_key(a, b))) continue;
    edges.push_back(a);
    edges.push_back(b);
  }
  model->edge_pairs = std::move(edges);
}

namespace {

// Each face's sides listed under their lesser vertex, in face order: the faces on side {a, b}
// are the entries of min(a, b) naming max(a, b). A few entries per vertex, in two passes over
// the faces (sorting or hashing every side cost more, most of it in page faults).
struct SidesByVertex {
  struct Entry {
    uint32_t other, face;
    bool up;  // the face runs the side from the lesser vertex to the greater
  };
  std::vector<uint32_t> first;  // vertex v's entries: [first[v], first[v + 1])
  std::vector<Entry> entry;

  explicit SidesByVertex(const ObjModel& m) : first(m.vertices.size() + 1, 0) {
    for_each_side(m, [&](uint32_t a, uint32_t b, uint32_t) { ++first[std::min(a, b) + 1]; });
    for (size_t v = 0; v + 1 < first.size(); ++v) first[v + 1] += first[v];
    entry.resize(first.back());
    std::vector<uint32_t> fill(first.begin(), first.end() - 1);
    for_each_side(m, [&](uint32_t a, uint32_t b, uint32_t f) {
      entry[fill[std::min(a, b)]++] = Entry{std::max(a, b), f, a < b};
    });
  }
  template <typename Fn>
  static void for_each_side(const ObjModel& m, Fn fn) {
    for (uint32_t f = 0; f < m.faces.size(); ++f) {
      const std::vector<uint32_t>& c = m.faces[f];
      for (size_t i = 0; i < c.size(); ++i) fn(c[i], c[(i + 1) % c.size()], f);
    }
  }
  // Each vertex's entries by the other vertex, stably (the faces stay in order): every side's
  // entries together, the sides in key order, each one's faces in order.
  void sort_each() {
    for (size_t v = 0; v + 1 < first.size(); ++v)
      std::stable_sort(entry.begin() + first[v], entry.begin() + first[v + 1],
                       [](const Entry& x, const Entry& y) { return x.other < y.other; });
  }
  // How many faces side {a, b} is on (each face once), and the first two.
  uint32_t faces(uint32_t a, uint32_t b, uint32_t face[2]) const {
    const uint32_t lo = std::min(a, b), hi = std::max(a, b);
    uint32_t n = 0;
    for (uint32_t k = first[lo]; k < first[lo + 1]; ++k) {
      if (entry[k].other != hi || (n > 0 && entry[k].face == face[n < 2 ? n - 1 : 1])) continue;
      if (n < 2) face[n] = entry[k].face;
      ++n;
    }
    return n;
  }
};

// The faces next to each face: neighbour, and whether it must be flipped relative to this
// face (0, 1), or 2 across a side on three or more faces (no constraint: the shell cannot be
// oriented).
struct Adjacency {
  std::vector<uint32_t> first;  // face f's neighbours are [first[f], first[f + 1])
  std::vector<std::pair<uint32_t, uint8_t>> next;
  std::vector<uint8_t> on_boundary, on_nonmanifold;  // per face
};

Adjacency adjacency(const ObjModel& m) {
  SidesByVertex sides(m);
  sides.sort_each();  // the sides in key order, each one's faces in order
  Adjacency adj;
  adj.on_boundary.assign(m.faces.size(), 0);
  adj.on_nonmanifold.assign(m.faces.size(), 0);
  // Every link (face, neighbour, constraint) in one order, met twice: counted, then placed.
  // (A list of them, sorted into place after, was the plot's peak on a 1.1M-triangle export:
  // 27 MB beside the sides and the neighbours.)
  auto for_each_link = [&](auto link) {
    for (uint32_t v = 0; v + 1 < sides.first.size(); ++v) {
      const SidesByVertex::Entry* e = sides.entry.data() + sides.first[v];
      const size_t k = sides.first[v + 1] - sides.first[v];
      for (size_t i = 0, j = 0; i < k; i = j) {
        while (j < k && e[j].other == e[i].other) ++j;
        if (e[i].other == v) continue;  // a side from a vertex to itself joins nothing
        for (size_t p = i; p < j; ++p)
          for (size_t q = i; q < j; ++q) {
            if (e[p].face == e[q].face) continue;
            // Two faces on one side agree when they run it opposite ways.
            const uint32_t c = j - i > 2 ? 2u : e[p].up == e[q].up ? 1u : 0u;
            link(e[p].face, e[q].face, c);
          }
        if (j - i == 1) adj.on_boundary[e[i].face] = 1;
        if (j - i > 2)
          for (size_t q = i; q < j; ++q) adj.on_nonmanifold[e[q].face] = 1;
      }
    }
  };
  adj.first.assign(m.faces.size() + 1, 0);
  for_each_link([&](uint32_t f, uint32_t, uint32_t) { ++adj.first[f + 1]; });
  for (size_t f = 0; f < m.faces.size(); ++f) adj.first[f + 1] += adj.first[f];
  adj.next.resize(adj.first.back());
  std::vector<uint32_t> fill(adj.first.begin(), adj.first.end() - 1);
  for_each_link([&](uint32_t f, uint32_t n, uint32_t c) { adj.next[fill[f]++] = {n, uint8_t(c)}; });
  return adj;
}

// Six times the signed volume the faces enclose (each face fanned from its first corner).
__int128 volume6(const ObjModel& m, const std::vector<uint32_t>& faces,
                 const std::vector<uint8_t>& flip) {
  __int128 sum = 0;
  for (uint32_t f : faces) {
    const std::vector<uint32_t>& c = m.faces[f];
    const Point3& a = m.vertices[c[0]];
    for (size_t i = 1; i + 1 < c.size(); ++i) {
      const Point3& p = m.vertices[c[i]];
      const Point3& q = m.vertices[c[i + 1]];
      const __int128 det = __int128(a.x) * (int64_t(p.y) * q.z - int64_t(p.z) * q.y) -
                           __int128(a.y) * (int64_t(p.x) * q.z - int64_t(p.z) * q.x) +
                           __int128(a.z) * (int64_t(p.x) * q.y - int64_t(p.y) * q.x);
      sum += flip[f] ? -det : det;
    }
  }
  return sum;
}

// Does face c run from corner a straight to corner b?
bool runs(const std::vector<uint32_t>& c, uint32_t a, uint32_t b) {
  for (size_t i = 0; i < c.size(); ++i)
    if (c[i] == a && c[(i + 1) % c.size()] == b) return true;
  return false;
}

struct Shell {
  std::vector<uint32_t> faces;
  bool closed = true, orientable = true;
};

// Breadth first from `seed`: the shell's faces and each one's flip (relative to the seed).
Shell grow_shell(const Adjacency& adj, uint32_t seed, std::vector<uint8_t>* seen,
                 std::vector<uint8_t>* flip) {
  Shell s;
  s.faces.push_back(seed);
  (*seen)[seed] = 1;
  (*flip)[seed] = 0;
  for (size_t at = 0; at < s.faces.size(); ++at) {
    const uint32_t f = s.faces[at];
    s.closed = s.closed && !adj.on_boundary[f] && !adj.on_nonmanifold[f];
    s.orientable = s.orientable && !adj.on_nonmanifold[f];
    for (uint32_t k = adj.first[f]; k < adj.first[f + 1]; ++k) {
      const uint32_t n = adj.next[k].first, c = adj.next[k].second;
      const uint8_t want = c == 2 ? 0 : uint8_t((*flip)[f] ^ c);
      if (!(*seen)[n]) {
        (*seen)[n] = 1;
        (*flip)[n] = want;
        s.faces.push_back(n);
      } else if (c != 2 && (*flip)[n] != want) {
        s.orientable = false;  // a twist: the two ways round disagree
      }
    }
  }
  return s;
}

// The side a -> b of face f (its i-th) in the problem's terms: file coordinates and f's line.
ShellProblem problem_at(const ObjModel& m, uint32_t f, size_t i, uint32_t faces_on_side) {
  ShellProblem p;
  p.faces_on_side = faces_on_side;
  p.line = f < m.face_lines.size() ? m.face_lines[f] : 0;
  p.unit = 1 / m.scale;
  const std::vector<uint32_t>& c = m.faces[f];
  const Point3& a = m.vertices[c[i]];
  const Point3& b = m.vertices[c[(i + 1) % c.size()]];
  const double wa[3] = {double(a.x), double(a.y), double(a.z)};
  const double wb[3] = {double(b.x), double(b.y), double(b.z)};
  for (int k = 0; k < 3; ++k) {
    p.from[k] = wa[k] / m.scale + m.centre[k];
    p.to[k] = wb[k] / m.scale + m.centre[k];
  }
  return p;
}

// Where shell s cannot be oriented: its first face (in the search's order) on a side on three
// or more faces, that side; else the first side its two faces run the same way as the file
// gives them. A shell whose every side is run both ways could be oriented as given, so a twist
// leaves at least one such side; where the file is wound consistently but for a seam, it is
// the seam (where the search's two ways round met is anywhere on the strip).
ShellProblem shell_problem(const ObjModel& m, const Adjacency& adj, const Shell& s) {
  SidesByVertex sides(m);
  sides.sort_each();
  for (int pass = 0; pass < 2; ++pass)
    for (uint32_t f : s.faces) {
      if (pass == 0 && !adj.on_nonmanifold[f]) continue;
      const std::vector<uint32_t>& c = m.faces[f];
      for (size_t i = 0; i < c.size(); ++i) {
        const uint32_t a = c[i], b = c[(i + 1) % c.size()];
        uint32_t face[2] = {0, 0};
        const uint32_t n = sides.faces(a, b, face);
        if (pass == 0 && n > 2) return problem_at(m, f, i, n);
        if (pass == 1 && n == 2 && runs(m.faces[face[0]], a, b) == runs(m.faces[face[1]], a, b))
          return problem_at(m, f, i, 2);
      }
    }
  return problem_at(m, s.faces[0], 0, 2);  // not reached (see above)
}

}  // namespace

void orient_shells(ObjModel* model, RepairReport* report) {
  const Adjacency adj = adjacency(*model);
  std::vector<uint8_t> seen(model->faces.size(), 0), flip(model->faces.size(), 0);
  for (uint32_t seed = 0; seed < model->faces.size(); ++seed) {
    if (seen[seed]) continue;
    Shell s = grow_shell(adj, seed, &seen, &flip);
    ++report->shells;
    if (!s.orientable) {
      if (report->problem.faces_on_side == 0) report->problem = shell_problem(*model, adj, s);
      ++report->unorientable_shells;
      for (uint32_t f : s.faces) flip[f] = 0;  // left as given
      continue;
    }
    size_t flipped = 0;
    for (uint32_t f : s.faces) flipped += flip[f];
    bool invert = 2 * flipped > s.faces.size();  // open: most faces keep their winding
    if (s.closed) {
      ++report->closed_shells;
      invert = volume6(*model, s.faces, flip) < 0;
    }
    for (uint32_t f : s.faces) {
      flip[f] = uint8_t(flip[f] ^ (invert ? 1 : 0));
      if (!flip[f]) continue;
      ++report->flipped_faces;
      std::vector<uint32_t>& c = model->faces[f];
      std::reverse(c.begin() + 1, c.end());  // the same first corner, the other way round
    }
    if (s.closed && invert) ++report->turned_shells;
  }
}

namespace {

using Normal = std::array<__int128, 3>;

// Newell's normal: twice the area vector, exact for a planar polygon on integer vertices.
Normal newell(const ObjModel& m, const std::vector<uint32_t>& c) {
  Normal n = {0, 0, 0};
  for (size_t i = 0; i < c.size(); ++i) {
    const Point3& a = m.vertices[c[i]];
    const Point3& b = m.vertices[c[(i + 1) % c.size()]];
    n[0] += __int128(int64_t(a.y) - b.y) * (int64_t(a.z) + b.z);
    n[1] += __int128(int64_t(a.z) - b.z) * (int64_t(a.x) + b.x);
    n[2] += __int128(int64_t(a.x) - b.x) * (int64_t(a.y) + b.y);
  }
  return n;
}

bool planar(const ObjModel& m, const std::vector<uint32_t>& c, const Normal& n) {
  const Point3& o = m.vertices[c[0]];
  for (uint32_t v : c) {
    const Point3& p = m.vertices[v];
    if (n[0] * (int64_t(p.x) - o.x) + n[1] * (int64_t(p.y) - o.y) + n[2] * (int64_t(p.z) - o.z) !=
        0)
      return false;
  }
  return true;
}

bool is_zero(const Normal& n) { return n[0] == 0 && n[1] == 0 && n[2] == 0; }

double length(const Normal& n) {
  return std::sqrt(double(n[0]) * double(n[0]) + double(n[1]) * double(n[1]) +
                   double(n[2]) * double(n[2]));
}

double distance(const Point3& p, const Point3& q) {
  const double dx = double(p.x) - q.x, dy = double(p.y) - q.y, dz = double(p.z) - q.z;
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// A face's normal and what rounding can do to it (mesh_repair.h, drop_flat_edges).
struct FaceShape {
  Normal n = {0, 0, 0};
  double length = 0;      // |n|
  double normal_off = 0;  // E = sqrt(3) d D + 9 k d^2: how far n may be from the true normal
};

FaceShape face_shape(const ObjModel& m, const std::vector<uint32_t>& c, double d) {
  FaceShape s;
  s.n = newell(m, c);
  s.length = length(s.n);
  double around = 0;  // D: the sum of |v[i+1] - v[i-1]|
  const size_t k = c.size();
  for (size_t i = 0; i < k; ++i)
    around += distance(m.vertices[c[(i + 1) % k]], m.vertices[c[(i + k - 1) % k]]);
  s.normal_off = std::sqrt(3.0) * d * around + 9.0 * double(k) * d * d;
  return s;
}

// Every corner of `other` within what rounding d can produce of the plane of face f through a.
bool corners_near_plane(const ObjModel& m, const FaceShape& f, const std::vector<uint32_t>& other,
                        const Point3& a, double d) {
  const double r3 = std::sqrt(3.0) * d;
  for (uint32_t v : other) {
    const Point3& p = m.vertices[v];
    const __int128 s = f.n[0] * (int64_t(p.x) - a.x) + f.n[1] * (int64_t(p.y) - a.y) +
                       f.n[2] * (int64_t(p.z) - a.z);
    const double bound = 2 * r3 * f.length + f.normal_off * (distance(p, a) + 6 * r3);
    if (std::fabs(double(s)) > bound) return false;
  }
  return true;
}

bool within_angle(const Normal& a, const Normal& b, double deg) {
  const double dot =
      double(a[0]) * double(b[0]) + double(a[1]) * double(b[1]) + double(a[2]) * double(b[2]);
  return dot > std::cos(deg * 3.14159265358979323846 / 180) * length(a) * length(b);
}

// Face g's normal as seen from face f across side a -> b: turned over where the two are wound
// the same way along it (a shell that cannot be oriented, like a Moebius strip's seam).
Normal normal_across(const ObjModel& m, const std::vector<FaceShape>& shape, uint32_t f, uint32_t g,
                     uint32_t a, uint32_t b) {
  const Normal& given = shape[g].n;
  const bool turned = runs(m.faces[f], a, b) == runs(m.faces[g], a, b);
  return turned ? Normal{-given[0], -given[1], -given[2]} : given;
}

// Do faces f and g, on the side a -> b, bend less than kGentleDegrees?
bool gentle_between(const ObjModel& m, const std::vector<FaceShape>& shape, uint32_t f, uint32_t g,
                    uint32_t a, uint32_t b) {
  const Normal& nf = shape[f].n;
  const Normal ng = normal_across(m, shape, f, g, a, b);
  return !is_zero(nf) && !is_zero(ng) && within_angle(nf, ng, kGentleDegrees);
}

// Do faces f and g, on the side a -> b, count as one flat surface? Two faces wound the same way
// along their side (a shell that cannot be oriented, like a Moebius strip's seam) are compared
// as if one were turned over: how a surface bends does not depend on how its faces are wound.
bool flat_between(const ObjModel& m, const std::vector<FaceShape>& shape, uint32_t f, uint32_t g,
                  uint32_t a, uint32_t b, const CreaseRule& rule) {
  const Normal& nf = shape[f].n;
  const Normal ng = normal_across(m, shape, f, g, a, b);
  if (is_zero(nf) || is_zero(ng)) return false;
  if (rule.deg > 0 && within_angle(nf, ng, rule.deg)) return true;  // as wide as asked
  // Each normal component is below 2^62 (vertices within 2^20), so the products fit.
  const __int128 dot = nf[0] * ng[0] + nf[1] * ng[1] + nf[2] * ng[2];
  if (dot <= 0) return false;  // at 90 degrees or more apart: not the same way
  if (rule.rounding > 0)
    return corners_near_plane(m, shape[f], m.faces[g], m.vertices[a], rule.rounding) &&
           corners_near_plane(m, shape[g], m.faces[f], m.vertices[a], rule.rounding);
  // Exactly: both planar, normals parallel and the same way (then, sharing a side, one plane).
  const __int128 cx = nf[1] * ng[2] - nf[2] * ng[1];
  const __int128 cy = nf[2] * ng[0] - nf[0] * ng[2];
  const __int128 cz = nf[0] * ng[1] - nf[1] * ng[0];
  return cx == 0 && cy == 0 && cz == 0 && planar(m, m.faces[f], nf) && planar(m, m.faces[g], ng);
}

}  // namespace

double vertex_rounding(const ObjModel& model) { return 0.5 + model.rounding * model.scale; }

double weld_distance(const ObjModel& model) { return 2 * std::sqrt(3.0) * vertex_rounding(model); }

void drop_flat_edges(ObjModel* model, const CreaseRule& rule, RepairReport* report) {
  if (rule.keep_all) return;
  const SidesByVertex sides(*model);
  std::vector<FaceShape> shape;
  shape.reserve(model->faces.size());
  for (const std::vector<uint32_t>& c : model->faces)
    shape.push_back(face_shape(*model, c, rule.rounding));
  std::vector<uint32_t> kept;
  kept.reserve(model->edge_pairs.size());
  for (size_t e = 0; e + 1 < model->edge_pairs.size(); e += 2) {
    const uint32_t a = model->edge_pairs[e], b = model->edge_pairs[e + 1];
    uint32_t face[2] = {0, 0};
    const bool two = sides.faces(a, b, face) == 2;
    if (two && flat_between(*model, shape, face[0], face[1], a, b, rule)) {
      ++report->flat_edges;
      CreaseRule flat_only = rule;
      flat_only.deg = 0;
      if (rule.deg > 0 && !flat_between(*model, shape, face[0], face[1], a, b, flat_only))
        ++report->bent_edges;
      continue;
    }
    if (two && rule.deg == 0 && gentle_between(*model, shape, face[0], face[1], a, b))
      ++report->gentle_edges;
    kept.insert(kept.end(), {a, b});
  }
  model->edge_pairs = kept;
  report->kept_edges = uint32_t(kept.size() / 2);
}

void find_regions(ObjModel* model) {
  const SidesByVertex sides(*model);
  std::vector<std::pair<uint32_t, uint32_t>> drawn;  // each drawn edge, lesser vertex first
  drawn.reserve(model->edge_pairs.size() / 2);
  for (size_t e = 0; e + 1 < model->edge_pairs.size(); e += 2)
    drawn.emplace_back(std::min(model->edge_pairs[e], model->edge_pairs[e + 1]),
                       std::max(model->edge_pairs[e], model->edge_pairs[e + 1]));
  std::sort(drawn.begin(), drawn.end());
  // Union-find whose root is the region's first face, so the id does not depend on the order
  // the sides are met in.
  std::vector<uint32_t>& up = model->face_region;
  up.resize(model->faces.size());
  for (uint32_t f = 0; f < up.size(); ++f) up[f] = f;
  auto root = [&](uint32_t f) {
    while (up[f] != f) f = up[f] = up[up[f]];
    return f;
  };
  for (uint32_t f = 0; f < model->faces.size(); ++f) {
    const std::vector<uint32_t>& c = model->faces[f];
    for (size_t i = 0; i < c.size(); ++i) {
      const uint32_t a = c[i], b = c[(i + 1) % c.size()];
      uint32_t face[2] = {0, 0};
      if (sides.faces(a, b, face) != 2) continue;
      const uint32_t g = face[0] == f ? face[1] : face[0];
      if (g <= f) continue;  // each side once, from its lesser face
      const uint32_t rf = root(f), rg = root(g);
      if (rf == rg || std::binary_search(drawn.begin(), drawn.end(),
                                         std::make_pair(std::min(a, b), std::max(a, b))))
        continue;
      up[std::max(rf, rg)] = std::min(rf, rg);
    }
  }
  for (uint32_t f = 0; f < up.size(); ++f) up[f] = root(f);
}

}  // namespace haloplot::host
