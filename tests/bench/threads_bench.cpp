// The host's threads, measured side by side in one run: one thread against N (the core's parts,
// memory/parts.h, on host threads) for the hidden-line stage of a torus of about 1M triangles
// as `plot --mode hidden-removed` runs it (run_hidden_lines: topology, classes, CUT, incidences,
// QI, intersection lines, the pieces), for CUT alone on that torus's edges (its share of the
// stage), and for CUT and DRAW of the paper's random scene (N = 50,000, L = 0.01), the haloed
// path. Each measurement alternates the thread counts, RUNS rounds; shown is each one's fastest
// round, wall and CPU (user + system of the whole process, every thread). The results are
// compared too: the same pieces, the same CUTSET, with any thread count.
//   threads_bench [QUADS_AROUND QUADS_ACROSS [RUNS [THREADS]]]   (default 1000 500 3 2)
// Prints a Markdown table (docs/reports/performance.md, "Threads").
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "bench/perf_common.h"
#include "demo/random_scene.h"
#include "haloplot/solid/classify.h"
#include "haloplot/solid/face_grid.h"
#include "haloplot/solid/hidden_lines.h"
#include "haloplot/solid/incidence.h"
#include "haloplot/solid/qi.h"
#include "haloplot/solid/topology.h"
#include "pipeline/host_pipeline.h"
#include "pipeline/solid_pipeline.h"
#include "pipeline/thread_parts.h"
#include "support/solid_scenes.h"

using namespace haloplot;
using namespace haloplot::host;
using namespace solid_scenes;

namespace {

struct Time {
  double wall = 1e300, cpu = 1e300;  // ms, the fastest round's
};

double cpu_ms() {
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) / 1e6;
}

// Runs f(parts) for one thread and for `threads`, alternating, `runs` rounds; before(), if
// given, untimed before each run (a copy of the input that the run then takes over, as `plot`
// hands its edges to host_cut without copying them).
void measure(int runs, uint32_t threads, const std::function<bool(const Parts*)>& f, Time* one,
             Time* many, const std::function<void()>& before = nullptr) {
  for (int r = 0; r < runs; ++r)
    for (Time* t : {one, many}) {
      const Parts* parts = thread_parts(t == one ? 1 : threads);
      if (before) before();
      const double w0 = bench::now_ms(), c0 = cpu_ms();
      if (!f(parts)) {
        std::fprintf(stderr, "threads_bench: a run failed\n");
        std::exit(1);
      }
      const double w = bench::now_ms() - w0;
      // The pool's workers spin a moment after a run before they sleep (thread_parts.cpp),
      // and the kernel adds a running thread's time to the process clock only at a tick or a
      // switch: read the clock once they sleep, so it holds their spin too.
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      const double c = cpu_ms() - c0;
      if (w < t->wall) t->wall = w;
      if (c < t->cpu) t->cpu = c;
    }
}

void row(const std::string& what, const Time& one, const Time& many, bool equal) {
  std::printf("| %s | %s | %s | %s | %s | %s | %s | %s |\n", what.c_str(),
              bench::fmt(one.wall, 1).c_str(), bench::fmt(many.wall, 1).c_str(),
              bench::fmt(one.wall / many.wall, 2).c_str(), bench::fmt(one.cpu, 1).c_str(),
              bench::fmt(many.cpu, 1).c_str(), bench::fmt(many.cpu / one.cpu, 2).c_str(),
              equal ? "yes" : "NO");
  std::fflush(stdout);
}

bool same_pieces(const SolidRun& a, const SolidRun& b) {
  auto same = [](const std::vector<SolidPiece>& x, const std::vector<SolidPiece>& y) {
    if (x.size() != y.size()) return false;
    for (size_t i = 0; i < x.size(); ++i)
      if (x[i].edge != y[i].edge || x[i].t0 != y[i].t0 || x[i].t1 != y[i].t1 || x[i].q != y[i].q ||
          x[i].hidden != y[i].hidden)
        return false;
    return true;
  };
  return same(a.pieces, b.pieces) && same(a.contour_diagonals, b.contour_diagonals) &&
         same(a.intersections, b.intersections);
}

