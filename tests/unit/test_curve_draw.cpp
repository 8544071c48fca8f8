// Haloed curves (core/include/haloplot/curve/curve_draw.h) against references that share no code
// with the core:
//  1. knots and a helix with its axis: every crossing of the long-double reference (dense
//     sampling refined by Newton's method, tests/reference/curve_reference.h) has exactly one
//     gap, on the strand behind, and the strand in front is drawn there; each side of a gap has
//     the arc length W / sin(theta) (the reference's angle, the arc integrated from the
//     reference's speed) within the bound docs/curves.md states;
//  1b. crossings at joints: knots fitted so that crossings fall on joints (the reference keeps
//     crossings at edge ends), a curve through another chain's joint, and two joints that
//     touch or cross (hand-worked);
//  2. the same knot written by this test as ~10,000 straight edges (its own long-double
//     evaluation) and drawn by the straight-edge CUT and DRAW: the same ink within a step.
// `curve_draw plant front` cuts the gaps on the front strand and `plant width` draws with 3/4
// of the halo: both must fail (CTest curve_draw_planted*).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "check.h"
#include "haloplot/curve/curve_draw.h"
#include "reference/curve_reference.h"
#include "support/pen_drawing.h"
#include "support/plot.h"

using namespace haloplot;
using namespace curve_reference;
using haloplot::host::CurveView;

