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

#include "demo/cube_array.h"
#include "demo/random_scene.h"
#include "haloplot/band/conductor.h"
#include "haloplot/job/job.h"
#include "haloplot/protocol/frame.h"
#include "haloplot/protocol/job_server.h"
#include "haloplot/protocol/messages.h"
#include "perf_common.h"
#include "pipeline/band_stream.h"
#include "sim/simulator.h"

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
    w.status = job_bytes(spec, Edges{edges.data(), n}, capacity, &b);
    if (!ok(w.status)) return w;
    std::vector<uint64_t> buffer(b.total() / 8 + 1);
    PreparedJob job;
    JobCounters c;
    const double t0 = bench::now_ms();
    w.status = job_prepare(spec, Edges{edges.data(), n}, capacity, buffer.data(), buffer.size() * 8,
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

// The link budget of a streamed Figure 4 on the demo job: each band's edges sent as 4-byte
// scene indices with the 24-byte edge records the upload uses today, in frames of at most
// kMaxPayload bytes (kFrameOverhead each), at 115200 baud 8N1 (11,520 bytes/s), against the
// plot time of the band before it (the next band is received while this one plots).
void link_budget(size_t arena) {
  const std::vector<Edge3> edges = host::cube_array(CubeArrayParams{});
  JobSpec job;
  job.draw = DrawParams{50, HaloMode::kPaper};
  job.machine.kinematics = Kinematics::kCoreXY;
  BandSpec spec;
  spec.draw = job.draw;
  host::BandPlan plan;
  if (!ok(host::plan_streamed_bands(edges, spec, arena, &plan))) return;
  host::PlanStream stream;
  stream.plan = &plan;
  host::SimReport r;
  if (!ok(host::simulate_streamed(job, stream.stream(), plan.margin, arena, nullptr, &r))) return;
  constexpr double kBytesPerSecond = 115200.0 / 10.0;
  const double record = double(kEdgeRecordBytes + 4);
  const double per_frame = double(JobServer::kMaxPayload / size_t(record)) * record;
  const double wire_per_edge = record * (1.0 + double(kFrameOverhead) / per_frame);
  std::printf("\n| band | rows | edges sent | on the wire | upload | plot of the band before |\n");
  std::printf("|---:|---|---:|---:|---:|---:|\n");
  double worst = 0, total_bytes = 0;
  for (size_t k = 0; k < plan.bands.size(); ++k) {
    const double bytes = wire_per_edge * double(plan.bands[k].edges.size());
    total_bytes += bytes;
    const double upload = bytes / kBytesPerSecond;
    double plot = 0;
    if (k > 0) plot = double(r.band_ticks[k] - r.band_ticks[k - 1]) / double(job.machine.tick_hz);
    if (k > 0 && upload / plot > worst) worst = upload / plot;
    std::printf("| %zu | %d-%d | %zu | %s KB | %s s | %s |\n", k, plan.bands[k].y0,
                plan.bands[k].y1 - 1, plan.bands[k].edges.size(), kb(size_t(bytes)).c_str(),
                bench::fmt(upload, 2).c_str(),
                k == 0 ? "(before the plot starts)" : (bench::fmt(plot, 1) + " s").c_str());
  }
  std::printf(
      "\nFigure 4 streamed in %s KB: %zu bands, %s bytes on the wire per edge sent, "
      "%s KB in all (%s s at 115200 baud) for a %s s plot; the first band takes %s s "
      "before the pen moves; after that the upload of a band takes at most %s of the "
      "plot time of the band before it.\n",
      kb(arena).c_str(), plan.bands.size(), bench::fmt(wire_per_edge, 2).c_str(),
      kb(size_t(total_bytes)).c_str(), bench::fmt(total_bytes / kBytesPerSecond, 1).c_str(),
      bench::fmt(double(r.end_tick) / double(job.machine.tick_hz), 0).c_str(),
      bench::fmt(wire_per_edge * double(plan.bands[0].edges.size()) / kBytesPerSecond, 2).c_str(),
      (bench::fmt(100.0 * worst, 2) + " %").c_str());
}

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
  std::printf(
      "| scene | edges | crossings | one band: bytes | bands in %s KB | margin (rows) | "
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
    std::printf(
        "| %s | %zu | %llu | %s KB | %u | %d | %zu | %s | %s | %s | %s |\n", s.name.c_str(),
        s.edges.size(), (unsigned long long)w.crossings, kb(w.bytes).c_str(), b.stats.bands,
        b.stats.margin, b.stats.peak_bytes,
        bench::fmt(double(b.stats.edge_reads) / double(s.edges.size()), 1).c_str(), verdict.c_str(),
        bench::fmt(b.ms / std::max(w.ms, 1e-3), 2).c_str(),
        bench::fmt(double(b.stats.path.pen_up_length) / double(std::max<uint64_t>(w.pen_up, 1)), 2)
            .c_str());
    std::fflush(stdout);
  }
  link_budget(arena);
  return 0;
}
