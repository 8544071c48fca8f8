#include "pipeline/mesh_repair.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <utility>

#include "io/pair_set.h"

namespace haloplot::host {
namespace {

// Integer world coordinates (within +-2^20) packed into one key.
uint64_t position_key(int64_t x, int64_t y, int64_t z) {
  const int64_t off = int64_t(1) << 21;
  return uint64_t(x + off) << 44 | uint64_t(y + off) << 22 | uint64_t(z + off);
}

// For each vertex, the vertex it becomes (the first kept one at its place, or itself).
std::vector<uint32_t> weld_map(const std::vector<Point3>& v, double tolerance) {
  std::vector<uint32_t> to(v.size());
  const int64_t cell = std::max<int64_t>(1, int64_t(std::ceil(tolerance)));
  std::unordered_map<uint64_t, std::vector<uint32_t>> grid;
  const double tol2 = tolerance * tolerance;
  for (uint32_t i = 0; i < v.size(); ++i) {
    to[i] = i;
    const int64_t cx = v[i].x / cell, cy = v[i].y / cell, cz = v[i].z / cell;
    const int64_t reach = tolerance > 0 ? 1 : 0;
    for (int64_t dx = -reach; dx <= reach && to[i] == i; ++dx)
      for (int64_t dy = -reach; dy <= reach && to[i] == i; ++dy)
        for (int64_t dz = -reach; dz <= reach && to[i] == i; ++dz) {
          auto it = grid.find(position_key(cx + dx, cy + dy, cz + dz));
          if (it == grid.end()) continue;
          for (uint32_t k : it->second) {
            const double ex = double(v[k].x) - v[i].x, ey = double(v[k].y) - v[i].y,
                         ez = double(v[k].z) - v[i].z;
            if (ex * ex + ey * ey + ez * ez <= tol2) {
              to[i] = k;
              break;
            }
          }
        }
    if (to[i] == i) grid[position_key(cx, cy, cz)].push_back(i);
  }
  return to;
}

}  // namespace

void weld_vertices(ObjModel* model, double tolerance, RepairReport* report) {
  const std::vector<uint32_t> to = weld_map(model->vertices, tolerance);
  std::vector<uint32_t> index(to.size());
  std::vector<Point3> kept;
  for (uint32_t i = 0; i < to.size(); ++i) {
    if (to[i] == i) {
      index[i] = uint32_t(kept.size());
      kept.push_back(model->vertices[i]);
    } else {
      index[i] = index[to[i]];
      ++report->merged_vertices;
    }
  }
  model->vertices = kept;
  std::vector<std::vector<uint32_t>> faces;
  std::vector<uint32_t> lines;
  for (size_t f = 0; f < model->faces.size(); ++f) {
    std::vector<uint32_t> c;
    for (uint32_t v : model->faces[f])
      if (c.empty() || c.back() != index[v]) c.push_back(index[v]);
    while (c.size() > 1 && c.back() == c.front()) c.pop_back();
    if (c.size() < 3) {
      ++report->dropped_faces;
      continue;
    }
    faces.push_back(c);
    if (f < model->face_lines.size()) lines.push_back(model->face_lines[f]);
  }
  model->faces = faces;
  model->face_lines = lines;
  std::vector<uint32_t> edges;
  PairSet seen;
  for (size_t e = 0; e + 1 < model->edge_pairs.size(); e += 2) {
    const uint32_t a = index[model->edge_pairs[e]], b = index[model->edge_pairs[e + 1]];
    if (a != b && seen.insert(pair_key(a, b))) edges.insert(edges.end(), {a, b});
  }
  model->edge_pairs = edges;
}

namespace {

// A face's side: the face, whether it runs from the lower vertex to the higher.
struct Side {
  uint64_t key;
  uint32_t face;
  bool up;
};

// The faces next to each face: neighbour, and whether it must be flipped relative to this
// face (0, 1), or 2 across a side on three or more faces (no constraint: the shell cannot be
// oriented).
struct Adjacency {
  std::vector<uint32_t> first;  // face f's neighbours are [first[f], first[f + 1])
  std::vector<std::pair<uint32_t, uint8_t>> next;
  std::vector<uint8_t> on_boundary, on_nonmanifold;  // per face
};

// Sorts the sides by key, stably: a radix sort on the key's 16-bit digits, skipping the digits
// every key shares (a model's vertex indices use few of the 64 bits).
void sort_by_key(std::vector<Side>* sides) {
  std::vector<Side> other(sides->size());
  std::vector<uint32_t> count(size_t{1} << 16);
  for (int shift = 0; shift < 64; shift += 16) {
    std::fill(count.begin(), count.end(), 0);
    for (const Side& s : *sides) ++count[(s.key >> shift) & 0xffff];
    if (!sides->empty() && count[(sides->front().key >> shift) & 0xffff] == sides->size())
      continue;  // one digit for all: this pass would keep the order
    uint32_t at = 0;
    for (uint32_t& c : count) at += std::exchange(c, at);
    for (const Side& s : *sides) other[count[(s.key >> shift) & 0xffff]++] = s;
    sides->swap(other);
  }
}

Adjacency adjacency(const ObjModel& m) {
  std::vector<Side> sides;
  for (uint32_t f = 0; f < m.faces.size(); ++f)
    for (size_t i = 0; i < m.faces[f].size(); ++i) {
      const uint32_t a = m.faces[f][i], b = m.faces[f][(i + 1) % m.faces[f].size()];
      if (a != b) sides.push_back(Side{pair_key(a, b), f, a < b});
    }
  sort_by_key(&sides);  // stable, and the faces came in order: by key, then face
  Adjacency adj;
  adj.on_boundary.assign(m.faces.size(), 0);
  adj.on_nonmanifold.assign(m.faces.size(), 0);
  std::vector<std::array<uint32_t, 3>> links;  // face, neighbour, constraint
  links.reserve(sides.size());
  for (size_t i = 0, j = 0; i < sides.size(); i = j) {
    while (j < sides.size() && sides[j].key == sides[i].key) ++j;
    if (j - i == 1) adj.on_boundary[sides[i].face] = 1;
    if (j - i > 2)
      for (size_t k = i; k < j; ++k) adj.on_nonmanifold[sides[k].face] = 1;
    for (size_t p = i; p < j; ++p)
      for (size_t q = i; q < j; ++q) {
        if (sides[p].face == sides[q].face) continue;
        // Two faces on one side agree when they run it opposite ways.
        const uint32_t c = j - i > 2 ? 2u : sides[p].up == sides[q].up ? 1u : 0u;
        links.push_back({sides[p].face, sides[q].face, c});
      }
  }
  adj.first.assign(m.faces.size() + 1, 0);
  for (const auto& l : links) ++adj.first[l[0] + 1];
  for (size_t f = 0; f < m.faces.size(); ++f) adj.first[f + 1] += adj.first[f];
  adj.next.resize(links.size());
  std::vector<uint32_t> fill(adj.first.begin(), adj.first.end() - 1);
  for (const auto& l : links) adj.next[fill[l[0]]++] = {l[1], uint8_t(l[2])};
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

}  // namespace

void orient_shells(ObjModel* model, RepairReport* report) {
  const Adjacency adj = adjacency(*model);
  std::vector<uint8_t> seen(model->faces.size(), 0), flip(model->faces.size(), 0);
  for (uint32_t seed = 0; seed < model->faces.size(); ++seed) {
    if (seen[seed]) continue;
    Shell s = grow_shell(adj, seed, &seen, &flip);
    ++report->shells;
    if (!s.orientable) {
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

// Do faces f and g count as one flat surface across their shared side?
bool flat_between(const ObjModel& m, const std::vector<Normal>& n, uint32_t f, uint32_t g,
                  double crease_deg) {
  const Normal& a = n[f];
  const Normal& b = n[g];
  if (is_zero(a) || is_zero(b)) return false;
  if (crease_deg > 0) {
    const double dot =
        double(a[0]) * double(b[0]) + double(a[1]) * double(b[1]) + double(a[2]) * double(b[2]);
    const double la = std::sqrt(double(a[0]) * double(a[0]) + double(a[1]) * double(a[1]) +
                                double(a[2]) * double(a[2]));
    const double lb = std::sqrt(double(b[0]) * double(b[0]) + double(b[1]) * double(b[1]) +
                                double(b[2]) * double(b[2]));
    const double cos_limit = std::cos(crease_deg * 3.14159265358979323846 / 180);
    return dot > cos_limit * la * lb;
  }
  // Exactly: both planar, normals parallel and the same way (then, sharing a side, one plane).
  // Each normal component is below 2^62 (vertices within 2^20), so the products fit.
  const __int128 cx = a[1] * b[2] - a[2] * b[1];
  const __int128 cy = a[2] * b[0] - a[0] * b[2];
  const __int128 cz = a[0] * b[1] - a[1] * b[0];
  const __int128 dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return cx == 0 && cy == 0 && cz == 0 && dot > 0 && planar(m, m.faces[f], a) &&
         planar(m, m.faces[g], b);
}

// The faces on a side: how many, the first two, and the last one counted.
struct SideFaces {
  uint32_t n = 0, face[2] = {0, 0}, last = 0;
};

}  // namespace

void drop_flat_edges(ObjModel* model, double crease_deg, RepairReport* report) {
  if (crease_deg < 0) return;
  PairMap<SideFaces> faces_of;
  size_t n_sides = 0;
  for (const std::vector<uint32_t>& c : model->faces) n_sides += c.size();
  faces_of.reserve(n_sides);
  for (uint32_t f = 0; f < model->faces.size(); ++f) {
    const std::vector<uint32_t>& c = model->faces[f];
    for (size_t i = 0; i < c.size(); ++i) {
      SideFaces* s = faces_of.insert(pair_key(c[i], c[(i + 1) % c.size()]));
      if (s->n > 0 && s->last == f) continue;  // a face counts once on a side
      if (s->n < 2) s->face[s->n] = f;
      ++s->n;
      s->last = f;
    }
  }
  std::vector<Normal> normals;
  normals.reserve(model->faces.size());
  for (const std::vector<uint32_t>& c : model->faces) normals.push_back(newell(*model, c));
  std::vector<uint32_t> kept;
  kept.reserve(model->edge_pairs.size());
  for (size_t e = 0; e + 1 < model->edge_pairs.size(); e += 2) {
    const uint32_t a = model->edge_pairs[e], b = model->edge_pairs[e + 1];
    const SideFaces* s = faces_of.find(pair_key(a, b));
    if (s != nullptr && s->n == 2 &&
        flat_between(*model, normals, s->face[0], s->face[1], crease_deg)) {
      ++report->flat_edges;
      continue;
    }
    kept.insert(kept.end(), {a, b});
  }
  model->edge_pairs = kept;
}

}  // namespace haloplot::host