bool same_cut(const HostCut& a, const HostCut& b) {
  const CutSet &x = a.set, &y = b.set;
  return x.n_edges == y.n_edges && x.n_crossings == y.n_crossings &&
         std::memcmp(x.first, y.first, (size_t{x.n_edges} + 1) * 4) == 0 &&
         std::memcmp(x.crossings, y.crossings, size_t{x.n_crossings} * sizeof(Crossing)) == 0;
}

// What the stage's CUT and QI propagation read, built once as the stage builds them: the
// topology and its classes, its edges and the marked ones (the pairs CUT tests), CUT, the
// incidences.
struct QiInputs {
  std::vector<uint64_t> topo_mem, inc_mem;
  Topology topo;
  std::vector<uint8_t> front;
  std::vector<Edge3> edges;
  std::vector<uint32_t> marked;
  HostCut cut;
  Incidences inc;
};

bool qi_inputs(const SolidScene& scene, QiInputs* q) {
  const SolidInput in = solid_input(scene);
  q->topo_mem.assign(topology_bytes(in) / 8 + 1, 0);
  if (build_topology(in, q->topo_mem.data(), q->topo_mem.size() * 8, &q->topo) != Status::kOk)
    return false;
  q->front.assign(q->topo.n_triangles, 0);
  classify(&q->topo, q->front.data(), in.facing);
  q->edges.resize(q->topo.n_edges);
  for (uint32_t e = 0; e < q->topo.n_edges; ++e) q->edges[e] = q->topo.edge3(e);
  q->marked.assign((size_t{q->topo.n_edges} + 31) / 32, 0);
  mark_crossing_edges(q->topo, q->marked.data());
  CutParams cp;
  cp.marked = q->marked.data();
  if (host_cut(q->edges, cp, &q->cut) != Status::kOk) return false;
  const uint32_t capacity = q->topo.n_vertices + 64;
  q->inc_mem.assign(incidence_bytes(q->topo, capacity) / 8 + 1, 0);
  uint32_t needed = 0;
  return find_incidences(q->topo, capacity, q->inc_mem.data(), q->inc_mem.size() * 8, &q->inc,
                         &needed) == Status::kOk;
}

struct QiRun {
  std::vector<uint64_t> mem;
  QiState state;
  QiStats stats;
};

