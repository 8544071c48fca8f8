// Runs CUT and DRAW from the installed package on a 3 x 3 cube array and checks them against a
// brute-force count of its crossings written here: every pair of edges whose projections cross
// at one point strictly inside both, at different depths; then the motion runner on a fake
// board (runner_check.cpp). Exit 0 when all agree.
#include <haloplot/cut/cut.h>
#include <haloplot/draw/draw.h>
#include <haloplot/memory/sized_stage.h>
#include <haloplot/scene/cube_array.h>

#include <cstdio>
#include <vector>

using namespace haloplot;

int check_motion_runner();  // runner_check.cpp

namespace {

long long cross(long long ax, long long ay, long long bx, long long by) {
  return ax * by - ay * bx;
}

// Crossings strictly inside both edges with different depths there (CUT's records for them).
size_t brute_force(const std::vector<Edge3>& e) {
  size_t n = 0;
  for (size_t i = 0; i < e.size(); ++i)
    for (size_t j = i + 1; j < e.size(); ++j) {
      const Edge3 &p = e[i], &q = e[j];
      const long long dpx = p.b.x - p.a.x, dpy = p.b.y - p.a.y, dqx = q.b.x - q.a.x,
                      dqy = q.b.y - q.a.y;
      long long den = cross(dpx, dpy, dqx, dqy);
      long long tn = cross(q.a.x - p.a.x, q.a.y - p.a.y, dqx, dqy);
      long long un = cross(q.a.x - p.a.x, q.a.y - p.a.y, dpx, dpy);
      if (den == 0) continue;
      if (den < 0) den = -den, tn = -tn, un = -un;
      if (tn <= 0 || tn >= den || un <= 0 || un >= den) continue;
      const __int128 zp = __int128(p.a.z) * den + __int128(p.b.z - p.a.z) * tn;
      const __int128 zq = __int128(q.a.z) * den + __int128(q.b.z - q.a.z) * un;
      if (zp != zq) ++n;
    }
  return n;
}

Status count_span(void* ctx, const Span&) {
  ++*static_cast<size_t*>(ctx);
  return Status::kOk;
}

}  // namespace

int main() {
  CubeArrayParams p;
  p.cubes = 3;
  std::vector<Edge3> edges(cube_array_edges(p));
  if (!ok(cube_array(p, edges.data(), uint32_t(edges.size())))) return 1;
  CutPlan plan;
  if (!ok(plan_cut(edges.data(), uint32_t(edges.size()), CutParams{}, &plan))) return 1;
  CutSet set;
  CutStats stats;
  CutStage stage{&plan, edges.data(), &set, &stats};
  StageNeeds needs;
  needs.crossings = 8;
  std::vector<uint64_t> buffer(1 << 16);
  FixedMemory memory{buffer.data(), buffer.size() * 8};
  if (!ok(run_sized(stage, memory.memory(), &needs))) return 1;
  const size_t want = brute_force(edges);
  std::vector<Gap> scratch(set.n_crossings + 8);
  size_t spans = 0;
  DrawStats ds;
  DrawParams dp;
  dp.halo = 40;
  if (!ok(draw(set, dp, scratch.data(), scratch.size() * sizeof(Gap), SpanSink{&count_span, &spans},
               &ds)))
    return 1;
  std::printf("package consumer: %u edges, %u crossings (brute force %zu), %zu spans\n",
              set.n_edges, set.n_crossings, want, spans);
  if (set.n_crossings != want || spans < edges.size()) return 1;
  return check_motion_runner();
}
