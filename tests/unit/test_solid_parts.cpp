// The hidden-line stage's face grid and incidences built in parts (memory/parts.h) are the ones
// one part builds, element for element: every cell's first index and face list, and every
// incidence array (by edge, edge_first, by vertex, vertex_first, same_next, the counts), with
// 2, 3 and 7 parts on threads and on a runner that runs them last first, on meshes with
// vertices on the same point, edges through vertices and an open surface; with an incidence
// capacity so tight that parts outgrow their slices (they run again into their place), and one
// short (the count a retry needs, as one part says it). The one-part incidences are checked
// against a brute-force search (every edge against every vertex, exact integers), and a face
// grid whose buffer holds no second part's cursors is built in one part, the same.
#include <algorithm>
#include <string>
#include <vector>

#include "../check.h"
#include "haloplot/solid/face_grid.h"
#include "haloplot/solid/incidence.h"
#include "haloplot/solid/topology.h"
#include "pipeline/thread_parts.h"
#include "support/solid_scenes.h"

using namespace haloplot;

namespace {

// A runner that runs the parts one after another, last first, and a count of the calls that
// split (so a scene that never split would be seen).
uint32_t g_split_calls = 0;
void backwards(void*, uint32_t n, PartFn work, void* arg) {
  ++g_split_calls;
  for (uint32_t i = n; i-- > 0;) work(arg, i);
}
struct Counted {
  const Parts* inner;
};
void counted(void* ctx, uint32_t n, PartFn work, void* arg) {
  ++g_split_calls;
  const Parts* inner = static_cast<Counted*>(ctx)->inner;
  inner->run(inner->context, n, work, arg);
}

struct Scene {
  std::string name;
  host::SolidScene scene;
  SolidInput in;
  std::vector<uint64_t> topo_mem;
  Topology topo;
};

bool make(const std::string& name, const solid_scenes::Mesh& m, const View& view, Scene* s) {
  s->name = name;
  if (!solid_scenes::project(m, view, &s->scene)) return false;
  s->in = host::solid_input(s->scene);
  s->topo_mem.assign(topology_bytes(s->in) / 8 + 1, 0);
  return build_topology(s->in, s->topo_mem.data(), s->topo_mem.size() * 8, &s->topo) == Status::kOk;
}

// ---- The face grid.

struct GridArrays {
  Status status = Status::kOk;
  std::vector<uint32_t> first, faces;
  Grid grid;
};

GridArrays grid_of(const Topology& topo, size_t extra_bytes, const Parts* parts) {
  std::vector<uint64_t> mem((face_grid_bytes(topo) + extra_bytes) / 8 + 1, 0xa5a5a5a5a5a5a5a5u);
  FaceGrid fg;
  GridArrays a;
  a.status = build_face_grid(topo, mem.data(), mem.size() * 8, &fg, 1, parts);
  if (a.status != Status::kOk) return a;
  a.grid = fg.grid;
  a.first.assign(fg.first, fg.first + fg.grid.cells() + 1);
  a.faces.assign(fg.faces, fg.faces + fg.pairs);
  return a;
}

bool same_grid(const GridArrays& a, const GridArrays& b) {
  return a.status == b.status && a.first == b.first && a.faces == b.faces &&
         a.grid.cells() == b.grid.cells() && a.grid.cell == b.grid.cell;
}

void check_grid(const Scene& s, const Parts& runner, const std::string& how) {
  const GridArrays one = grid_of(s.topo, 0, nullptr);
  CHECK_MSG(one.status == Status::kOk && !one.faces.empty(), s.name + ": no grid");
  // Each cell's list ascends (one part fills the faces in order).
  for (uint32_t c = 0; c + 1 < one.first.size(); ++c)
    CHECK_MSG(
        std::is_sorted(one.faces.begin() + one.first[c], one.faces.begin() + one.first[c + 1]),
        s.name);
  const size_t part_bytes = face_grid_part_bytes(s.topo);
  const uint32_t before = g_split_calls;
  const GridArrays split = grid_of(s.topo, runner.count * part_bytes, &runner);
  const uint32_t split_calls = g_split_calls - before;
  CHECK_MSG(split_calls > 2, s.name + how + ": the grid was not split");
  CHECK_MSG(same_grid(split, one), s.name + how + ": face grid");
  // No room for a second part's cursors: one part, the same grid. The pairs are counted in
  // parts as the grid is chosen either way; the fill's two splits (count, drop) are not made.
  const uint32_t before_tight = g_split_calls;
  const GridArrays tight = grid_of(s.topo, part_bytes - 24, &runner);
  CHECK_MSG(same_grid(tight, one), s.name + how + ": face grid without room for parts");
  CHECK_MSG(g_split_calls - before_tight == split_calls - 2,
            s.name + how + ": a split without room");
}

// ---- The incidences.

struct IncArrays {
  Status status = Status::kOk;
  uint32_t needed = 0, coincident = 0;
  std::vector<Incidence> by_edge;
  std::vector<uint32_t> edge_first, by_vertex, vertex_first, same_next;
};

bool same_records(const std::vector<Incidence>& a, const std::vector<Incidence>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const Incidence& x, const Incidence& y) {
                      return x.edge == y.edge && x.vertex == y.vertex && x.t == y.t &&
                             x.num == y.num && x.den == y.den;
                    });
}

