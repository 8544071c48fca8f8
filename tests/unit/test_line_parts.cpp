// The end of the hidden-line stage split into parts on real threads gives what one part gives,
// element by element: the pieces of every edge, the contour diagonals', the intersection lines'
// (their numbers, positions, cover, faces and segments) and the stats that count them. On a
// sphere through a torus (so intersection segments exist) and on a torus alone, with 2, 3 and 7
// parts (the whole stage through the host's run; the core's stage with its end's buffer so
// small that the QI emission's parts fill their shares, on the sphere whose walks stop at
// pierces; and draw_intersections alone with buffers so small that parts fill their shares and
// draw the rest of their cells on the calling thread).
#include <cstring>
#include <string>
#include <vector>

#include "../check.h"
#include "haloplot/solid/classify.h"
#include "haloplot/solid/hidden_lines.h"
#include "haloplot/solid/intersection_lines.h"
#include "pipeline/thread_parts.h"
#include "support/solid_scenes.h"

using namespace haloplot;
using namespace haloplot::host;
using namespace solid_scenes;

namespace {

struct Model {
  std::string name;
  Mesh mesh;
  bool crosses;  // intersection segments expected
};

std::vector<Model> models() {
  std::vector<Model> out;
  {
    Model m{"sphere through a torus", {}, true};
    torus(&m.mesh, 0, 0, 0, 150000, 50000, 48, 16);
    sphere(&m.mesh, 150000, 0, 20000, 80000, 16, 32);
    out.push_back(m);
  }
  {
    Model m{"torus", {}, false};
    torus(&m.mesh, 0, 0, 0, 150000, 50000, 64, 24);
    out.push_back(m);
  }
  return out;
}

// A real thread runner that splits even these small models.
Parts threads(uint32_t n) {
  Parts p = *thread_parts(n);
  p.min_work = 0;
  return p;
}

bool same_pieces(const std::vector<SolidPiece>& a, const std::vector<SolidPiece>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].edge != b[i].edge || a[i].t0 != b[i].t0 || a[i].t1 != b[i].t1 || a[i].q != b[i].q ||
        a[i].hidden != b[i].hidden)
      return false;
  return true;
}

bool same_edges(const std::vector<Edge3>& a, const std::vector<Edge3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Edge3)) == 0;
}

bool same_counts(const IntersectionStats& x, const IntersectionStats& y) {
  return x.pairs == y.pairs && x.segments == y.segments && x.pieces == y.pieces &&
         x.tests == y.tests && x.face_tests == y.face_tests;
}

// The whole stage through the host's run (the QI's walks split too: parts of 64 vertices).
void whole_stage(const Model& m, const SolidScene& scene) {
  SolidRun one;
  CHECK(run_hidden_lines(scene, HiddenMethod::kAuto, FallbackParams{}, &one, false, true, nullptr,
                         nullptr, 64) == Status::kOk);
  CHECK_MSG(!one.pieces.empty(), m.name + ": no pieces");
  CHECK_MSG((one.intersection_stats.segments > 0) == m.crosses,
            m.name + ": " + std::to_string(one.intersection_stats.segments) + " segments");
  CHECK_MSG(!m.crosses || !one.intersections.empty(), m.name + ": no intersection pieces");
  for (uint32_t n : {2u, 3u, 7u}) {
    const Parts parts = threads(n);
    SolidRun run;
    CHECK(run_hidden_lines(scene, HiddenMethod::kAuto, FallbackParams{}, &run, false, true, nullptr,
                           &parts, 64) == Status::kOk);
    const std::string what = m.name + ", " + std::to_string(n) + " parts: ";
    CHECK_MSG(same_pieces(run.pieces, one.pieces), what + "edge pieces");
    CHECK_MSG(same_pieces(run.contour_diagonals, one.contour_diagonals), what + "diagonals");
    CHECK_MSG(same_pieces(run.intersections, one.intersections), what + "intersection pieces");
    CHECK_MSG(run.intersection_faces == one.intersection_faces, what + "intersection faces");
    CHECK_MSG(same_edges(run.edges, one.edges), what + "geometry");
    CHECK_MSG(same_counts(run.intersection_stats, one.intersection_stats), what + "counts");
  }
}

// A piece as the stage's sink saw it, with its geometry.
struct Heard {
  HiddenPiece p;
  Edge3 g;
};
Status hear(void* context, const HiddenPiece& p) {
  static_cast<std::vector<Heard>*>(context)->push_back(Heard{p, *p.geometry});
  return Status::kOk;
}
bool same_heard(const std::vector<Heard>& a, const std::vector<Heard>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    const HiddenPiece &x = a[i].p, &y = b[i].p;
    if (x.edge != y.edge || x.t0 != y.t0 || x.t1 != y.t1 || x.q != y.q || x.hidden != y.hidden ||
        x.tested != y.tested || x.face[0] != y.face[0] || x.face[1] != y.face[1] ||
        x.hatch != y.hatch || std::memcmp(&a[i].g, &b[i].g, sizeof(Edge3)) != 0)
      return false;
  }
  return true;
}

