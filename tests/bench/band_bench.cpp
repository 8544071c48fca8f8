// Band benchmark: memory that does not grow with the scene. Every scene is plotted in the same
// fixed arena (the controller's 64 KB by default) and, as the peer, in one band with memory
// sized for the whole scene (the core's own job_bytes for the same drawing). Reports, per scene:
// the arena's peak, the bands, the margin, the pieces (checked equal to the one-band run's),
// the host time of both runs and their ratio, and the pen-up travel of both plans.
// Usage: band_bench [ARENA_BYTES] > table.md
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <tuple>
#include <vector>

#include "band/conductor.h"
#include "demo/cube_array.h"
#include "demo/random_scene.h"
#include "job/job.h"
#include "perf_common.h"

using namespace haloplot;

namespace {

struct Run {
  Status status = Status::kOk;
  std::vector<std::tuple<uint32_t, int64_t, int64_t>> pieces;
  BandStats stats;
  double ms = 0;
};

Run banded(const std::vector<Edge3>& edges, const DrawParams& draw, size_t arena_bytes) {
  Run r;
  BandSpec spec;
  spec.draw = draw;
  if (draw.mode == HaloMode::kExact) spec.cut.reach = draw.halo;  // near misses too
  std::vector<uint64_t> arena(arena_bytes / 8);
  BandConductor bc;
  bc.set_observer(PieceObserver{[](void* ctx, const BandPiece& p) {
                                  static_cast<Run*>(ctx)->pieces.emplace_back(p.edge, p.t0, p.t1);
                                },
                                &r});
  const double t0 = bench::now_ms();
  r.status = bc.begin(spec, array_edge_source(edges.data(), uint32_t(edges.size())), arena.data(),
                      arena.size() * 8);
  while (ok(r.status) && !bc.done()) {
    const PathPoint* p = nullptr;
    uint32_t n = 0;
    r.status = bc.next(&p, &n);
  }
  r.ms = bench::now_ms() - t0;
  r.stats = bc.stats();
  std::sort(r.pieces.begin(), r.pieces.end());
  return r;
}

// The peer: the whole scene in one job buffer (core/job), as the controller did before bands.
struct Whole {
  Status status = Status::kOk;
  size_t bytes = 0;
  uint64_t pen_up = 0, crossings = 0;
  double ms = 0;
};

Whole whole(const std::vector<Edge3>& edges, const DrawParams& draw) {
  Whole w;
  JobSpec spec;
  spec.draw = draw;
  spec.cut.compact_cells = false;  // as the bands use
  if (draw.mode == HaloMode::kExact) spec.cut.reach = draw.halo;
  const uint32_t n = uint32_t(edges.size());
  uint32_t capacity = 4 * n + 1024;
  // Twice: the second run sized by the records the first found, so the bytes are the need.
  for (int attempt = 0; attempt < 2; ++attempt) {
    JobBytes b;
    w.status = job_bytes(spec, edges.data(), n, capacity, &b);
    if (!ok(w.status)) return w;
    std::vector<uint64_t> buffer(b.total() / 8 + 1);
    PreparedJob job;
    JobCounters c;
    const double t0 = bench::now_ms();
    w.status = job_prepare(spec, edges.data(), n, capacity, buffer.data(), buffer.size() * 8,
                           &job, &c);
    w.ms = bench::now_ms() - t0;
    w.bytes = b.total();
    w.pen_up = c.path.pen_up_length;
    w.crossings = c.cut.crossings;
    if (w.status != Status::kCrossingCapacity && !ok(w.status)) break;
    capacity = uint32_t(c.cut.crossings + c.cut.near_misses);
  }
  return w;
}

std::string kb(size_t bytes) { return bench::fmt(double(bytes) / 1024.0, 1); }

}  // namespace

int main(int argc, char** argv) {
  const size_t arena = argc > 1 ? size_t(std::atol(argv[1])) : 64 * 1024;
  struct Scene {
    std::string name;
    std::vector<Edge3> edges;
    DrawParams draw;
  };
  std::vector<Scene> scenes;
  // Cube arrays drawn as Figure 4 draws its cubes (the plot grows with the array, the cubes
  // keep their size), halo 50 with the paper's gap.
  for (int32_t cubes : {9, 28, 29, 91}) {
    CubeArrayParams p;
    p.cubes = cubes;
    p.width = 20000 * cubes / 28;
    p.height = 16000 * cubes / 28;
    scenes.push_back({std::to_string(cubes) + " x " + std::to_string(cubes) + " cubes",
                      host::cube_array(p), DrawParams{50, HaloMode::kPaper}});
  }
  // The paper's EDGE scenes at about one crossing per edge (K is about 0.19 N^2 L^2) on the
  // 2^20-step square, halo 200 steps, with the exact gap and with the paper's.
  const std::pair<uint32_t, int64_t> randoms[] = {{1000, 72500}, {10000, 22900}, {100000, 7250}};
  for (HaloMode mode : {HaloMode::kExact, HaloMode::kPaper})
    for (const auto& [n, l] : randoms)
      scenes.push_back({"random, N = " + std::to_string(n) +
                            (mode == HaloMode::kExact ? ", exact gap" : ", paper's gap"),
                        host::paper_random(n, l, 7), DrawParams{200, mode}});
  std::printf("| scene | edges | crossings | one band: bytes | bands in %s KB | margin (rows) | "
              "peak bytes | edges read / N | pieces equal | time banded / one band | pen-up "
              "banded / one band |\n",
              kb(arena).c_str());
  std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|\n");
  for (const Scene& s : scenes) {
    const DrawParams& draw = s.draw;
    const Whole w = whole(s.edges, draw);
    const Run b = banded(s.edges, draw, arena);
    // The one-band pieces, for the equality check (the conductor given room for everything).
    const Run one = banded(s.edges, draw, std::max<size_t>(w.bytes * 2, arena));
    const bool equal = ok(b.status) && ok(one.status) && b.pieces == one.pieces;
    std::string verdict = equal ? "yes" : "NO";
    if (!ok(b.status)) {  // the smallest power-of-two arena that holds this scene's densest row
      size_t fits = arena;
      Run r;
      do {
        fits *= 2;
        r = banded(s.edges, draw, fits);
      } while (r.status == Status::kArenaTooSmall && fits < (size_t{64} << 20));
      verdict = std::string(status_name(b.status)) + " (one row needs " +
                std::to_string(b.stats.need_bytes) + " bytes; " + kb(fits) + " KB plots it" +
                (ok(r.status) && r.pieces == one.pieces ? ", pieces equal" : ", pieces differ") +
                ")";
    }
    std::printf("| %s | %zu | %llu | %s KB | %u | %d | %zu | %s | %s | %s | %s |\n",
                s.name.c_str(), s.edges.size(), (unsigned long long)w.crossings,
                kb(w.bytes).c_str(), b.stats.bands, b.stats.margin, b.stats.peak_bytes,
                bench::fmt(double(b.stats.edge_reads) / double(s.edges.size()), 1).c_str(),
                verdict.c_str(),
                bench::fmt(b.ms / std::max(w.ms, 1e-3), 2).c_str(),
                bench::fmt(double(b.stats.path.pen_up_length) /
                               double(std::max<uint64_t>(w.pen_up, 1)),
                           2)
                    .c_str());
    std::fflush(stdout);
  }
  return 0;
}
