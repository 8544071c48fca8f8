// build_topology and build_topology_stars in parts (TopologyOptions::parts) keep exactly what
// one part keeps: every edge (ends, faces, drawn, regular), the mesh check and every star
// array, element by element, with 2, 3 and 7 parts each on a thread of its own, in a buffer of
// topology_bytes() (the parts use its spare room) and in the least buffer the build takes (no
// spare room: the steps a part cannot take in room of its own are done as one part). Meshes:
// a closed torus with some polygon sides undrawn, an open grid, and a soup of random triangles
// on few vertices (sides with one, two, three or more faces, either way round, loose edges).
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "../check.h"
#include "../support/solid_scenes.h"
#include "haloplot/solid/topology.h"
#include "pipeline/thread_parts.h"

using namespace haloplot;

namespace {

struct Mesh {
  std::vector<Point3> v;
  std::vector<uint32_t> pairs;
  std::vector<Triangle> tris;
  SolidInput input() const {
    SolidInput in;
    in.vertices = v.data();
    in.n_vertices = uint32_t(v.size());
    in.edge_pairs = pairs.data();
    in.n_edges = uint32_t(pairs.size() / 2);
    in.triangles = tris.data();
    in.n_triangles = uint32_t(tris.size());
    return in;
  }
};

struct Built {
  std::vector<uint64_t> buffer;
  Topology t;
  Status status = Status::kOk;
};

// The topology in a buffer of `bytes` (0: topology_bytes()), its stars built with it or after.
void build(const SolidInput& in, TopologyOptions o, bool stars_after, const Parts* parts,
           size_t bytes, Built* b) {
  o.parts = parts;
  if (stars_after) o.stars = false;
  if (bytes == 0) bytes = topology_bytes(in);
  // Room for the stars after the kept arrays too, at most (as hidden_lines() puts them there).
  const size_t most_stars =
      4 * (2 * (size_t{in.n_vertices} + 1) + 9 * size_t{in.n_triangles} + 2 * size_t{in.n_edges}) +
      64;
  b->buffer.assign((bytes + most_stars) / 8 + 1, 0);
  b->status = build_topology(in, b->buffer.data(), bytes, &b->t, o);
  if (b->status != Status::kOk || !stars_after) return;
  const size_t star_bytes = topology_star_bytes(b->t);
  CHECK(b->t.kept_bytes + star_bytes <= bytes + most_stars);
  b->status = build_topology_stars(
      &b->t, reinterpret_cast<uint8_t*>(b->buffer.data()) + b->t.kept_bytes, star_bytes, parts);
}

// Every array the two keep, element by element; says the first difference.
bool same(const Topology& x, const Topology& y, bool stars, std::string* why) {
  char at[160];
  if (x.n_edges != y.n_edges || x.n_drawn != y.n_drawn || x.n_vertices != y.n_vertices)
    return *why = "edge counts", false;
  if (x.check.boundary_edges != y.check.boundary_edges ||
      x.check.nonmanifold_edges != y.check.nonmanifold_edges ||
      x.check.misoriented_edges != y.check.misoriented_edges ||
      x.check.loose_edges != y.check.loose_edges)
    return *why = "mesh check", false;
  if (x.kept_bytes != y.kept_bytes || x.scratch_bytes != y.scratch_bytes)
    return *why = "bytes", false;
  for (uint32_t e = 0; e < x.n_edges; ++e) {
    const SolidEdge &a = x.edges[e], &b = y.edges[e];
    if (a.v0 != b.v0 || a.v1 != b.v1 || a.face[0] != b.face[0] || a.face[1] != b.face[1] ||
        a.cls != b.cls || a.drawn != b.drawn || a.regular != b.regular) {
      std::snprintf(at, sizeof at, "edge %u: %u-%u faces %u,%u vs %u-%u faces %u,%u", e, a.v0, a.v1,
                    a.face[0], a.face[1], b.v0, b.v1, b.face[0], b.face[1]);
      return *why = at, false;
    }
  }
  if (!stars) return true;
  const uint32_t nv = x.n_vertices, sides = 3 * x.n_triangles;
  for (uint32_t v = 0; v <= nv; ++v)
    if (x.vertex_edge_first[v] != y.vertex_edge_first[v] ||
        x.vertex_face_first[v] != y.vertex_face_first[v])
      return *why = "star starts at vertex " + std::to_string(v), false;
  for (uint32_t i = 0; i < 2 * x.n_edges; ++i)
    if (x.vertex_edges[i] != y.vertex_edges[i])
      return *why = "vertex_edges[" + std::to_string(i) + "]", false;
  for (uint32_t i = 0; i < sides; ++i)
    if (x.vertex_faces[i] != y.vertex_faces[i])
      return *why = "vertex_faces[" + std::to_string(i) + "]", false;
  return true;
}

// Which ways the mesh breaks a closed manifold, so the meshes are seen to cover them.
std::string flaws(const MeshCheck& c) {
  return std::string(c.boundary_edges > 0 ? " boundary" : "") +
         (c.nonmanifold_edges > 0 ? " nonmanifold" : "") +
         (c.misoriented_edges > 0 ? " misoriented" : "") + (c.loose_edges > 0 ? " loose" : "");
}

void check_mesh(const std::string& name, const Mesh& m, const std::string& expect_flaws) {
  const SolidInput in = m.input();
  struct Case {
    const char* what;
    TopologyOptions o;
    bool stars_after;
  };
  TopologyOptions plain, band;
  band.stars = false;
  band.rows = true;
  band.row_lo = -20000;
  band.row_hi = 30000;
  for (const Case& c :
       {Case{"stars", plain, false}, Case{"stars after", plain, true}, Case{"rows", band, false}}) {
    Built one;
    build(in, c.o, c.stars_after, nullptr, 0, &one);
    CHECK_MSG(one.status == Status::kOk, name + ", " + c.what + ": one part");
    if (one.status != Status::kOk) continue;
    if (!c.o.rows) CHECK_MSG(flaws(one.t.check) == expect_flaws, name + ":" + flaws(one.t.check));
    const bool stars = c.o.stars || c.stars_after;
    const size_t least = one.t.kept_bytes + one.t.scratch_bytes;
    for (uint32_t threads : {2u, 3u, 7u}) {
      Parts parts = *host::thread_parts(threads);
      parts.min_work = 0;  // split even these small meshes
      for (size_t bytes : {size_t{0}, least}) {
        if (c.stars_after && bytes != 0) continue;  // the stars are built apart: no least
        Built split;
        build(in, c.o, c.stars_after, &parts, bytes, &split);
        const std::string what = name + ", " + c.what + ", " + std::to_string(threads) + " parts" +
                                 (bytes == 0 ? "" : ", least buffer");
        CHECK_MSG(split.status == Status::kOk, what);
        std::string why;
        const bool agree = split.status == Status::kOk && same(one.t, split.t, stars, &why);
        CHECK_MSG(agree || split.status != Status::kOk, what + ": " + why);
      }
    }
  }
}

// Polygons of a scene as triangles, and their sides drawn but every `undrawn`-th.
Mesh from_scene(const solid_scenes::Mesh& m, uint32_t undrawn) {
  haloplot::host::SolidScene scene;
  CHECK(solid_scenes::project(m, solid_scenes::view(30000, 25000), &scene));
  Mesh out;
  const SolidInput in = haloplot::host::solid_input(scene);
  out.v.assign(in.vertices, in.vertices + in.n_vertices);
  out.tris.assign(in.triangles, in.triangles + in.n_triangles);
  for (uint32_t e = 0; e < in.n_edges; ++e)
    if (undrawn == 0 || e % undrawn != 0)
      out.pairs.insert(out.pairs.end(), {in.edge_pairs[2 * e], in.edge_pairs[2 * e + 1]});
  return out;
}

// An open grid of n x n quads, each split into two triangles, its outline and rows drawn.
Mesh grid(uint32_t n) {
  Mesh m;
  for (uint32_t y = 0; y <= n; ++y)
    for (uint32_t x = 0; x <= n; ++x)
      m.v.push_back(Point3{int32_t(x * 4000) + 1000, int32_t(y * 2000) + 1000, int32_t(x * y)});
  auto at = [&](uint32_t x, uint32_t y) { return y * (n + 1) + x; };
  for (uint32_t y = 0; y < n; ++y)
    for (uint32_t x = 0; x < n; ++x) {
      m.tris.push_back(Triangle{{at(x, y), at(x + 1, y), at(x + 1, y + 1)}, 0});
      m.tris.push_back(Triangle{{at(x, y), at(x + 1, y + 1), at(x, y + 1)}, 0});
      m.pairs.insert(m.pairs.end(), {at(x, y), at(x + 1, y)});  // rows drawn
    }
  return m;
}

// Random triangles on few vertices: sides shared by any number of faces, either way round;
// drawn edges some of them on faces, some loose.
Mesh soup(uint32_t n_vertices, uint32_t n_triangles, uint32_t seed) {
  std::mt19937 gen(seed);
  auto rng = [&] { return uint32_t(gen()); };
  Mesh m;
  for (uint32_t i = 0; i < n_vertices; ++i)
    m.v.push_back(
        Point3{int32_t(rng() % 100000), int32_t(rng() % 100000), int32_t(rng() % 100000)});
  while (m.tris.size() < n_triangles) {
    const uint32_t a = rng() % n_vertices, b = rng() % n_vertices, c = rng() % n_vertices;
    if (a != b && b != c && a != c) m.tris.push_back(Triangle{{a, b, c}, 0});
  }
  std::vector<uint8_t> drawn(size_t{n_vertices} * n_vertices, 0);
  for (uint32_t i = 0; i < n_triangles; ++i) {
    const uint32_t a = rng() % n_vertices, b = rng() % n_vertices;
    if (a == b || drawn[a * n_vertices + b] || drawn[b * n_vertices + a]) continue;
    drawn[a * n_vertices + b] = 1;
    m.pairs.insert(m.pairs.end(), {a, b});
  }
  return m;
}

}  // namespace

int main() {
  solid_scenes::Mesh torus;
  solid_scenes::torus(&torus, 0, 0, 0, 150000, 60000, 60, 24);
  check_mesh("torus", from_scene(torus, 0), "");
  check_mesh("torus, every third side undrawn", from_scene(torus, 3), "");
  check_mesh("open grid", grid(30), " boundary");
  for (uint32_t seed = 1; seed <= 3; ++seed)
    check_mesh("soup " + std::to_string(seed), soup(40, 400, seed),
               " boundary nonmanifold misoriented loose");
  check_mesh("tiny soup", soup(5, 3, 4), " boundary");
  return check::finish("topology_parts");
}