IncArrays incidences_of(const Topology& topo, uint32_t capacity, bool by_vertex,
                        const Parts* parts) {
  const size_t bytes = incidence_bytes(topo, capacity, by_vertex);
  // Not zeros (a record left unwritten shows), but no index out of range either.
  std::vector<uint64_t> mem(bytes / 8 + 1, 0x0000000100000001u);
  Incidences inc;
  IncArrays a;
  a.status = find_incidences(topo, capacity, mem.data(), bytes, &inc, &a.needed, by_vertex, parts);
  if (a.status != Status::kOk) return a;
  const uint32_t nv = topo.n_vertices;
  a.coincident = inc.coincident_vertices;
  a.by_edge.assign(inc.by_edge, inc.by_edge + inc.n);
  a.edge_first.assign(inc.edge_first, inc.edge_first + topo.n_edges + 1);
  if (by_vertex) {
    a.by_vertex.assign(inc.by_vertex, inc.by_vertex + inc.n);
    a.vertex_first.assign(inc.vertex_first, inc.vertex_first + nv + 1);
    a.same_next.assign(inc.same_next, inc.same_next + nv);
  }
  return a;
}

bool same_inc(const IncArrays& a, const IncArrays& b) {
  return a.status == b.status && a.needed == b.needed && a.coincident == b.coincident &&
         same_records(a.by_edge, b.by_edge) && a.edge_first == b.edge_first &&
         a.by_vertex == b.by_vertex && a.vertex_first == b.vertex_first &&
         a.same_next == b.same_next;
}

// Every edge against every vertex: on its line, strictly between its ends; the position along
// the longer axis; each edge's in order of position, then vertex. Vertices on one point ringed
// in index order.
void reference(const Topology& topo, std::vector<Incidence>* recs, std::vector<uint32_t>* ring,
               uint32_t* coincident) {
  const Point3* p = topo.vertices;
  for (uint32_t e = 0; e < topo.n_edges; ++e) {
    const SolidEdge& se = topo.edges[e];
    const int64_t ax = p[se.v0].x, ay = p[se.v0].y, dx = p[se.v1].x - ax, dy = p[se.v1].y - ay;
    if (dx == 0 && dy == 0) continue;
    std::vector<Incidence> mine;
    for (uint32_t w = 0; w < topo.n_vertices; ++w) {
      if (w == se.v0 || w == se.v1) continue;
      const int64_t wx = p[w].x - ax, wy = p[w].y - ay;
      if (dx * wy != dy * wx) continue;
      const bool use_x = std::abs(dx) >= std::abs(dy);
      int64_t num = use_x ? wx : wy, den = use_x ? dx : dy;
      if (den < 0) num = -num, den = -den;
      if (num <= 0 || num >= den) continue;
      mine.push_back(Incidence{e, w, uint32_t((uint64_t(num) << 32) / uint64_t(den)), uint32_t(num),
                               uint32_t(den)});
    }
    std::sort(mine.begin(), mine.end(), [](const Incidence& a, const Incidence& b) {
      return a.t != b.t ? a.t < b.t : a.vertex < b.vertex;
    });
    recs->insert(recs->end(), mine.begin(), mine.end());
  }
  *coincident = 0;
  ring->assign(topo.n_vertices, 0);
  for (uint32_t v = 0; v < topo.n_vertices; ++v) {
    std::vector<uint32_t> same;
    for (uint32_t u = 0; u < topo.n_vertices; ++u)
      if (p[u].x == p[v].x && p[u].y == p[v].y) same.push_back(u);
    const size_t k = size_t(std::find(same.begin(), same.end(), v) - same.begin());
    (*ring)[v] = same[(k + 1) % same.size()];
    if (same.size() > 1) ++*coincident;
  }
}

