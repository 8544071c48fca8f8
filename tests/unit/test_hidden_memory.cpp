// What a hidden-line run holds does not grow with the capacities it was first given: the host
// asks with a guess (its CUTSET capacity on a torus is several times the records CUT stores,
// its incidence capacity one per vertex), and the stages after CUT must not start beyond the
// unwritten rest of those (solid/hidden_lines.h: the CUTSET and the incidences are packed down
// to what they hold). The tail handed to the sink, which lies above everything the run keeps
// while it emits its pieces, must be the same with the exact capacities and with capacities
// ten times as large; and the pieces the same.
//
// And what a run writes at all: a host's buffer is fresh pages, each resident from its first
// write to the end of the run, so the highest byte written (not the report's high-water mark,
// which counts capacities never written) is the run's resident memory. Outside a band, CUT's
// copy of the edges is given back with its scratch and the topology's build gets no room for
// the stars it does not build (its scratch lies at the top of its room): on a mesh of the
// 1M-triangle torus's shape the run writes 124 bytes a triangle, the top of the build's room
// (before both, 172: the later stages' blocks, above CUT's edges). Any size of that mesh gives
// the same figure; the bound is 130. Three tori that pierce one another, with the intersection
// lines drawn (the walks stopping at pierces): 149 bytes a triangle at 10,080 triangles (154 at
// 2,520, 146 at 40,320 and at 161,280; the whole plot of 1M triangles peaks higher: the host's
// pieces and scene come on top, docs/reports/performance.md section 11); the bound is 155.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "check.h"
#include "haloplot/solid/hidden_lines.h"
#include "support/solid_scenes.h"

