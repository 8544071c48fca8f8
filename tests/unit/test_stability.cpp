// Numerical stability under perturbation: thousands of random crossing pairs (near-parallel
// and long ones included); every vertex coordinate is moved by one unit in turn.
//   - Topology (which edge passes behind which) must equal the exact reference on both
//     sides of the move: where it changes, it changes consistently.
//   - The emitted crossing point stays within 1/2 + 2^-11 steps of the exact point, and the
//     paper-halo gap ends within their documented bound, so when the topology is unchanged the
//     output moves by the geometric amount plus at most 1 step: rounding never amplifies.
#include <cmath>
#include <string>

#include "../check.h"
#include "../reference/brute_cut.h"
#include "../support/plot.h"
#include "../support/run_core.h"
#include "../support/scenes.h"
#include "haloplot/geometry/fraction.h"

using namespace haloplot;
using ld = long double;

struct Measured {
  bool crosses = false;
  uint32_t behind = 0, front = 0;
  ld exact_x = 0, exact_y = 0;     // exact crossing point
  int32_t emit_x = 0, emit_y = 0;  // the core's emitted crossing point (CUTSET t, rounded)
  ld gap_exact = 0, gap_emit = 0;  // first gap end on the behind edge, x (paper halo)
  ld gap_bound = 0;
};

static Measured measure(const std::vector<Edge3>& e, int32_t halo) {
  Measured m;
  host::HostCut c;
  CHECK(ok(host::host_cut(e, CutParams{}, &c)));
  const auto recs = support::records_of(c.set);
  const auto ref = reference::brute_cut(e).records;
  CHECK_MSG(recs == ref, "topology differs from the exact reference");
  if (recs.size() != 1) return m;
  m.crosses = true;
  m.behind = recs[0].behind;
  m.front = recs[0].front;
  const Edge3 &p = e[m.behind], &q = e[m.front];
  __int128 num = 0, den = 1;
  CHECK(reference::crossing(p, q, &num, &den));
  const ld t = ld(num) / ld(den);
  m.exact_x = p.a.x + t * (p.b.x - p.a.x);
  m.exact_y = p.a.y + t * (p.b.y - p.a.y);
  span_point(p, recs[0].t, &m.emit_x, &m.emit_y);
  // Paper gap start on the behind edge: t - W |dq| / |cross(dp, dq)|, in x.
  const ld pdx = p.b.x - p.a.x, pdy = p.b.y - p.a.y, qdx = q.b.x - q.a.x, qdy = q.b.y - q.a.y;
  const ld d = std::fabs(pdx * qdy - pdy * qdx), lq = std::hypot(qdx, qdy),
           lp = std::hypot(pdx, pdy);
  const ld h = halo * lq / d;
  const auto plotted = support::plot(e, halo, HaloMode::kPaper);
  for (const Span& s : plotted.spans)
    if (s.edge == m.behind && s.t1 < (int64_t{1} << 32) && t - h > 0) {
      m.gap_emit = s.x1;
      m.gap_exact = p.a.x + (t - h) * pdx;
      // rounding 1/2, Q0.32 2^-11, the Q10 length of the front edge W 2^-10 |dp| / |d|
      m.gap_bound = 0.5L + std::ldexp(1.0L, -11) + halo * std::ldexp(1.0L, -10) * lp / d + 1e-9L;
      break;
    }
  return m;
}

int main() {
  scenes::Rng r(2024);
  int cases = 0, topology_changes = 0, near_parallel = 0;
  const int32_t halo = 50;
  for (int trial = 0; trial < 700; ++trial) {
    // Two edges through a common point, at a random angle; a third of them nearly parallel.
    const int32_t cx = int32_t(r.uniform(200000, 800000)), cy = int32_t(r.uniform(200000, 800000));
    const int32_t len = int32_t(r.uniform(50, 150000));
    const int32_t ax = int32_t(r.uniform(-len, len)), ay = int32_t(r.uniform(-len, len));
    int32_t bx, by;
    if (trial % 3 == 0) {
      bx = ax + int32_t(r.uniform(-3, 3));
      by = ay + int32_t(r.uniform(-3, 3));  // nearly parallel, offset down to one step
      ++near_parallel;
    } else {
      bx = int32_t(r.uniform(-len, len));
      by = int32_t(r.uniform(-len, len));
    }
    std::vector<Edge3> e = {scenes::edge(cx - ax, cy - ay, int32_t(r.uniform(0, 1000)), cx + ax + 1,
                                         cy + ay, int32_t(r.uniform(0, 1000))),
                            scenes::edge(cx - bx + 1, cy - by, int32_t(r.uniform(2000, 3000)),
                                         cx + bx, cy + by + 1, int32_t(r.uniform(0, 5000)))};
    const Measured base = measure(e, halo);
    for (int coord = 0; coord < 12; ++coord)
      for (int delta : {-1, 1}) {
        std::vector<Edge3> moved = e;
        Point3& pt = coord < 6 ? (coord < 3 ? moved[0].a : moved[0].b)
                               : (coord < 9 ? moved[1].a : moved[1].b);
        int32_t& v = (coord % 3 == 0) ? pt.x : (coord % 3 == 1) ? pt.y : pt.z;
        v += delta;
        if (!in_range(pt)) {  // off the coordinate range: a named refusal, not a result
          host::HostCut c;
          CHECK(host::host_cut(moved, CutParams{}, &c) == Status::kCoordinateOutOfRange);
          continue;
        }
        const Measured m = measure(moved, halo);
        ++cases;
        if (m.crosses != base.crosses || m.behind != base.behind) {
          ++topology_changes;  // checked against the exact reference inside measure()
          continue;
        }
        if (!m.crosses) continue;
        const ld bound = 0.5L + std::ldexp(1.0L, -11) + 1e-9L;
        CHECK_MSG(
            std::fabs(m.emit_x - m.exact_x) <= bound && std::fabs(m.emit_y - m.exact_y) <= bound,
            "crossing point rounding bound");
        // What the move did to the output, against what it did to the exact geometry.
        const ld moved_out = ld(m.emit_x - base.emit_x), moved_exact = m.exact_x - base.exact_x;
        CHECK_MSG(std::fabs(moved_out - moved_exact) <= 1.0L + 1e-9L,
                  "output moved by " + std::to_string(double(moved_out)) + ", geometry by " +
                      std::to_string(double(moved_exact)));
        if (m.gap_bound > 0)
          CHECK_MSG(std::fabs(m.gap_emit - m.gap_exact) <= m.gap_bound, "halo gap end bound");
      }
  }
  CHECK(cases > 16000);
  CHECK(near_parallel > 200);
  std::printf("%d perturbed cases, %d with a topology change (all matching the exact reference)\n",
              cases, topology_changes);
  return check::finish("stability_perturbation");
}
