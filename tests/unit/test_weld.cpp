// weld_vertices (host_sim/pipeline/mesh_repair.h) against a brute-force reference of its rule:
// in file order, a vertex becomes the first vertex kept before it within the tolerance, where
// "first" is the order a search of the cells around it meets them: cells of side
// ceil(tolerance) (at least 1; a coordinate's cell is its quotient, rounded toward zero), the
// neighbouring cells (dx, dy, dz) from -1 to 1 in that order (only its own cell at tolerance 0),
// each cell's kept vertices in file order. The reference asks every earlier kept vertex, with
// no grid and no sorting. Clouds of clustered points make many ties between candidates; the
// faces and drawn edges that follow the vertices are checked too.
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "check.h"
#include "pipeline/mesh_repair.h"

namespace haloplot::host {
namespace {

// Which earlier kept vertex each vertex becomes (itself if none), by the rule above.
std::vector<uint32_t> reference_weld(const std::vector<Point3>& v, double tolerance) {
  const int64_t cell = std::max<int64_t>(1, int64_t(std::ceil(tolerance)));
  std::vector<uint32_t> to(v.size());
  for (uint32_t i = 0; i < v.size(); ++i) {
    to[i] = i;
    int64_t best_rank = 0;
    for (uint32_t k = 0; k < i; ++k) {
      if (to[k] != k) continue;
      const int64_t d[3] = {v[k].x / cell - v[i].x / cell, v[k].y / cell - v[i].y / cell,
                            v[k].z / cell - v[i].z / cell};
      const int64_t reach = tolerance > 0 ? 1 : 0;
      bool near_cell = true;
      for (int64_t x : d) near_cell = near_cell && x >= -reach && x <= reach;
      const double ex = double(v[k].x) - v[i].x, ey = double(v[k].y) - v[i].y,
                   ez = double(v[k].z) - v[i].z;
      if (!near_cell || ex * ex + ey * ey + ez * ez > tolerance * tolerance) continue;
      const int64_t rank = (d[0] + 1) * 9 + (d[1] + 1) * 3 + (d[2] + 1);
      if (to[i] == i || rank < best_rank) {  // k ascends: the first of a rank is kept
        to[i] = k;
        best_rank = rank;
      }
    }
  }
  return to;
}

// A face's corners as a closed walk, reduced until nothing changes: anywhere round the
// cycle, a corner the same as the next goes, and a corner whose two neighbours are the same
// vertex (a spike, out and straight back) goes. The order of removals may leave another
// rotation of the same cycle than weld_vertices' one pass, so faces are compared as cycles.
void reduce_walk(std::vector<uint32_t>* c) {
  for (bool changed = true; changed && c->size() >= 2;) {
    changed = false;
    const size_t n = c->size();
    for (size_t i = 0; i < n && !changed; ++i) {
      const uint32_t before = (*c)[(i + n - 1) % n], here = (*c)[i], after = (*c)[(i + 1) % n];
      if (here == after || (n >= 3 && before == after)) {
        c->erase(c->begin() + std::ptrdiff_t(i));
        changed = true;
      }
    }
  }
}

bool same_cycle(const std::vector<uint32_t>& a, const std::vector<uint32_t>& b) {
  if (a.size() != b.size()) return false;
  for (size_t r = 0; r < a.size(); ++r) {
    bool same = true;
    for (size_t i = 0; i < a.size() && same; ++i) same = a[(i + r) % a.size()] == b[i];
    if (same) return true;
  }
  return a.empty();
}

// Points in a few clusters around the origin (both signs: cells there are wider), each
// vertex a small random step from a cluster centre, in shuffled order; quads over them.
ObjModel cloud(std::mt19937& rng, uint32_t n, int32_t spread, int32_t jitter) {
  ObjModel m;
  std::uniform_int_distribution<int32_t> centre(-spread, spread), step(-jitter, jitter);
  std::vector<Point3> centres(n / 4 + 1);
  for (Point3& c : centres) c = Point3{centre(rng), centre(rng), centre(rng)};
  std::uniform_int_distribution<size_t> pick(0, centres.size() - 1);
  for (uint32_t i = 0; i < n; ++i) {
    const Point3 c = centres[pick(rng)];
    m.vertices.push_back(Point3{c.x + step(rng), c.y + step(rng), c.z + step(rng)});
  }
  std::uniform_int_distribution<uint32_t> any(0, n - 1);
  for (uint32_t f = 0; f < n / 2; ++f) {
    m.faces.push_back({any(rng), any(rng), any(rng), any(rng)});
    m.face_lines.push_back(f + 1);
    m.edge_pairs.insert(m.edge_pairs.end(), {m.faces.back()[0], m.faces.back()[1]});
  }
  return m;
}

void check_case(std::mt19937& rng, uint32_t n, int32_t spread, int32_t jitter, double tolerance) {
  const ObjModel given = cloud(rng, n, spread, jitter);
  const std::vector<uint32_t> to = reference_weld(given.vertices, tolerance);
  // The reference's model: kept vertices in order, faces and edges renumbered and cleaned.
  std::vector<uint32_t> index(to.size());
  std::vector<Point3> kept;
  uint32_t merged = 0;
  for (uint32_t i = 0; i < to.size(); ++i) {
    index[i] = to[i] == i ? uint32_t(kept.size()) : index[to[i]];
    if (to[i] == i) kept.push_back(given.vertices[i]);
    merged += to[i] != i;
  }
  std::vector<std::vector<uint32_t>> faces;
  std::vector<uint32_t> lines;
  for (size_t f = 0; f < given.faces.size(); ++f) {
    std::vector<uint32_t> c;
    for (uint32_t v : given.faces[f]) c.push_back(index[v]);
    reduce_walk(&c);
    if (c.size() < 3) continue;
    faces.push_back(c);
    lines.push_back(given.face_lines[f]);
  }
  std::vector<uint32_t> edges;
  for (size_t e = 0; e < given.edge_pairs.size(); e += 2) {
    uint32_t a = index[given.edge_pairs[e]], b = index[given.edge_pairs[e + 1]];
    bool seen = a == b;
    for (size_t k = 0; k < edges.size() && !seen; k += 2)
      seen = (edges[k] == a && edges[k + 1] == b) || (edges[k] == b && edges[k + 1] == a);
    if (!seen) edges.insert(edges.end(), {a, b});
  }

  ObjModel m = given;
  RepairReport report;
  weld_vertices(&m, tolerance, &report);
  CHECK_EQ(report.merged_vertices, merged);
  CHECK_EQ(report.dropped_faces, uint32_t(given.faces.size() - faces.size()));
  CHECK_EQ(m.vertices.size(), kept.size());
  bool same_vertices = m.vertices.size() == kept.size();
  for (size_t i = 0; same_vertices && i < kept.size(); ++i)
    same_vertices = m.vertices[i].x == kept[i].x && m.vertices[i].y == kept[i].y &&
                    m.vertices[i].z == kept[i].z;
  CHECK(same_vertices);
  bool same_faces = m.faces.size() == faces.size();
  for (size_t f = 0; same_faces && f < faces.size(); ++f)
    same_faces = same_cycle(m.faces[f], faces[f]);
  CHECK(same_faces);
  CHECK(m.face_lines == lines);
  CHECK(m.edge_pairs == edges);
  // Something to decide: the clouds must weld some vertices and keep others.
  CHECK(merged > 0 && merged < n);
}

}  // namespace
}  // namespace haloplot::host

int main() {
  std::mt19937 rng(48);
  for (int round = 0; round < 20; ++round) {
    haloplot::host::check_case(rng, 400, 40, 1, 0);        // the same position only
    haloplot::host::check_case(rng, 400, 60, 4, 1.7);      // the default's least
    haloplot::host::check_case(rng, 400, 80, 6, 3.5);      // cells of 4
    haloplot::host::check_case(rng, 300, 1000, 40, 25.0);  // wide cells, many per cell
  }
  return check::finish("weld");
}