namespace {

enum class Plant { kNone, kFront, kWidth };
Plant g_plant = Plant::kNone;

// ---- the code under test: the core's two stages, as the host runs them ----

struct Drawing {
  std::vector<CurveHit> hits;
  std::vector<CurveInterval> intervals;
  std::vector<Span> chords;
  CurveDrawStats stats;
};

Status into_chords(void* c, const Span& s) {
  static_cast<std::vector<Span>*>(c)->push_back(s);
  return Status::kOk;
}
Status into_intervals(void* c, const CurveInterval& i) {
  static_cast<std::vector<CurveInterval>*>(c)->push_back(i);
  return Status::kOk;
}

Drawing draw_core(const CurveScene& s, int32_t halo) {
  Drawing d;
  const uint32_t nc = uint32_t(s.curves.size()), ns = uint32_t(s.segments.size());
  CurveCrossParams cp;
  cp.segment_pairs = true;
  CurveCrossPlan plan;
  Status st = plan_curve_cross(s.curves.data(), nc, s.segments.data(), ns, cp, &plan);
  CHECK_MSG(ok(st), "plan_curve_cross");
  std::vector<uint64_t> scratch(plan.scratch_bytes / 8 + 1);
  d.hits.resize(4096);
  uint32_t n = 0;
  CurveCrossStats cs;
  st = run_curve_cross(plan, s.curves.data(), s.segments.data(), scratch.data(), scratch.size() * 8,
                       d.hits.data(), uint32_t(d.hits.size()), &n, &cs);
  CHECK_MSG(ok(st), std::string("run_curve_cross: ") + status_name(st));
  d.hits.resize(n);
  if (g_plant == Plant::kFront)
    for (CurveHit& h : d.hits) h.front = int8_t(-h.front);
  if (g_plant == Plant::kWidth) halo = halo * 3 / 4;
  CurveDrawParams p;
  p.halo = halo;
  CurveDrawPlan dplan;
  st = plan_curve_draw(s.curves.data(), nc, s.segments.data(), ns, d.hits.data(), n, p, &dplan);
  CHECK_MSG(ok(st), std::string("plan_curve_draw: ") + status_name(st));
  std::vector<uint64_t> dscratch(dplan.scratch_bytes / 8 + 1);
  const CurveIntervalSink is{&into_intervals, &d.intervals};
  st = run_curve_draw(dplan, s.curves.data(), s.segments.data(), d.hits.data(), n, dscratch.data(),
                      dscratch.size() * 8, SpanSink{&into_chords, &d.chords}, &is, &d.stats);
  CHECK_MSG(ok(st), std::string("run_curve_draw: ") + status_name(st));
  return d;
}

// ---- the reference's geometry ----

std::vector<RefCurve> ref_curves(const CurveScene& s) {
  std::vector<RefCurve> cs;
  for (const auto& c : s.curves) cs.push_back(ref_of(c));
  for (const auto& e : s.segments) cs.push_back(ref_of(e));
  return cs;
}

LD speed(const RefCurve& c, LD t) {
  const LP d = deriv(c, t);
  return std::hypot(d.x, d.y);
}

// Arc length of c over [a, b]: composite Simpson, 256 panels (the speed is smooth).
LD arc(const RefCurve& c, LD a, LD b) {
  const int n = 256;
  const LD h = (b - a) / n;
  LD sum = speed(c, a) + speed(c, b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * speed(c, a + i * h);
  return sum * h / 3;
}

// The largest length of a second difference of the control points (x, y): |B''| <= 6 D.
LD second_difference(const RefCurve& c) {
  if (c.straight) return 0;
  LD most = 0;
  for (int i = 0; i < 2; ++i)
    most = std::max(most, std::hypot(c.p[i][0] - 2 * c.p[i + 1][0] + c.p[i + 2][0],
                                     c.p[i][1] - 2 * c.p[i + 1][1] + c.p[i + 2][1]));
  return most;
}

LD max_speed(const RefCurve& c) {
  LD most = 0;
  for (int i = 0; i < 3; ++i)
    most = std::max(most, std::hypot(c.p[i + 1][0] - c.p[i][0], c.p[i + 1][1] - c.p[i][1]));
  return c.straight ? most : 3 * most;
}

// ---- chains: a knot is one closed chain of edges, the helix an open one and its axis ----

struct Chain {
  std::vector<uint32_t> edges;
  bool closed = false;
};

struct Place {
  int chain = -1;
  LD g = 0;  // position along the chain: the edge's place in it plus t
};

Place place_of(const std::vector<Chain>& chains, uint32_t edge, LD t) {
  for (size_t c = 0; c < chains.size(); ++c)
    for (size_t k = 0; k < chains[c].edges.size(); ++k)
      if (chains[c].edges[k] == edge) return Place{int(c), LD(k) + t};
  return Place{};
}

struct Hole {
  LD lo, hi;  // along the chain; a closed chain's hole may pass its start (hi > size)
  bool clipped_lo, clipped_hi;  // ends at an open chain's end: that side is not a whole gap
  int behind = 0;
};

// The parts of each chain that are not drawn, from the visible intervals.
std::vector<std::vector<Hole>> holes_of(const std::vector<Chain>& chains, const Drawing& d) {
  std::vector<std::vector<Hole>> out(chains.size());
  for (size_t c = 0; c < chains.size(); ++c) {
    std::vector<std::pair<LD, LD>> vis;
    for (const CurveInterval& i : d.intervals) {
      const Place p = place_of(chains, i.edge, 0);
      if (p.chain == int(c))
        vis.push_back({p.g + LD(i.t0) / 4294967296.0L, p.g + LD(i.t1) / 4294967296.0L});
    }
    std::sort(vis.begin(), vis.end());
    std::vector<std::pair<LD, LD>> merged;
    for (const auto& v : vis)
      if (!merged.empty() && v.first <= merged.back().second)
        merged.back().second = std::max(merged.back().second, v.second);
      else
        merged.push_back(v);
    const LD size = LD(chains[c].edges.size());
    if (merged.empty()) {
      out[c].push_back(Hole{0, size, !chains[c].closed, !chains[c].closed});
      continue;
    }
    for (size_t k = 0; k + 1 < merged.size(); ++k)
      out[c].push_back(Hole{merged[k].second, merged[k + 1].first, false, false});
    const LD first = merged.front().first, last = merged.back().second;
    if (chains[c].closed) {
      if (first > 0 || last < size) out[c].push_back(Hole{last, first + size, false, false});
    } else {
      if (first > 0) out[c].push_back(Hole{0, first, true, false});
      if (last < size) out[c].push_back(Hole{last, size, false, true});
    }
  }
  return out;
}

bool in_hole(const Hole& h, LD g, LD size) {
  return (g > h.lo && g < h.hi) || (g + size > h.lo && g + size < h.hi);
}

// ---- 1. gaps against the reference crossings ----

struct SideFigures {
  int sides = 0, across_joints = 0, most_edges = 0;  // most_edges: the most one side runs on
  LD worst = 0;                                      // the largest |arc - W / sin| / bound
};

// The arc from g0 to g1 along a chain, and how many edges it runs on.
void side_arc(const std::vector<RefCurve>& cs, const Chain& ch, LD g0, LD g1, LD* length,
              int* edges) {
  *length = 0, *edges = 0;
  const LD size = LD(ch.edges.size());
  while (g1 - g0 > 1e-15L) {
    const LD k = std::floor(g0), end = std::min(g1, k + 1);
    const RefCurve& c = cs[ch.edges[size_t(std::fmod(k, size))]];
    *length += arc(c, g0 - k, end - k);
    ++*edges;
    g0 = end;
  }
}

// The core's bound for a crossing on `edge` near t (its t_err, Q0.32), as a parameter.
LD core_t_err(const Drawing& d, uint32_t edge, uint32_t other, LD t) {
  LD best = 1, err = 1;
  for (const CurveHit& h : d.hits)
    if (h.curve == edge && h.other == other && h.kind == CurveHitKind::kCrossing &&
        std::fabs(LD(h.t) / 4294967296.0L - t) < best) {
      best = std::fabs(LD(h.t) / 4294967296.0L - t);
      err = LD(h.t_err) / 4294967296.0L;
    }
  return err;
}

// The checks of one gap side: |arc - L| within the bound docs/curves.md states for the walk
// (2^-14.5 L for its estimates, 2^-20.6 units a step, at most 4,096 steps, 1/64 unit for its
// last step), plus what the crossing's parameter bound allows.
void check_side(const char* name, const std::vector<RefCurve>& cs, const Chain& ch, LD g0, LD g1,
                LD L, LD fixed, LD t_err, LD speed_a, SideFigures* fig) {
  LD length;
  int edges;
  side_arc(cs, ch, g0, g1, &length, &edges);
  const LD walk = L * std::pow(2.0L, -14.5L) + 4096 * std::pow(2.0L, -20.6L) + 1.0L / 64;
  const LD bound = walk + 2 * speed_a * t_err + fixed;
  fig->worst = std::max(fig->worst, std::fabs(length - L) / bound);
  ++fig->sides;
  if (edges > 1) ++fig->across_joints;
  fig->most_edges = std::max(fig->most_edges, edges);
  CHECK_MSG(std::fabs(length - L) <= bound,
            std::string(name) + ": a gap side of arc " + std::to_string(double(length)) +
                " against W / sin(theta) = " + std::to_string(double(L)) + ", bound " +
                std::to_string(double(bound)));
}

// At a joint the edges on either side have their own tangents (a fit's kink): the gap on each
// side may take W / sin(theta) of any pair of the two chains' tangents there. The spread of
// those four (the reference's own derivatives) is added to the bound of a crossing at a joint.
LD joint_spread(const std::vector<RefCurve>& cs, const Chain& back, LD gb, const Chain& front,
                LD gf, int32_t W) {
  const auto tangents = [&cs](const Chain& ch, LD g, LP out[2]) {
    const size_t n = ch.edges.size(), k = size_t(std::llround(g)) % n;
    if (std::fabs(g - std::round(g)) > 1e-6L) {  // inside an edge: one tangent
      out[0] = out[1] = deriv(cs[ch.edges[size_t(g) % n]], g - std::floor(g));
      return;
    }
    out[0] = deriv(cs[ch.edges[k]], 0);
    out[1] = deriv(cs[ch.edges[(k + n - 1) % n]], 1);
  };
  LP a[2], b[2];
  tangents(back, gb, a);
  tangents(front, gf, b);
  LD lo = 1e30L, hi = 0;
  for (const LP& u : a)
    for (const LP& v : b) {
      const LD sin =
          std::fabs(u.x * v.y - u.y * v.x) / (std::hypot(u.x, u.y) * std::hypot(v.x, v.y));
      lo = std::min(lo, W / sin), hi = std::max(hi, W / sin);
    }
  return hi - lo;
}

int g_at_joints = 0;  // reference crossings at joints, over every check_gaps call

void check_gaps(const char* name, const CurveScene& scene, const std::vector<Chain>& chains,
                int32_t W, SideFigures* fig) {
  const std::vector<RefCurve> cs = ref_curves(scene);
  const std::vector<RefCrossing> ref = curve_reference::reference(scene, 64, true);
  const Drawing d = draw_core(scene, W);
  std::vector<std::vector<Hole>> holes = holes_of(chains, d);
  int problems = 0;
  for (const RefCrossing& r : ref) {
    const bool i_behind = r.dz < 0;
    const uint32_t be = i_behind ? r.i : r.j, fe = i_behind ? r.j : r.i;
    const LD bt = i_behind ? r.s : r.u, ft = i_behind ? r.u : r.s;
    const Place b = place_of(chains, be, bt), f = place_of(chains, fe, ft);
    const LD bsize = LD(chains[b.chain].edges.size()), fsize = LD(chains[f.chain].edges.size());
    for (const Hole& h : holes[f.chain])
      if (in_hole(h, f.g, fsize)) ++problems;
    Hole* hole = nullptr;
    for (Hole& h : holes[b.chain])
      if (in_hole(h, b.g, bsize)) hole = &h, ++h.behind;
    CHECK_MSG(hole != nullptr, std::string(name) + ": no gap on the strand behind at edge " +
                                   std::to_string(be) + " t=" + std::to_string(double(bt)));
    if (hole == nullptr) continue;
    const LD g = b.g + (b.g < hole->lo ? bsize : 0);
    // A crossing at a joint is at the edges' end points exactly: no parameter error.
    const LD L = LD(W) / r.sin_angle, t_err = r.at_end ? 0 : core_t_err(d, be, fe, bt);
    const LD u_err = r.at_end ? 0 : core_t_err(d, fe, be, ft);
    const LD sa = speed(cs[be], bt), sb = speed(cs[fe], ft);
    // The tangents at the reported parameters: a relative error in 1 / sin(theta) of at most
    // (|dA'| / |A'| + |dB'| / |B'|) (1 + 1 / sin), |dA'| <= 6 D t_err; the rounding 2^-26 / sin.
    const LD tangents =
        (6 * second_difference(cs[be]) * t_err / sa + 6 * second_difference(cs[fe]) * u_err / sb) *
        (1 + 1 / r.sin_angle);
    const LD fixed =
        L * (tangents + std::ldexp(1.0L, -26) / r.sin_angle) + 1e-6L +
        (r.at_end ? joint_spread(cs, chains[b.chain], b.g, chains[f.chain], f.g, W) : 0);
    if (!hole->clipped_lo)
      check_side(name, cs, chains[b.chain], hole->lo, g, L, fixed, t_err, max_speed(cs[be]), fig);
    if (!hole->clipped_hi)
      check_side(name, cs, chains[b.chain], g, hole->hi, L, fixed, t_err, max_speed(cs[be]), fig);
  }
  CHECK_MSG(problems == 0, std::string(name) + ": " + std::to_string(problems) +
                               " crossings with a gap on the strand in front");
  size_t n_holes = 0;
  for (const auto& hs : holes)
    for (const Hole& h : hs) {
      ++n_holes;
      CHECK_MSG(h.behind == 1, std::string(name) + ": a gap holding " + std::to_string(h.behind) +
                                   " reference crossings (one expected)");
    }
  CHECK_MSG(n_holes == ref.size(), std::string(name) + ": " + std::to_string(n_holes) +
                                       " gaps for " + std::to_string(ref.size()) + " crossings");
  size_t at_joints = 0;
  for (const RefCrossing& r : ref) at_joints += r.at_end ? 1 : 0;
  g_at_joints += int(at_joints);
  std::printf("%-28s W=%-5d %zu crossings (%zu at joints), %zu gaps, %llu carried over a joint\n",
              name, W, ref.size(), at_joints, n_holes, (unsigned long long)d.stats.carried);
}

std::vector<Chain> knot_chain(const CurveScene& s) {
  Chain c;
  for (uint32_t k = 0; k < s.curves.size(); ++k) c.edges.push_back(k);
  c.closed = true;
  return {c};
}

std::vector<Chain> helix_chains(const CurveScene& s) {
  Chain c, axis;
  for (uint32_t k = 0; k < s.curves.size(); ++k) c.edges.push_back(k);
  axis.edges.push_back(uint32_t(s.curves.size()));
  return {c, axis};
}

void test_gaps() {
  CurveView top, tilted;
  tilted.tilt = 1.0;
  SideFigures fig;
  for (int32_t W : {64, 700, 2500}) {
    check_gaps("trefoil", host::trefoil_knot(24, top), knot_chain(host::trefoil_knot(24, top)), W,
               &fig);
    const CurveScene t25 = host::torus_knot(2, 5, 42, top);
    check_gaps("torus knot (2,5)", t25, knot_chain(t25), W, &fig);
    const CurveScene hx = host::helix(4, 1.0, 24, true, tilted);
    check_gaps("helix + axis", hx, helix_chains(hx), W, &fig);
  }
  std::printf("gap sides: %d (%d across a joint), worst |arc - W/sin| / bound %.3f\n", fig.sides,
              fig.across_joints, double(fig.worst));
  CHECK_MSG(fig.across_joints > 0, "no gap side crossed a joint: the carry went untested");
}

// Knots whose crossings fall on joints of both strands (by symmetry, at these edge counts; the
// reference says which): each must still get one gap, on the strand behind, of W / sin(theta)
// on each side, across the joint.
void test_gaps_at_joints() {
  CurveView top;
  SideFigures fig;
  g_at_joints = 0;
  for (int32_t W : {64, 600}) {
    for (int n : {24, 40})
      check_gaps(("trefoil/" + std::to_string(n)).c_str(), host::trefoil_knot(n, top),
                 knot_chain(host::trefoil_knot(n, top)), W, &fig);
    for (int n : {12, 20, 40}) {
      const CurveScene k = host::torus_knot(2, 5, n, top);
      check_gaps(("torus knot (2,5)/" + std::to_string(n)).c_str(), k, knot_chain(k), W, &fig);
    }
    for (int n : {9, 24, 30}) {
      const CurveScene k = host::torus_knot(3, 4, n, top);
      check_gaps(("torus knot (3,4)/" + std::to_string(n)).c_str(), k, knot_chain(k), W, &fig);
    }
  }
  std::printf("at joints: %d reference crossings; gap sides %d, worst |arc - W/sin| / bound %.3f\n",
              g_at_joints, fig.sides, double(fig.worst));
  CHECK_MSG(g_at_joints > 0, "no reference crossing fell on a joint: the case went untested");
}

// Hand-worked: chain A-A' (two straight-shaped cubics, the joint at (1000, 1000))
// and a cubic B from (0, 2000) to (2000, 0), point-symmetric about (1000, 1000), so it passes
// through the joint at t = 1/2, at depth `zb` (A's is 10). B in front: A and A' lose the gap at the
// joint; B behind: B loses it around t = 1/2. Checked against the reference by check_gaps.
void test_through_joint() {
  for (int zb : {20, 0}) {
    const int za = 10;
    CurveScene s;
    s.curves.push_back(BezierEdge3{{{0, 0, za}, {300, 300, za}, {700, 700, za}, {1000, 1000, za}}});
    s.curves.push_back(
        BezierEdge3{{{1000, 1000, za}, {1300, 1300, za}, {1700, 1700, za}, {2000, 2000, za}}});
    s.curves.push_back(
        BezierEdge3{{{0, 2000, zb}, {600, 1800, zb}, {1400, 200, zb}, {2000, 0, zb}}});
    Chain a, b;
    a.edges = {0, 1};
    b.edges = {2};
    SideFigures fig;
    g_at_joints = 0;
    check_gaps(zb > za ? "B through A's joint, in front" : "B through A's joint, behind", s, {a, b},
               100, &fig);
    CHECK_MSG(g_at_joints == 1, "the reference sees the crossing at the joint");
  }
}

// The through_joint scene: chain A-A' with its joint J at (3000, 5000) and a cubic B through J
// at its t = 1/3 (not a piece end of its halving: B(1/3) = (8 P0 + 12 P1 + 6 P2 + P3) / 27 = J
// exactly), so run_curve_cross() sees only touches at A's and A''s ends; B in front and behind.
// Also with A' turned at J by more than 45 degrees (a corner, not a joint), and with B's last
// control point a unit off (it passes J by 1/27 unit: a crossing near A's end, or a touch).
void test_through_joint_anywhere() {
  int cases = 0;
  for (int variant = 0; variant < 3; ++variant)
    for (int zb : {20, 0}) {
      const int za = 10;
      CurveScene s;
      s.curves.push_back(
          BezierEdge3{{{1000, 3000, za}, {1700, 3600, za}, {2400, 4500, za}, {3000, 5000, za}}});
      if (variant == 1)  // a corner: leaving J up and a little left
        s.curves.push_back(
            BezierEdge3{{{3000, 5000, za}, {2900, 5600, za}, {2700, 6300, za}, {2500, 7000, za}}});
      else
        s.curves.push_back(
            BezierEdge3{{{3000, 5000, za}, {3600, 5500, za}, {4300, 6400, za}, {5000, 7000, za}}});
      s.curves.push_back(BezierEdge3{{{1000, 7000, zb},
                                      {3100, 5000, zb},
                                      {4900, 3000, zb},
                                      {variant == 2 ? 6401 : 6400, 1000, zb}}});
      Chain a, b;
      a.edges = {0, 1};
      b.edges = {2};
      SideFigures fig;
      const std::string name = std::string(variant == 0   ? "B through J at t=1/3"
                                           : variant == 1 ? "B through a corner at t=1/3"
                                                          : "B 1/27 unit from J") +
                               (zb > za ? ", in front" : ", behind");
      const Drawing d = draw_core(s, 100);
      check_gaps(name.c_str(), s, {a, b}, 100, &fig);
      CHECK_MSG(d.stats.gaps == 1, name + ": one gap, got " + std::to_string(d.stats.gaps));
      ++cases;
    }
  CHECK_EQ(cases, 6);
}

// A gap across more than one joint: the trefoil fitted with 100 edges, its gaps at W = 2,500
// and 8,000 units run over several joints a side.
void test_many_joints() {
  CurveView top;
  SideFigures fig;
  for (int32_t W : {2500, 8000})
    check_gaps("trefoil/100", host::trefoil_knot(100, top),
               knot_chain(host::trefoil_knot(100, top)), W, &fig);
  std::printf(
      "trefoil/100: %d gap sides, the longest on %d edges, worst |arc - W/sin| / bound %.3f\n",
      fig.sides, fig.most_edges, double(fig.worst));
  CHECK_MSG(fig.most_edges >= 4, "no gap side ran across 3 joints or more");
}

// Hand-worked: chain A-A' along y = 1000 at depth 10 with its joint at (1000, 1000), chain
// B-B' at depth 20 with its joint at the same (x, y), leaving it at slopes -0.3 and 0.3 (both
// above A: a touch, every edge drawn whole) or with B' turned below A (B crosses A there: A,
// behind, loses a gap on each side of its joint, B is whole).
void test_touch_at_joint() {
  for (bool crossing : {false, true}) {
    CurveScene s;
    s.curves.push_back(
        BezierEdge3{{{0, 1000, 10}, {300, 1000, 10}, {700, 1000, 10}, {1000, 1000, 10}}});
    s.curves.push_back(
        BezierEdge3{{{1000, 1000, 10}, {1300, 1000, 10}, {1700, 1000, 10}, {2000, 1000, 10}}});
    s.curves.push_back(
        BezierEdge3{{{0, 1300, 20}, {300, 1210, 20}, {700, 1090, 20}, {1000, 1000, 20}}});
    const int sign = crossing ? -1 : 1;
    s.curves.push_back(BezierEdge3{{{1000, 1000, 20},
                                    {1300, 1000 + sign * 90, 20},
                                    {1700, 1000 + sign * 210, 20},
                                    {2000, 1000 + sign * 300, 20}}});
    const Drawing d = draw_core(s, 100);
    std::vector<std::vector<CurveInterval>> by_edge(4);
    for (const CurveInterval& i : d.intervals) by_edge[i.edge].push_back(i);
    const uint64_t one = uint64_t{1} << 32;
    CHECK_EQ(d.stats.joint_crossings, uint64_t{crossing ? 1u : 0u});
    for (uint32_t k = 0; k < 4; ++k) {
      const bool cut = crossing && k < 2;
      CHECK_MSG(by_edge[k].size() == 1, "one visible interval on each edge");
      if (by_edge[k].size() != 1) continue;
      const CurveInterval& v = by_edge[k][0];
      // A cut edge loses W / sin(theta) = 100 * sqrt(1.09) / 0.3 = 348 units of arc at the
      // joint, sin(theta) from slope 0.3 against 0; A's speed runs from 900 (at its ends) to
      // 1,050 units per unit of t, so between 0.33 and 0.39 of its parameter: 0.2 to 0.5 here.
      const bool whole = v.t0 == 0 && v.t1 == one;
      const int64_t lo = int64_t(one / 10 * 2), hi = int64_t(one / 10 * 5);
      const bool gap_at_joint = k == 0 ? (v.t0 == 0 && one - v.t1 > lo && one - v.t1 < hi)
                                       : (v.t1 == one && v.t0 > lo && v.t0 < hi);
      CHECK_MSG(cut ? gap_at_joint : whole, std::string(crossing ? "crossing" : "touch") +
                                                " at a joint: edge " + std::to_string(k) +
                                                " drawn on [" + std::to_string(double(v.t0) / one) +
                                                ", " + std::to_string(double(v.t1) / one) + "]");
    }
  }
}

// Straight edges among curves cross each other in the curve stages too (no CUT runs on such a
// scene). Hand-worked: a horizontal segment at depth 0 under a vertical one at depth 10, both
// 2,000 units long, crossing at right angles in their middles: the lower one loses
// W / 2,000 of its parameter on each side of 1/2 (the walk ends at most 1/64 unit past: 2^-16 of
// the parameter), the upper one is whole; a curve far away keeps its own drawing whole.
void test_segments_among_curves() {
  CurveScene s;
  s.curves.push_back(BezierEdge3{{{5000, 0, 0}, {6000, 500, 0}, {7000, 500, 0}, {8000, 0, 0}}});
  s.segments.push_back(Edge3{{0, 1000, 0}, {2000, 1000, 0}});
  s.segments.push_back(Edge3{{1000, 0, 10}, {1000, 2000, 10}});
  const Drawing d = draw_core(s, 100);
  std::vector<CurveInterval> low, high, curve;
  for (const CurveInterval& i : d.intervals)
    (i.edge == 1 ? low : i.edge == 2 ? high : curve).push_back(i);
  const LD one = 4294967296.0L, slack = 1.0L / (1 << 16);
  CHECK_EQ(low.size(), size_t{2});
  CHECK(high.size() == 1 && high[0].t0 == 0 && high[0].t1 == uint64_t{1} << 32);
  CHECK(curve.size() == 1 && curve[0].t0 == 0 && curve[0].t1 == uint64_t{1} << 32);
  if (low.size() == 2) {
    const LD end = LD(low[0].t1) / one, start = LD(low[1].t0) / one;
    CHECK_MSG(low[0].t0 == 0 && end <= 0.45L && end >= 0.45L - slack,
              "the gap starts at 0.45: " + std::to_string(double(end)));
    CHECK_MSG(low[1].t1 == uint64_t{1} << 32 && start >= 0.55L && start <= 0.55L + slack,
              "the gap ends at 0.55: " + std::to_string(double(start)));
  }
}

// ---- 2. the same knot as ~10,000 straight edges, drawn by CUT and DRAW ----

// Every position drawn, in half steps of `unit` units, sampled every 1/8 step along each span.
test::Drawn ink(const std::vector<Span>& spans, LD unit) {
  test::Drawn d;
  for (const Span& s : spans) {
    const LD dx = s.x1 - s.x0, dy = s.y1 - s.y0;
    const int n = 1 + int(8 * std::hypot(dx, dy) / unit);
    for (int i = 0; i <= n; ++i) {
      const LD x = s.x0 + dx * i / n, y = s.y0 + dy * i / n;
      d.at.insert({std::llround(2 * x / unit), std::llround(2 * y / unit)});
    }
  }
  return d;
}

// The knot's own flattening: `n` points at equal parameter steps per edge, in long double,
// rounded to units; points within `keep_out` of a crossing are left out (the straight DRAW
// clips a halo at an edge's end, so a gap must lie inside one straight edge).
std::vector<Edge3> flattening(const CurveScene& s, int per_edge,
                              const std::vector<std::pair<LD, LD>>& crossings, LD keep_out) {
  std::vector<Point3> pts;
  for (const BezierEdge3& e : s.curves) {
    const RefCurve c = ref_of(e);
    for (int i = 0; i < per_edge; ++i) {
      const LP p = eval(c, LD(i) / per_edge);
      bool near = false;
      for (const auto& x : crossings) near |= std::hypot(p.x - x.first, p.y - x.second) < keep_out;
      if (!near || i == 0)  // keep the joints: the curve scene's edge ends are vertices too
        pts.push_back(Point3{int32_t(std::llround(p.x)), int32_t(std::llround(p.y)),
                             int32_t(std::llround(p.z))});
    }
  }
  std::vector<Edge3> edges;
  for (size_t i = 0; i < pts.size(); ++i) edges.push_back(Edge3{pts[i], pts[(i + 1) % pts.size()]});
  return edges;
}

void check_flattening(const char* name, const CurveScene& knot, int32_t unit, int32_t W) {
  std::vector<std::pair<LD, LD>> at;
  LD keep_out = 0;
  const std::vector<RefCurve> cs = ref_curves(knot);
  for (const RefCrossing& r : curve_reference::reference(knot, 64)) {
    const LP p = eval(cs[r.i], r.s);
    at.push_back({p.x, p.y});
    keep_out = std::max(keep_out, 1.5L * W / r.sin_angle + 4 * unit);
  }
  const int per_edge = int(10000 / knot.curves.size()) + 1;
  const std::vector<Edge3> straight = flattening(knot, per_edge, at, keep_out);
  const support::Plot flat = support::plot(straight, W, HaloMode::kPaper);
  const Drawing curved = draw_core(knot, W);
  std::pair<int64_t, int64_t> where;
  const test::Drawn a = ink(curved.chords, unit), b = ink(flat.spans, unit);
  const bool a_in_b = test::within_a_step(a, b, &where);
  CHECK_MSG(a_in_b, std::string(name) + ": the curve drawing inks (" +
                        std::to_string(double(where.first) / 2) + ", " +
                        std::to_string(double(where.second) / 2) +
                        ") steps, more than a step from the straight flattening's ink");
  const bool b_in_a = test::within_a_step(b, a, &where);
  CHECK_MSG(b_in_a, std::string(name) + ": the straight flattening inks (" +
                        std::to_string(double(where.first) / 2) + ", " +
                        std::to_string(double(where.second) / 2) +
                        ") steps, more than a step from the curve drawing's ink");
  std::printf(
      "%s as %zu straight edges (%llu gaps) against %zu Bezier edges (%llu gaps, %zu "
      "chords): %zu and %zu inked half-step cells, same ink within a step: %s\n",
      name, straight.size(), (unsigned long long)flat.stats.gaps, knot.curves.size(),
      (unsigned long long)curved.stats.gaps, curved.chords.size(), a.at.size(), b.at.size(),
      a_in_b && b_in_a ? "yes" : "no");
  CHECK_EQ(flat.stats.gaps, curved.stats.gaps);
}

void test_flattening() {
  // 16 units a step (as a '# substep 4' scene): the rounding of both drawings' points is far
  // below the step the comparison allows. W = 8 steps.
  CurveView v;
  v.size = 1 << 18;
  v.margin = 1 << 12;
  check_flattening("trefoil", host::trefoil_knot(24, v), 16, 8 * 16);
  check_flattening("torus knot (2,5)", host::torus_knot(2, 5, 42, v), 16, 8 * 16);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 2 && std::string(argv[1]) == "plant")
    g_plant = std::string(argv[2]) == "front" ? Plant::kFront : Plant::kWidth;
  test_gaps();
  test_gaps_at_joints();
  test_through_joint();
  test_through_joint_anywhere();
  test_many_joints();
  test_touch_at_joint();
  test_segments_among_curves();
  test_flattening();
  return check::finish("curve_draw");
}