// The core's stage with the end's buffer from ample down to a few pieces a part.
std::vector<Heard> stage(const SolidInput& in, const Parts* parts, size_t end_bytes,
                         HiddenReport* report) {
  HiddenParams hp;
  hp.intersections = true;
  hp.cut.parts = parts;
  hp.qi_part_vertices = 64;
  hp.end_parts_bytes = end_bytes;
  hp.crossing_capacity = 8 * (in.n_edges + 3 * in.n_triangles) + 1024;
  hp.incidence_capacity = 4 * in.n_vertices + 64;
  std::vector<uint64_t> buffer(4 * hidden_lines_first_bytes(in) / 8);
  std::vector<Heard> got;
  CHECK(hidden_lines(in, hp, buffer.data(), buffer.size() * 8,
                     HiddenSink{nullptr, &hear, nullptr, &got}, report) == Status::kOk);
  return got;
}

void stage_alone(const Model& m, const SolidScene& scene) {
  const SolidInput in = solid_input(scene);
  HiddenReport one_r;
  const std::vector<Heard> one = stage(in, nullptr, 0, &one_r);
  CHECK_MSG(one_r.used_qi && (one_r.qi.first_conflicts > 0) == m.crosses,
            m.name + ": the QI walks stop at pierces where solids cross, only there");
  for (uint32_t n : {2u, 3u, 7u})
    for (size_t bytes : {size_t{0}, size_t{4} << 10, size_t{6} << 10, size_t{16} << 10,
                         size_t{64} << 10, size_t{16} << 20}) {
      const Parts parts = threads(n);
      HiddenReport r;
      const std::vector<Heard> got = stage(in, &parts, bytes, &r);
      const std::string what =
          m.name + ", stage, " + std::to_string(n) + " parts, " + std::to_string(bytes) + " bytes";
      CHECK_MSG(same_heard(got, one), what + ": pieces");
      CHECK_MSG(same_counts(r.intersections, one_r.intersections), what + ": counts");
    }
}

// One intersection piece as the sink saw it, with its segment's ends.
struct Seen {
  LinePiece p;
  Edge3 s;
};
Status keep(void* context, const LinePiece& p) {
  static_cast<std::vector<Seen>*>(context)->push_back(Seen{p, *p.segment});
  return Status::kOk;
}

bool same_lines(const std::vector<Seen>& a, const std::vector<Seen>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    const LinePiece &x = a[i].p, &y = b[i].p;
    if (x.edge != y.edge || x.t0 != y.t0 || x.t1 != y.t1 || x.q != y.q || x.hidden != y.hidden ||
        x.face[0] != y.face[0] || x.face[1] != y.face[1] ||
        std::memcmp(&a[i].s, &b[i].s, sizeof(Edge3)) != 0)
      return false;
  }
  return true;
}

// draw_intersections alone, on the closed solids' front faces and on both sides of every face,
// with buffers from none to ample: the small ones make parts fill up and hand the rest of their
// cells to the calling thread (counted in parts_full, which must happen).
void lines_alone(const Model& m, const SolidScene& scene) {
  const SolidInput in = solid_input(scene);
  std::vector<uint64_t> topo_mem(topology_bytes(in) / 8 + 1);
  Topology topo;
  CHECK(build_topology(in, topo_mem.data(), topo_mem.size() * 8, &topo) == Status::kOk);
  std::vector<uint8_t> front(topo.n_triangles);
  classify(&topo, front.data(), in.facing);
  std::vector<uint64_t> grid_mem(face_grid_bytes(topo) / 8 + 1);
  FaceGrid fg;
  CHECK(build_face_grid(topo, grid_mem.data(), grid_mem.size() * 8, &fg) == Status::kOk);
  uint64_t filled = 0;
  for (const uint8_t* hiding :
       {static_cast<const uint8_t*>(front.data()), static_cast<const uint8_t*>(nullptr)}) {
    std::vector<Seen> one;
    IntersectionStats one_st;
    CHECK(draw_intersections(topo, hiding, fg, LineSink{&keep, &one}, &one_st) == Status::kOk);
    CHECK_MSG(!m.crosses || !one.empty(), m.name + ": no lines");
    for (uint32_t n : {2u, 3u, 7u})
      for (size_t bytes : {size_t{0}, size_t{6} << 10, size_t{8} << 10, size_t{12} << 10,
                           size_t{32} << 10, size_t{1} << 20}) {
        const Parts parts = threads(n);
        std::vector<uint64_t> buffer(bytes / 8 + 1);
        std::vector<Seen> got;
        IntersectionStats st;
        CHECK(draw_intersections(topo, hiding, fg, LineSink{&keep, &got}, &st, LineRows{},
                                 LineParts{&parts, buffer.data(), bytes}) == Status::kOk);
        const std::string what = m.name + (hiding ? ", front faces, " : ", both sides, ") +
                                 std::to_string(n) + " parts, " + std::to_string(bytes) + " bytes";
        CHECK_MSG(same_lines(got, one), what + ": pieces");
        CHECK_MSG(same_counts(st, one_st), what + ": counts");
        filled += st.parts_full;
      }
  }
  CHECK_MSG(!m.crosses || filled > 0, m.name + ": no part ever filled its share");
}

}  // namespace

int main() {
  for (const Model& m : models()) {
    SolidScene scene;
    CHECK(project(m.mesh, view(30000, 25000), &scene));
    whole_stage(m, scene);
    stage_alone(m, scene);
    lines_alone(m, scene);
  }
  return check::finish("line_parts");
}