bool same_qi(const Topology& topo, const QiRun& a, const QiRun& b) {
  return std::memcmp(a.state.base, b.state.base, size_t{topo.n_vertices} * 4) == 0 &&
         std::memcmp(a.state.q_at_v0, b.state.q_at_v0, size_t{topo.n_edges} * 4) == 0 &&
         a.stats.conflicts == b.stats.conflicts && a.stats.ray_casts == b.stats.ray_casts;
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 2 ? std::atoi(argv[1]) : 1000, k = argc > 2 ? std::atoi(argv[2]) : 500;
  const int runs = argc > 3 ? std::atoi(argv[3]) : 3;
  const uint32_t threads = argc > 4 ? uint32_t(std::atoi(argv[4])) : 2;
  View v = view(30000, 25000);
  v.substep_bits = kDefaultSubstepBits;
  SolidScene scene;
  {
    Mesh m;
    torus(&m, 0, 0, 0, 600000, 250000, n, k);
    if (!project(m, v, &scene)) return 1;
  }
  const std::string t = std::to_string(threads);
  std::printf(
      "| work | wall ms, 1 thread | wall ms, %s | wall 1 / %s | CPU ms, 1 thread | CPU ms, "
      "%s | CPU %s / 1 | results equal |\n",
      t.c_str(), t.c_str(), t.c_str(), t.c_str());
  std::printf("|---|---:|---:|---:|---:|---:|---:|---|\n");
  FallbackParams kira;
  kira.use_classes = kira.use_vc = true;
  SolidRun runs_of[2];
  Time one, many;
  measure(
      runs, threads,
      [&](const Parts* p) {
        SolidRun& r = runs_of[p == nullptr ? 0 : 1];
        return run_hidden_lines(scene, HiddenMethod::kAuto, kira, &r, false, true, nullptr, p) ==
               Status::kOk;
      },
      &one, &many);
  row("hidden-line stage, torus of " + std::to_string(scene.triangles.size()) + " triangles", one,
      many, same_pieces(runs_of[0], runs_of[1]));
  // The QI propagation alone, in its parts (solid/qi.h's QiSplit); its face grid, built
  // first on one thread, timed apart.
  QiInputs qin;
  if (!qi_inputs(scene, &qin)) return 1;
  // The stage's CUT alone: its edges, the marked ones paired with the rest.
  const std::vector<Edge3>& edges = qin.edges;
  HostCut cuts[2];
  Time cut_one, cut_many;
  std::vector<Edge3> handed;
  measure(
      runs, threads,
      [&](const Parts* p) {
        CutParams cp;
        cp.parts = p;
        cp.marked = qin.marked.data();
        cp.compact_cells = false;  // as the stage's (solid/hidden_lines.cpp)
        return host_cut(std::move(handed), cp, &cuts[p == nullptr ? 0 : 1]) == Status::kOk;
      },
      &cut_one, &cut_many, [&] { handed = edges; });
  uint32_t n_marked = 0;
  for (uint32_t w : qin.marked) n_marked += uint32_t(__builtin_popcount(w));
  row("its CUT alone (" + std::to_string(edges.size()) + " edges, " + std::to_string(n_marked) +
          " marked, " + std::to_string(cuts[0].set.n_crossings) + " crossings)",
      cut_one, cut_many, same_cut(cuts[0], cuts[1]));
  QiRun qis[2];
  Time qi_one, qi_many;
  measure(
      runs, threads,
      [&](const Parts* p) {
        QiRun& q = qis[p == nullptr ? 0 : 1];
        q.mem.assign(qi_bytes(qin.topo) / 8 + 1, 0);
        return propagate_qi(qin.topo, qin.front.data(), qin.cut.set, qin.inc, q.mem.data(),
                            q.mem.size() * 8, &q.state, &q.stats, false,
                            QiSplit{kQiPartVertices, p}) == Status::kOk;
      },
      &qi_one, &qi_many);
  row("its QI propagation alone (" + std::to_string(qis[0].stats.components) + " parts, " +
          std::to_string(qis[0].stats.edges_walked) + " edges walked)",
      qi_one, qi_many, same_qi(qin.topo, qis[0], qis[1]));
  double grid_ms = 1e300;
  for (int r = 0; r < runs; ++r) {
    std::vector<uint64_t> g(face_grid_bytes(qin.topo) / 8 + 1);
    FaceGrid fg;
    const double c0 = cpu_ms();
    if (build_face_grid(qin.topo, g.data(), g.size() * 8, &fg) != Status::kOk) return 1;
    grid_ms = std::min(grid_ms, cpu_ms() - c0);
  }
  // Where CUT's time goes on one thread: what the parts split (the cell loop, the sorting)
  // and what stays serial (the cell lists, the grouping's scatter).
  CutParams staged;
  staged.marked = qin.marked.data();
  staged.compact_cells = false;
  const bench::CutTiming phases = bench::time_cut(edges, staged, runs);
  // The shares of the stage's two largest steps; every step of the stage but the pieces' hand
  // over to the host's sink (and classify, a few ms) now runs in parts (bench_threads.sh says
  // which), so no bound from these two alone is stated.
  const double cut_share = cut_one.cpu / one.cpu, qi_share = qi_one.cpu / one.cpu;
  std::fprintf(stderr,
               "Shares of the stage, 1 thread (CPU): CUT %.0f %%, the QI propagation %.0f %%. "
               "CUT's phases (wall, median of %d): plan and cell lists %.0f ms, pairs %.0f ms, "
               "grouping and sorting %.0f ms; the QI's face grid %.0f ms (one thread) before "
               "its walks",
               100 * cut_share, 100 * qi_share, runs, phases.t1, phases.t2, phases.group, grid_ms);
  const std::vector<Edge3> random = paper_random(50000, 10000, 1);
  HostCut haloed[2];
  Time h_one, h_many;
  measure(
      runs * 3, threads,
      [&](const Parts* p) {
        CutParams cp;
        cp.parts = p;
        return host_cut(std::move(handed), cp, &haloed[p == nullptr ? 0 : 1]) == Status::kOk;
      },
      &h_one, &h_many, [&] { handed = random; });
  row("CUT of the paper's random scene (N = 50,000, L = 0.01, seed 1, " +
          std::to_string(haloed[0].set.n_crossings) + " crossings)",
      h_one, h_many, same_cut(haloed[0], haloed[1]));
  return 0;
}
