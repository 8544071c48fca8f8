// Open meshes at full speed: the hidden-line stage of a closed torus of about 1M triangles
// against the same torus with a tenth of its tube left out (an open surface: the QI counts both
// sides of every face there, core/include/haloplot/solid/qi.h), side by side in one run. Each is
// sized once by the sized-stage protocol, as a controller with a tight arena would: a first run
// finds the crossings and incidences, the capacities are set to those, and the bytes grow from a
// quarter of the first guess until the run fits (each growth half as much again, so the buffer is
// at most 1.5 times the stage's need). Then each is timed on that buffer, closed and open
// alternating, the median of the runs; time per triangle and the stage's bytes (its buffer's
// high-water mark) per triangle. A third row pierces the closed torus with a sphere (the QI's
// second propagation, stopping where edges pass through faces).
//   open_mesh_bench [QUADS_AROUND [QUADS_ACROSS [RUNS]]]   (default 1000 500 3: 1M triangles)
// Prints a Markdown table (docs/reports/performance.md, "Open meshes").
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/perf_common.h"
#include "support/solid_scenes.h"

using namespace haloplot;
using namespace haloplot::host;
using namespace solid_scenes;

namespace {

Status ignore_piece(void*, const HiddenPiece&) { return Status::kOk; }

struct Sized {
  SolidScene scene;
  SolidInput in;
  HiddenParams params;
  std::vector<uint64_t> buffer;
  HiddenReport report;
  std::vector<double> ms;
};

// The sizes a run needs, found by the stage protocol; then one buffer of that size.
bool size_run(Sized* s) {
  s->in = solid_input(s->scene);
  StageNeeds needs;
  needs.crossings = 4 * (s->in.n_edges + 3 * s->in.n_triangles) + 1024;
  needs.incidences = s->in.n_vertices + 64;
  size_t bytes = hidden_lines_first_bytes(s->in);
  bool tight = false;
  for (int attempt = 0; attempt < 24; ++attempt) {
    s->params.crossing_capacity = needs.crossings;
    s->params.incidence_capacity = needs.incidences;
    s->buffer.assign(bytes / 8 + 1, 0);
    const Status st =
        hidden_lines(s->in, s->params, s->buffer.data(), bytes,
                     HiddenSink{nullptr, &ignore_piece, nullptr, nullptr}, &s->report);
    if (st == Status::kOk && tight) return true;
    if (st == Status::kOk) {  // now as tight as the run: its own crossings and incidences
      tight = true;
      needs.crossings = need_count(s->report.cut.crossings + s->report.cut.near_misses);
      needs.incidences = s->report.incidences_needed > s->report.incidences
                             ? s->report.incidences_needed
                             : s->report.incidences;
      bytes = hidden_lines_first_bytes(s->in) / 4;
      continue;
    }
    StageNeeds want = needs;
    want.bytes = bytes;
    hidden_lines_needs(st, s->report, bytes, &want);
    needs = want;
    bytes = want.bytes;
  }
  return false;
}

double time_once(Sized* s) {
  const double t0 = bench::now_ms();
  const Status st = hidden_lines(s->in, s->params, s->buffer.data(), s->buffer.size() * 8,
                                 HiddenSink{nullptr, &ignore_piece, nullptr, nullptr}, &s->report);
  const double t = bench::now_ms() - t0;
  return st == Status::kOk ? t : -1;
}

void torus_part(Mesh* m, int n, int k, int skip) {
  Mesh whole;
  torus(&whole, 0, 0, 0, 600000, 250000, n, k);
  m->v = whole.v;
  for (size_t f = 0; f < whole.faces.size(); ++f)
    if (int(f / size_t(k)) >= skip) m->face(whole.faces[f]);
}

void row(const char* name, const Sized& s, double base_per_tri) {
  const double tris = double(s.in.n_triangles);
  const double ms = bench::median(s.ms);
  const double per = ms * 1e6 / tris;  // ns per triangle
  std::printf("| %s | %u | %s | %s | %s | %s | %s |\n", name, s.in.n_triangles,
              bench::fmt(ms, 1).c_str(), bench::fmt(per, 0).c_str(),
              bench::fmt(per / base_per_tri, 2).c_str(),
              bench::fmt(double(s.report.bytes_used) / tris, 0).c_str(),
              s.report.used_qi ? (s.report.qi.pierces > 0 ? "QI, pierces" : "QI") : "fallback");
  const HiddenReport& r = s.report;
  std::fprintf(stderr,
               "%s: bytes per triangle: topology %.0f, CUT scratch + CUTSET %.0f, incidences %.0f, "
               "QI %.0f; crossings %llu; conflicts %u then %u, pierces %llu, projected facing %d\n",
               name, double(r.bytes_topology) / tris, double(r.bytes_cut) / tris,
               double(r.bytes_incidence) / tris, double(r.bytes_qi) / tris,
               (unsigned long long)r.cut.crossings, r.qi.first_conflicts, r.qi.conflicts,
               (unsigned long long)r.qi.pierces, r.projected_facing ? 1 : 0);
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 1000, k = argc > 2 ? std::atoi(argv[2]) : 500;
  const int runs = argc > 3 ? std::atoi(argv[3]) : 3;
  View v = view(30000, 25000);
  v.substep_bits = kDefaultSubstepBits;
  Sized closed, open, pierced;
  {
    Mesh m;
    torus_part(&m, n, k, 0);
    if (!project(m, v, &closed.scene)) return 1;
    Mesh o;
    torus_part(&o, n, k, n / 10);
    if (!project(o, v, &open.scene)) return 1;
    Mesh p;
    torus_part(&p, n, k, 0);
    sphere(&p, 600000, 0, 100000, 300000, k / 2, k);
    if (!project(p, v, &pierced.scene)) return 1;
  }
  if (!size_run(&closed) || !size_run(&open) || !size_run(&pierced)) {
    std::fprintf(stderr, "open_mesh_bench: a run could not be sized\n");
    return 1;
  }
  for (int r = 0; r < runs; ++r)
    for (Sized* s : {&closed, &open, &pierced}) s->ms.push_back(time_once(s));
  const double base = bench::median(closed.ms) * 1e6 / double(closed.in.n_triangles);
  std::printf(
      "| mesh | triangles | hidden stage ms | ns per triangle | per triangle / closed | "
      "bytes per triangle | method |\n|---|---:|---:|---:|---:|---:|---|\n");
  row("closed torus", closed, base);
  row("the torus, a tenth of its tube left out (open)", open, base);
  row("the closed torus pierced by a sphere", pierced, base);
  return 0;
}
