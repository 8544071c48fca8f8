// haloplot on the host, from its installed package: a 2 x 2 array of cubes drawn twice.
//   1. Haloed lines (the scene as bare edges): CUT finds where two edges cross in the picture,
//      DRAW leaves a gap (the halo) in the farther edge around each crossing.
//   2. Hidden lines (the same cubes as solids, with faces): the parts of edges behind a face
//      are left out.
// It prints every stroke it drew: "s EDGE X0 Y0 X1 Y1" for a haloed span (plot steps) and
// "piece EDGE visible|hidden" for a hidden-line piece, then a count of each.
#include <haloplot/cut/cut.h>
#include <haloplot/draw/draw.h>
#include <haloplot/memory/sized_stage.h>
#include <haloplot/scene/cube_array.h>
#include <haloplot/solid/hidden_lines.h>
#include <haloplot/view/projection.h>

#include <cstdio>
#include <vector>

using namespace haloplot;

namespace {

// The core allocates nothing: every stage works in memory the caller hands it (8-aligned).
std::vector<uint64_t> memory(1 << 17);  // 1 MB, far more than this scene needs

int fail(const char* what, Status s) {
  std::fprintf(stderr, "%s: %s\n", what, status_name(s));
  return 1;
}

int haloed() {
  CubeArrayParams scene;  // the demo scene's cubes, already projected to plot steps
  scene.cubes = 2;
  std::vector<Edge3> edges(cube_array_edges(scene));
  Status s = cube_array(scene, edges.data(), uint32_t(edges.size()));
  if (!ok(s)) return fail("cube_array", s);

  // CUT: plan its grid, then run it in our memory. run_sized asks again with a larger
  // capacity if the crossings do not fit the first guess (StageNeeds).
  CutPlan plan;
  s = plan_cut(edges.data(), uint32_t(edges.size()), CutParams{}, &plan);
  if (!ok(s)) return fail("plan_cut", s);
  CutSet crossings;  // lives at the start of `memory`
  CutStats cut_stats;
  CutStage cut{&plan, edges.data(), &crossings, &cut_stats};
  StageNeeds needs;
  needs.crossings = 16;
  FixedMemory fixed{memory.data(), memory.size() * sizeof(uint64_t)};
  s = run_sized(cut, fixed.memory(), &needs);
  if (!ok(s)) return fail("CUT", s);

  // DRAW: each visible stretch of an edge arrives at the sink as a span.
  std::vector<uint64_t> scratch(draw_scratch_bytes(crossings) / sizeof(uint64_t) + 1);
  uint32_t spans = 0;
  const SpanSink print{[](void* count, const Span& sp) {
                         std::printf("s %u %d %d %d %d\n", sp.edge, sp.x0, sp.y0, sp.x1, sp.y1);
                         ++*static_cast<uint32_t*>(count);
                         return Status::kOk;
                       },
                       &spans};
  DrawParams halo;
  halo.halo = 50;  // plot steps each side of a crossing
  DrawStats draw_stats;
  s = draw(crossings, halo, scratch.data(), scratch.size() * sizeof(uint64_t), print, &draw_stats);
  if (!ok(s)) return fail("DRAW", s);
  std::printf("haloed: %zu edges, %u crossings, %u spans\n", edges.size(), crossings.n_crossings,
              spans);
  return 0;
}

// The cubes as solids: 8 corners each (100 units a side, 125 apart), their 12 edges, and
// their 6 faces as 2 triangles each.
struct Cubes {
  std::vector<Point3> corners;
  std::vector<uint32_t> edge_pairs;  // two corner indices per edge
  std::vector<Triangle> triangles;
};

Cubes solid_cubes(int32_t n) {
  static const uint32_t kFaces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                        {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  Cubes c;
  for (int32_t i = 0; i < n; ++i)
    for (int32_t j = 0; j < n; ++j) {
      const uint32_t base = uint32_t(c.corners.size());
      for (int32_t k = 0; k < 8; ++k)  // corner k: bit 0 is x, bit 1 y, bit 2 z
        c.corners.push_back(
            Point3{i * 125 + (k & 1) * 100, j * 125 + ((k >> 1) & 1) * 100, ((k >> 2) & 1) * 100});
      for (const auto& f : kFaces) {  // outward faces, counter-clockwise seen from outside
        const uint32_t face = uint32_t(c.triangles.size() / 2);
        c.triangles.push_back(Triangle{{base + f[0], base + f[1], base + f[2]}, face});
        c.triangles.push_back(Triangle{{base + f[0], base + f[2], base + f[3]}, face});
      }
      for (uint32_t a = 0; a < 8; ++a)  // the edges join corners one bit apart
        for (uint32_t bit = 1; bit < 8; bit <<= 1)
          if (!(a & bit)) c.edge_pairs.insert(c.edge_pairs.end(), {base + a, base + (a | bit)});
    }
  return c;
}

int hidden() {
  Cubes cubes = solid_cubes(2);
  // Project the corners (azimuth 30, elevation 40) in units of 1/32 step, the host tool's
  // default resolution for models.
  View view;
  view.substep_bits = kDefaultSubstepBits;
  std::vector<Point3> screen(cubes.corners.size());
  Status s =
      project_points(view, cubes.corners.data(), uint32_t(cubes.corners.size()), screen.data());
  if (!ok(s)) return fail("project_points", s);
  SolidInput in;
  in.vertices = screen.data();
  in.n_vertices = uint32_t(screen.size());
  in.edge_pairs = cubes.edge_pairs.data();
  in.n_edges = uint32_t(cubes.edge_pairs.size() / 2);
  in.triangles = cubes.triangles.data();
  in.n_triangles = uint32_t(cubes.triangles.size());

  HiddenParams params;
  params.crossing_capacity = 1000;  // too few: kCrossingCapacity, and the report says how many
  params.incidence_capacity = 64;
  params.intersections = false;  // these cubes do not pass through each other
  uint32_t count[2] = {0, 0};    // visible, hidden
  HiddenSink sink{nullptr,
                  [](void* counts, const HiddenPiece& p) {
                    std::printf("piece %u %s\n", p.edge, p.hidden ? "hidden" : "visible");
                    ++static_cast<uint32_t*>(counts)[p.hidden ? 1 : 0];
                    return Status::kOk;
                  },
                  nullptr, count};
  HiddenReport report;
  s = hidden_lines(in, params, memory.data(), memory.size() * sizeof(uint64_t), sink, &report);
  if (!ok(s)) return fail("hidden_lines", s);
  std::printf("hidden lines: %u edges, %llu crossings, %u visible pieces, %u hidden pieces\n",
              in.n_edges, static_cast<unsigned long long>(report.cut.crossings), count[0],
              count[1]);
  return 0;
}

}  // namespace

int main() { return haloed() != 0 || hidden() != 0 ? 1 : 0; }