void check_incidences(const Scene& s, const Parts& runner, const std::string& how) {
  // The exact count, then one part with room to spare.
  const IncArrays probe = incidences_of(s.topo, 0, true, nullptr);
  const uint32_t exact = probe.status == Status::kOk ? 0 : probe.needed;
  const IncArrays one = incidences_of(s.topo, exact + 100, true, nullptr);
  CHECK_MSG(one.status == Status::kOk && one.needed == exact, s.name + ": one part");
  std::vector<Incidence> want;
  std::vector<uint32_t> ring;
  uint32_t coincident = 0;
  reference(s.topo, &want, &ring, &coincident);
  CHECK_MSG(same_records(one.by_edge, want),
            s.name + ": the incidences against the brute-force search");
  CHECK_MSG(one.same_next == ring && one.coincident == coincident, s.name + ": coincident");
  for (uint32_t capacity : {exact + 100, exact}) {
    const std::string what = s.name + how + ", capacity " + std::to_string(capacity);
    const uint32_t before = g_split_calls;
    CHECK_MSG(same_inc(incidences_of(s.topo, capacity, true, &runner),
                       incidences_of(s.topo, capacity, true, nullptr)),
              what);
    CHECK_MSG(g_split_calls > before, what + ": not split");
    CHECK_MSG(same_inc(incidences_of(s.topo, capacity, false, &runner),
                       incidences_of(s.topo, capacity, false, nullptr)),
              what + ", by edge only");
  }
  if (exact > 0) {
    const IncArrays short_one = incidences_of(s.topo, exact - 1, true, nullptr);
    const IncArrays short_parts = incidences_of(s.topo, exact - 1, true, &runner);
    CHECK_MSG(short_one.status == Status::kIncidenceCapacity && short_one.needed == exact &&
                  same_inc(short_parts, short_one),
              s.name + how + ", one record short");
  }
}

void check_scene(const Scene& s) {
  for (uint32_t n : {2u, 3u, 7u}) {
    Parts back;
    back.run = &backwards;
    back.count = n;
    back.min_work = 0;  // split these small scenes too
    const std::string how = ", " + std::to_string(n) + " parts";
    check_grid(s, back, how + " last first");
    check_incidences(s, back, how + " last first");
    Counted inner{host::thread_parts(n)};
    Parts threads;
    threads.run = &counted;
    threads.context = &inner;
    threads.count = n;
    threads.min_work = 0;
    check_grid(s, threads, how + " on threads");
    check_incidences(s, threads, how + " on threads");
  }
}

}  // namespace

int main() {
  // A closed torus, seen from above at an angle.
  {
    solid_scenes::Mesh m;
    solid_scenes::torus(&m, 0, 0, 0, 300000, 120000, 60, 30);
    Scene s;
    CHECK(make("torus", m, solid_scenes::view(30000, 25000), &s));
    check_scene(s);
  }
  // Boxes seen straight on: back corners on the front ones' points, and a row of short boxes
  // under a stack of long ones, each shorter than the one below, whose sides pass through the
  // corners of the boxes above them.
  {
    solid_scenes::Mesh m;
    for (int i = 0; i < 6; ++i)
      solid_scenes::box(&m, i * 40000, 0, 0, i * 40000 + 40000, 40000, 40000);
    for (int i = 0; i < 4; ++i)
      solid_scenes::box(&m, 0, 40000 + i * 30000, 0, 240000 - i * 30000, 70000 + i * 30000,
                        20000 * (i + 1));
    Scene s;
    CHECK(make("boxes head-on", m, solid_scenes::view(0, 0), &s));
    std::vector<Incidence> recs;
    std::vector<uint32_t> ring;
    uint32_t coincident = 0;
    reference(s.topo, &recs, &ring, &coincident);
    CHECK_MSG(recs.size() > 20 && coincident > 20, s.name + ": touches to find");
    check_scene(s);
  }
  // An open surface: a height field of 40 x 30 squares, seen from straight above, where rows of
  // vertices line up under its edges, and from an angle.
  for (int32_t el : {90000, 35000}) {
    solid_scenes::Mesh m;
    const int nx = 40, ny = 30;
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        m.add(i * 10000, j * 10000, ((i * 7 + j * 3) % 5) * 4000 + (i % 3 == 0 ? 0 : 2000));
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const uint32_t a = uint32_t(j * (nx + 1) + i);
        m.face({a, a + 1, a + uint32_t(nx) + 2, a + uint32_t(nx) + 1});
      }
    Scene s;
    CHECK(make("open height field, elevation " + std::to_string(el / 1000), m,
               solid_scenes::view(0, el), &s));
    CHECK_MSG(!s.topo.check.manifold(), s.name + ": open");
    check_scene(s);
  }
  return check::finish("solid_parts");
}
