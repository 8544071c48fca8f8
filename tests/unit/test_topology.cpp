// build_topology against a reference built with std::map: the drawn edges in input order, then
// one diagonal per distinct undrawn triangle side in key order, every side's face in its edge's
// slot, and the same topology (every array) whether the buffer is generous (the drawn keys get
// an index by vertex) or exactly what the build needs (searched whole), bands' rows too.
#include <cstring>
#include <map>
#include <vector>

#include "../check.h"
#include "../support/solid_scenes.h"
#include "haloplot/solid/topology.h"

using namespace haloplot;

namespace {

uint64_t key(uint32_t a, uint32_t b) {
  return a < b ? uint64_t{a} << 32 | b : uint64_t{b} << 32 | a;
}

// Checks t against the reference numbering and attachment.
void check_reference(const SolidInput& in, const Topology& t, const TopologyOptions& o) {
  std::map<uint64_t, uint32_t> drawn, diagonal;
  for (uint32_t e = 0; e < in.n_edges; ++e)
    drawn[key(in.edge_pairs[2 * e], in.edge_pairs[2 * e + 1])] = e;
  for (uint32_t s = 0; s < 3 * in.n_triangles; ++s) {
    const uint32_t a = in.triangles[s / 3].v[s % 3], b = in.triangles[s / 3].v[(s % 3 + 1) % 3];
    const int32_t ya = in.vertices[a].y, yb = in.vertices[b].y;
    const bool in_rows = !o.rows || (std::max(ya, yb) >= o.row_lo && std::min(ya, yb) <= o.row_hi);
    if (!drawn.count(key(a, b)) && in_rows) diagonal[key(a, b)] = 0;
  }
  CHECK_EQ(t.n_drawn, in.n_edges);
  CHECK_EQ(size_t{t.n_edges}, size_t{in.n_edges} + diagonal.size());
  uint32_t next = in.n_edges;
  for (auto& d : diagonal) d.second = next++;
  for (uint32_t e = 0; e < in.n_edges && e < t.n_edges; ++e)
    CHECK(t.edges[e].v0 == in.edge_pairs[2 * e] && t.edges[e].v1 == in.edge_pairs[2 * e + 1]);
  for (const auto& d : diagonal)
    if (d.second < t.n_edges) CHECK(key(t.edges[d.second].v0, t.edges[d.second].v1) == d.first);
  for (uint32_t s = 0; s < 3 * in.n_triangles; ++s) {
    const uint32_t a = in.triangles[s / 3].v[s % 3], b = in.triangles[s / 3].v[(s % 3 + 1) % 3];
    auto it = drawn.find(key(a, b));
    uint32_t e = it != drawn.end() ? it->second : kNoFace;
    if (e == kNoFace && diagonal.count(key(a, b))) e = diagonal[key(a, b)];
    if (e == kNoFace || e >= t.n_edges) continue;
    CHECK(t.edges[e].face[0] == s / 3 || t.edges[e].face[1] == s / 3);
  }
}

bool same(const Topology& x, const Topology& y, bool stars, uint32_t nv, uint32_t sides) {
  if (x.n_edges != y.n_edges || x.n_drawn != y.n_drawn) return false;
  if (std::memcmp(&x.check, &y.check, sizeof x.check) != 0) return false;
  for (uint32_t e = 0; e < x.n_edges; ++e) {
    const SolidEdge &a = x.edges[e], &b = y.edges[e];
    if (a.v0 != b.v0 || a.v1 != b.v1 || a.face[0] != b.face[0] || a.face[1] != b.face[1] ||
        a.drawn != b.drawn || a.regular != b.regular)
      return false;
  }
  if (!stars) return true;
  return std::memcmp(x.vertex_edge_first, y.vertex_edge_first, 4 * (nv + 1)) == 0 &&
         std::memcmp(x.vertex_edges, y.vertex_edges, 8 * size_t{x.n_edges}) == 0 &&
         std::memcmp(x.vertex_face_first, y.vertex_face_first, 4 * (nv + 1)) == 0 &&
         std::memcmp(x.vertex_faces, y.vertex_faces, 4 * size_t{sides}) == 0;
}

void generous_and_exact_agree(const solid_scenes::Mesh& m, uint32_t drop_every, bool rows) {
  haloplot::host::SolidScene scene;
  CHECK(solid_scenes::project(m, solid_scenes::view(30000, 25000), &scene));
  // Some polygon sides left undrawn: more diagonals to number.
  std::vector<uint32_t> pairs;
  for (size_t e = 0; 2 * e < scene.edge_pairs.size(); ++e)
    if (drop_every == 0 || e % drop_every != 0)
      pairs.insert(pairs.end(), {scene.edge_pairs[2 * e], scene.edge_pairs[2 * e + 1]});
  scene.edge_pairs = pairs;
  const SolidInput in = haloplot::host::solid_input(scene);
  TopologyOptions o;
  if (rows) {
    o.stars = false;
    o.rows = true;
    o.row_lo = -20000;
    o.row_hi = 30000;
  }
  std::vector<uint64_t> big(2 * topology_bytes(in) / 8 + 1);
  Topology g;
  CHECK(build_topology(in, big.data(), big.size() * 8, &g, o) == Status::kOk);
  check_reference(in, g, o);
  // The least buffer it takes: kept arrays and scratch, nothing between them.
  size_t exact = g.kept_bytes + g.scratch_bytes;
  std::vector<uint64_t> small;
  Topology x;
  Status s = Status::kWorkspaceTooSmall;
  for (; s == Status::kWorkspaceTooSmall && exact < g.kept_bytes + g.scratch_bytes + 64;
       exact += 8) {
    small.assign(exact / 8 + 1, 0);
    s = build_topology(in, small.data(), exact, &x, o);
  }
  CHECK(s == Status::kOk);
  CHECK(same(g, x, o.stars, in.n_vertices, 3 * in.n_triangles));
}

}  // namespace

int main() {
  solid_scenes::Mesh torus, boxes, sphere;
  solid_scenes::torus(&torus, 0, 0, 0, 150000, 60000, 60, 24);
  solid_scenes::box(&boxes, -100000, -100000, -100000, 0, 0, 0);
  solid_scenes::box(&boxes, 50000, 20000, -30000, 140000, 90000, 60000);
  solid_scenes::sphere(&sphere, 0, 0, 0, 200000, 20, 30);
  for (const solid_scenes::Mesh* m : {&torus, &boxes, &sphere})
    for (uint32_t drop : {0u, 3u})
      for (bool rows : {false, true}) generous_and_exact_agree(*m, drop, rows);
  return check::finish("topology");
}
