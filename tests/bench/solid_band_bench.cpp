// Solid band benchmark: a solid's hidden lines in a fixed arena. Solid cube arrays (N x N
// cubes drawn as the demo draws them, view 30,25, hidden-dashed) are plotted by the band
// conductor's solid stage in each arena given, and in one band; the peer for time is the
// whole-model run (core/include/haloplot/solid/hidden_lines.h: QI on the whole model in one buffer,
// the way the controller works a solid that fits). Reports, per scene and arena: the bands, the
// arena's peak, whether every stroke equals the one-band run's and the visible runs equal the QI
// run's, the host time against the whole-model run, and the pen-up travel against one band. Usage:
// solid_band_bench ARENA_BYTES... > table.md
#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <tuple>
#include <vector>

#include "haloplot/band/conductor.h"
#include "perf_common.h"
#include "pipeline/solid_pipeline.h"
#include "support/solid_refs.h"
#include "support/solid_scenes.h"

using namespace haloplot;
using namespace haloplot::host;

namespace {

using solid_refs::Stroke;

struct Run {
  Status status = Status::kOk;
  std::vector<Stroke> strokes;
  std::vector<std::array<int64_t, 8>> lines;  // hatch strokes: the line's ends, then t0, t1
  BandStats stats;
  double ms = 0;
};

Run banded(const SolidInput& in, bool closed, size_t arena_bytes,
           SolidMode mode = SolidMode::kHiddenDashed, const HatchParams* hatch = nullptr) {
  Run r;
  BandSpec spec;
  spec.hatch = hatch != nullptr;
  if (hatch != nullptr) spec.hatch_params = *hatch;
  spec.haloed = false;
  spec.style = StrokeStyle{mode, 160, 80};
  spec.intersections = true;  // as a job draws by default (none cross in a cube array)
  spec.cut.compact_cells = false;
  std::vector<uint64_t> arena(arena_bytes / 8);
  BandConductor bc;
  bc.set_observer(PieceObserver{[](void* ctx, const BandPiece& p) {
                                  Run* self = static_cast<Run*>(ctx);
                                  if (p.line != nullptr)
                                    self->lines.push_back({p.line->a.x, p.line->a.y, p.line->a.z,
                                                           p.line->b.x, p.line->b.y, p.line->b.z,
                                                           p.t0, p.t1});
                                  else
                                    self->strokes.emplace_back(p.edge, p.t0, p.t1);
                                },
                                &r});
  const double t0 = bench::now_ms();
  r.status = bc.begin_solid(spec, array_solid_source(&in, closed), arena.data(), arena.size() * 8);
  if (ok(r.status)) r.status = run_all_bands(bc);
  r.ms = bench::now_ms() - t0;
  r.stats = bc.stats();
  std::sort(r.strokes.begin(), r.strokes.end());
  // Hatch strokes of one line that meet at a band border, joined.
  std::sort(r.lines.begin(), r.lines.end());
  std::vector<std::array<int64_t, 8>> joined;
  for (const auto& l : r.lines)
    if (!joined.empty() && std::equal(l.begin(), l.begin() + 6, joined.back().begin()) &&
        joined.back()[7] == l[6])
      joined.back()[7] = l[7];
    else
      joined.push_back(l);
  r.lines = joined;
  return r;
}

// A banded run's cells of a table row, against one band's run.
struct Cells {
  std::string bands, peak = "-", pen = "-";
};
Cells cells(const Run& b, const Run& one) {
  Cells c;
  if (!ok(b.status)) {
    c.bands = std::string(status_name(b.status)) + " (a band one row high needs " +
              std::to_string(b.stats.need_bytes) + " bytes)";
    return c;
  }
  c.bands = std::to_string(b.stats.bands);
  c.peak = std::to_string(b.stats.peak_bytes);
  c.pen = bench::fmt(double(b.stats.path.pen_up_length) /
                         double(std::max<uint64_t>(one.stats.path.pen_up_length, 1)),
                     2);
  return c;
}

// N x N solid cubes at view 30,25, the plot area the same for every N.
bool cube_array_scene(int n, SolidScene* scene) {
  solid_scenes::Mesh m;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      solid_scenes::box(&m, i * 3000, j * 3000, 0, i * 3000 + 2000, j * 3000 + 2000, 2000);
  return solid_scenes::project(m, solid_scenes::view(30000, 25000), scene);
}

// The same arrays hatched (3 mm at 80 steps/mm): bands, peak, the hatching against one band's.
void hatched_table(const std::vector<size_t>& arenas) {
  std::printf(
      "\n| cubes, hatched | arena | bands | peak bytes | strokes and hatching equal one band | "
      "hatch strokes | pen-up banded / one band |\n");
  std::printf("|---|---:|---:|---:|---|---:|---:|\n");
  HatchParams hp;
  hp.spacing = 240;
  hp.angle_mdeg = 30000;
  hp.min_length = 1;
  for (int n : {3, 10, 14, 20, 28}) {
    SolidScene scene;
    if (!cube_array_scene(n, &scene)) return;
    const SolidInput in = solid_input(scene);
    const bool closed = model_closed(scene);
    const Run one = banded(in, closed, size_t{1} << 30, SolidMode::kHiddenDashed, &hp);
    for (size_t arena : arenas) {
      const Run b = banded(in, closed, arena, SolidMode::kHiddenDashed, &hp);
      const Cells c = cells(b, one);
      const std::string equal = !ok(b.status)                                      ? "-"
                                : b.strokes == one.strokes && b.lines == one.lines ? "yes"
                                                                                   : "NO";
      std::printf("| %d x %d | %zu KB | %s | %s | %s | %zu | %s |\n", n, n, arena >> 10,
                  c.bands.c_str(), c.peak.c_str(), equal.c_str(), one.lines.size(), c.pen.c_str());
      std::fflush(stdout);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<size_t> arenas;
  for (int i = 1; i < argc; ++i) arenas.push_back(size_t(std::atol(argv[i])));
  if (arenas.empty()) arenas = {64 * 1024, 96 * 1024};
  std::printf(
      "| cubes | vertices / edges / triangles | arena | bands | peak bytes | strokes equal one "
      "band | visible equal QI | time banded / whole-model QI | pen-up banded / one band |\n");
  std::printf("|---|---:|---:|---:|---:|---|---|---:|---:|\n");
  for (int n : {3, 10, 14, 20, 28}) {
    SolidScene scene;
    if (!cube_array_scene(n, &scene)) return 1;
    const SolidInput in = solid_input(scene);
    const bool closed = model_closed(scene);
    SolidRun qi;
    const double q0 = bench::now_ms();
    const Status qs = run_hidden_lines(scene, HiddenMethod::kAuto, FallbackParams{}, &qi);
    const double qi_ms = bench::now_ms() - q0;
    std::vector<Stroke> qi_visible;
    for (const SolidPiece& p : qi.pieces)
      if (!p.hidden) qi_visible.emplace_back(p.edge, p.t0, p.t1);
    qi_visible = solid_refs::joined(qi_visible);
    const Run one = banded(in, closed, size_t{1} << 30);
    // The visible runs of one band (hidden-removed: the strokes are the visible pieces).
    const Run removed = banded(in, closed, size_t{1} << 30, SolidMode::kHiddenRemoved);
    const std::string vis =
        ok(qs) && ok(removed.status) && solid_refs::joined(removed.strokes) == qi_visible ? "yes"
                                                                                          : "NO";
    for (size_t arena : arenas) {
      const Run b = banded(in, closed, arena);
      const Cells c = cells(b, one);
      const std::string &bands = c.bands, &peak = c.peak, &pen = c.pen;
      const std::string equal = !ok(b.status) ? "-" : b.strokes == one.strokes ? "yes" : "NO";
      const std::string time = !ok(b.status) ? "-" : bench::fmt(b.ms / std::max(qi_ms, 1e-3), 2);
      std::printf("| %d x %d | %u / %u / %u | %zu KB | %s | %s | %s | %s | %s | %s |\n", n, n,
                  in.n_vertices, in.n_edges, in.n_triangles, arena >> 10, bands.c_str(),
                  peak.c_str(), equal.c_str(), vis.c_str(), time.c_str(), pen.c_str());
      std::fflush(stdout);
    }
  }
  hatched_table(arenas);
  return 0;
}