namespace {

using namespace haloplot;

struct Run {
  size_t tail = 0;
  std::vector<int64_t> pieces;  // edge, t0, t1, q of each piece in order
  static void begin(void* ctx, uint8_t* tail, size_t, const Edge3*) {
    static_cast<Run*>(ctx)->tail = size_t(tail - static_cast<Run*>(ctx)->base);
  }
  static Status piece(void* ctx, const HiddenPiece& p) {
    static_cast<Run*>(ctx)->pieces.insert(static_cast<Run*>(ctx)->pieces.end(),
                                          {int64_t{p.edge}, p.t0, p.t1, int64_t{p.q}});
    return Status::kOk;
  }
  uint8_t* base = nullptr;
};

Status run(const SolidInput& in, uint32_t crossings, uint32_t incidences,
           std::vector<uint64_t>* buffer, Run* out, HiddenReport* r) {
  HiddenParams p;
  p.intersections = true;
  p.crossing_capacity = crossings;
  p.incidence_capacity = incidences;
  out->base = reinterpret_cast<uint8_t*>(buffer->data());
  return hidden_lines(in, p, buffer->data(), buffer->size() * 8,
                      HiddenSink{&Run::begin, &Run::piece, nullptr, out}, r);
}

void check_scene(const char* name, const solid_scenes::Mesh& m, const View& view) {
  host::SolidScene scene;
  CHECK_MSG(solid_scenes::project(m, view, &scene), name);
  const SolidInput in = host::solid_input(scene);
  std::vector<uint64_t> buffer(hidden_lines_first_bytes(in) * 4 / 8 + 1);
  // The exact counts, from a run asked with none.
  Run probe;
  HiddenReport r;
  uint32_t crossings = 0, incidences = 0;
  for (int i = 0; i < 3; ++i) {
    const Status s = run(in, crossings, incidences, &buffer, &probe, &r);
    if (s == Status::kCrossingCapacity) crossings = uint32_t(r.cut.crossings + r.cut.near_misses);
    if (s == Status::kIncidenceCapacity) incidences = r.incidences_needed;
    probe = Run{};
  }
  Run exact, large;
  HiddenReport re, rl;
  CHECK_MSG(run(in, crossings, incidences, &buffer, &exact, &re) == Status::kOk, name);
  CHECK_MSG(
      run(in, 10 * crossings + 1000, 10 * incidences + 1000, &buffer, &large, &rl) == Status::kOk,
      name);
  CHECK_MSG(re.used_qi && rl.used_qi, name);
  CHECK_MSG(exact.tail > 0 && exact.tail == large.tail, name);
  CHECK_MSG(exact.pieces == large.pieces && !exact.pieces.empty(), name);
  // The larger capacities are carved, only not held: CUT's block does grow (the high-water mark
  // need not: with few crossings, the QI's stage holds more than CUT's).
  CHECK_MSG(rl.bytes_cut > re.bytes_cut, name);
}

// The highest byte a run writes in a buffer of `bytes`, prefilled twice (0x00 and 0xff: a byte
// written with the fill's own value is missed by one fill, not by both).
size_t written_extent(const SolidInput& in, size_t bytes, bool lines = false) {
  size_t extent = 0;
  for (const uint8_t fill : {uint8_t{0x00}, uint8_t{0xff}}) {
    std::vector<uint64_t> buffer(bytes / 8 + 1);
    uint8_t* base = reinterpret_cast<uint8_t*>(buffer.data());
    for (size_t i = 0; i < buffer.size() * 8; ++i) base[i] = fill;
    Run out;
    HiddenReport r;
    HiddenParams p;  // the host's hidden-removed plot: first-guess capacities, no lines
    p.crossing_capacity = 4 * (in.n_edges + 3 * in.n_triangles) + 1024;
    p.incidence_capacity = in.n_vertices + 64;
    p.intersections = lines;  // where faces cross, the plot draws where
    out.base = base;
    CHECK(hidden_lines(in, p, buffer.data(), buffer.size() * 8,
                       HiddenSink{&Run::begin, &Run::piece, nullptr, &out}, &r) == Status::kOk);
    CHECK(r.used_qi && !out.pieces.empty());
    size_t top = buffer.size() * 8;
    while (top > 0 && base[top - 1] == fill) --top;
    if (top > extent) extent = top;
  }
  return extent;
}

// A torus of quads (two triangles each, the diagonal undrawn) in the 1M-triangle benchmark's
// proportions (R / r = 2.5, twice as many quads around as across), seen from (30, 25) degrees.
void check_written(int around, int across, size_t bytes_a_triangle) {
  solid_scenes::Mesh torus;
  solid_scenes::torus(&torus, 0, 0, 0, 300000, 120000, around, across, true);
  host::SolidScene scene;
  CHECK(solid_scenes::project(torus, solid_scenes::view(30000, 25000), &scene));
  const SolidInput in = host::solid_input(scene);
  const size_t extent = written_extent(in, hidden_lines_first_bytes(in));
  std::printf("torus %d x %d: %u triangles, %zu bytes written, %.1f a triangle\n", around, across,
              in.n_triangles, extent, double(extent) / in.n_triangles);
  CHECK_MSG(extent <= bytes_a_triangle * in.n_triangles, "bytes written a triangle");
}

// Three tori through one another (tests/support/model_files.sh's pierced_tori_obj): torus k
// is the upright torus turned by k cyclic shifts of the axes (a rotation) and moved, so each
// passes through the other two. The QI stops its walks where edges pass through faces and the
// intersection lines are drawn, as `plot` draws them; its face grid holds more faces a cell
// than the torus's (each torus has a third of the faces over as much paper).
void check_pierced(int around, int across, size_t bytes_a_triangle) {
  solid_scenes::Mesh tori;
  for (int k = 0; k < 3; ++k) {
    solid_scenes::Mesh one;
    solid_scenes::torus(&one, 0, 0, 0, 300000, 100000, around, across, true);
    const uint32_t base = uint32_t(tori.v.size());
    for (const Point3& p : one.v) {
      const int32_t c[3] = {p.x, p.y, p.z};
      tori.add(c[(3 - k) % 3] + 42000 * k, c[(4 - k) % 3] - 26000 * k, c[(5 - k) % 3] + 34000 * k);
    }
    for (std::vector<uint32_t> f : one.faces) {
      for (uint32_t& x : f) x += base;
      tori.face(f);
    }
  }
  host::SolidScene scene;
  CHECK(solid_scenes::project(tori, solid_scenes::view(30000, 25000), &scene));
  const SolidInput in = host::solid_input(scene);
  const size_t extent = written_extent(in, hidden_lines_first_bytes(in), true);
  std::printf("pierced tori 3 x %d x %d: %u triangles, %zu bytes written, %.1f a triangle\n",
              around, across, in.n_triangles, extent, double(extent) / in.n_triangles);
  CHECK_MSG(extent <= bytes_a_triangle * in.n_triangles, "bytes written a triangle (pierced)");
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3) {  // a size's figures only: hidden_memory AROUND ACROSS
    check_pierced(std::atoi(argv[1]), std::atoi(argv[2]), 1000);
    return check::finish("hidden_memory");
  }
  check_written(200, 100, 130);
  check_pierced(60, 28, 155);
  solid_scenes::Mesh torus, spheres;
  solid_scenes::torus(&torus, 0, 0, 0, 300000, 120000, 60, 30);
  solid_scenes::sphere(&spheres, -250000, 0, 0, 150000, 16, 24);
  solid_scenes::sphere(&spheres, 250000, 50000, 60000, 150000, 16, 24);
  check_scene("torus", torus, solid_scenes::view(30000, 25000));
  check_scene("two spheres", spheres, solid_scenes::view(-40000, 35000));
  return check::finish("hidden_memory");
}
