#include "precision_modes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <vector>

#include "../support/must.h"
#include "chart.h"
#include "demo/random_scene.h"
#include "haloplot/cut/cut.h"
#include "haloplot/draw/draw.h"
#include "haloplot/geometry/predicates.h"
#include "haloplot/view/projection.h"
#include "haloplot/view/trig.h"
#include "perf_common.h"
#include "reference/draw_reference.h"

namespace bench {
namespace {

using namespace haloplot;

constexpr long double kPi = 3.141592653589793238462643383279502884L;

// World scenes: the demo's cube array (as world vertices) and a tessellated torus.
struct World {
  std::string name;
  std::vector<Point3> vertices;
  std::vector<uint32_t> pairs;
};

World cube_world(int n) {
  World w{"cube array " + std::to_string(n) + " × " + std::to_string(n), {}, {}};
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const uint32_t base = uint32_t(w.vertices.size());
      for (int k = 0; k < 8; ++k)
        w.vertices.push_back(
            {i * 125 + (k & 1) * 100, j * 125 + ((k >> 1) & 1) * 100, (k >> 2) * 100});
      for (uint32_t a = 0; a < 8; ++a)
        for (uint32_t bit = 1; bit < 8; bit <<= 1)
          if (!(a & bit)) w.pairs.insert(w.pairs.end(), {base + a, base + (a | bit)});
    }
  return w;
}

World torus_world(int around, int across) {
  World w{
      "torus mesh, " + std::to_string(around) + " × " + std::to_string(across) + " quads", {}, {}};
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < across; ++j) {
      const long double u = 2 * kPi * i / around, v = 2 * kPi * j / across;
      const long double r = 30000 + 10000 * std::cos(v);
      w.vertices.push_back({int32_t(std::lround(r * std::cos(u))),
                            int32_t(std::lround(r * std::sin(u))),
                            int32_t(std::lround(10000 * std::sin(v)))});
    }
  auto id = [&](int i, int j) { return uint32_t((i % around) * across + (j % across)); };
  for (int i = 0; i < around; ++i)
    for (int j = 0; j < across; ++j)
      w.pairs.insert(w.pairs.end(), {id(i, j), id(i + 1, j), id(i, j), id(i, j + 1)});
  return w;
}

// The README's view and fit in long double: the exact reference.
template <typename F>
std::vector<std::array<F, 3>> rotate(const View& v, const std::vector<Point3>& w) {
  const F az = F(v.azimuth_mdeg * kPi / 180000), el = F(v.elevation_mdeg * kPi / 180000);
  const F ca = std::cos(az), sa = std::sin(az), ce = std::cos(el), se = std::sin(el);
  std::vector<std::array<F, 3>> r;
  r.reserve(w.size());
  for (const Point3& p : w) {
    const F x = F(p.x), y = F(p.y), z = F(p.z);
    const F y1 = x * sa + y * ca;
    r.push_back({x * ca - y * sa, z * ce + y1 * se, z * se - y1 * ce});  // core/view convention
  }
  return r;
}

template <typename F>
std::vector<std::array<F, 3>> fit(const View& v, const std::vector<std::array<F, 3>>& r) {
  F lo[3] = {F(1e30), F(1e30), F(1e30)}, hi[3] = {F(-1e30), F(-1e30), F(-1e30)};
  for (const auto& q : r)
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], q[k]), hi[k] = std::max(hi[k], q[k]);
  const F scale = std::min(F(v.width) / (hi[0] - lo[0]), F(v.height) / (hi[1] - lo[1]));
  std::vector<std::array<F, 3>> out;
  for (const auto& q : r)
    out.push_back({F(v.margin) + (q[0] - lo[0]) * scale, F(v.margin) + (q[1] - lo[1]) * scale,
                   (q[2] - lo[2]) / (hi[2] - lo[2]) * F(kCoordMax)});
  return out;
}

template <typename F>
std::vector<Point3> project_float(const View& v, const std::vector<Point3>& w) {
  std::vector<Point3> out;
  for (const auto& q : fit<F>(v, rotate<F>(v, w)))
    out.push_back(
        {int32_t(std::lround(q[0])), int32_t(std::lround(q[1])), int32_t(std::lround(q[2]))});
  return out;
}

std::vector<Edge3> edges_of(const std::vector<Point3>& p, const std::vector<uint32_t>& pairs) {
  std::vector<Edge3> e;
  for (size_t i = 0; i + 1 < pairs.size(); i += 2) e.push_back({p[pairs[i]], p[pairs[i + 1]]});
  return e;
}

// CUT's crossings as (behind, front) pairs: topology to compare between projections.
std::set<std::pair<uint32_t, uint32_t>> crossings(const std::vector<Edge3>& e) {
  std::vector<uint64_t> storage;
  CutSet set;
  time_cut(e, CutParams{}, 1, &storage, &set);
  std::set<std::pair<uint32_t, uint32_t>> out;
  for (uint32_t i = 0; i < set.n_crossings; ++i)
    out.insert({set.crossings[i].behind, set.crossings[i].front_edge()});
  return out;
}

struct ModeResult {
  std::string name;
  double ms = 0, max_err = 0, mean_err = 0;
  long span_diff = 0;
};

template <typename P>
ModeResult run_draw_mode(const std::string& name, const CutSet& set,
                         const std::vector<reference::RefSpan>& ref, int runs) {
  std::vector<Gap> scratch(draw_scratch_bytes(set) / sizeof(Gap) + 1);
  std::vector<Span> spans;
  std::vector<double> t;
  for (int r = 0; r < runs + 1; ++r) {  // the first run warms caches and is not counted
    spans.clear();
    const double t0 = now_ms();
    must(draw_with<P>(set, DrawParams{50, HaloMode::kPaper}, scratch.data(),
                      scratch.size() * sizeof(Gap),
                      SpanSink{[](void* c, const Span& s) {
                                 static_cast<std::vector<Span>*>(c)->push_back(s);
                                 return Status::kOk;
                               },
                               &spans},
                      nullptr));
    if (r > 0) t.push_back(now_ms() - t0);
  }
  ModeResult m{name, median(t), 0, 0, 0};
  // Positions are compared edge by edge where the mode and the reference cut the edge into
  // the same number of spans; an edge with another count is a change of topology (a grown gap
  // swallowed a short span, or two gaps merged) and is counted, not measured.
  std::map<uint32_t, std::vector<const reference::RefSpan*>> by_edge;
  std::map<uint32_t, std::vector<const Span*>> got_by_edge;
  for (const auto& r : ref) by_edge[r.edge].push_back(&r);
  for (const Span& s : spans) got_by_edge[s.edge].push_back(&s);
  std::set<uint32_t> edges_seen;
  for (const auto& [e, list] : by_edge) edges_seen.insert(e);
  for (const auto& [e, list] : got_by_edge) edges_seen.insert(e);
  double sum = 0;
  size_t n = 0;
  for (uint32_t e : edges_seen) {
    const auto& want = by_edge[e];
    const auto& got = got_by_edge[e];
    if (want.size() != got.size()) {
      ++m.span_diff;
      continue;
    }
    for (size_t k = 0; k < got.size(); ++k) {
      const Span& s = *got[k];
      const auto& r = *want[k];
      for (double err : {double(std::fabs(s.x0 - r.x0)), double(std::fabs(s.y0 - r.y0)),
                         double(std::fabs(s.x1 - r.x1)), double(std::fabs(s.y1 - r.y1))}) {
        m.max_err = std::max(m.max_err, err);
        sum += err;
        ++n;
      }
    }
  }
  m.mean_err = n ? sum / double(n) : 0;
  return m;
}

std::vector<reference::RefGapInput> reference_cuts(const std::vector<Edge3>& edges,
                                                   const CutSet& set) {
  std::vector<reference::RefGapInput> cuts;
  for (uint32_t e = 0; e < set.n_edges; ++e)
    for (uint32_t k = 0; k < set.count(e); ++k) {
      const Crossing& c = set.begin(e)[k];
      const bool forward = c.behind < c.front_edge();
      const CrossingTest y = forward ? test_crossing(edges[c.behind], edges[c.front_edge()])
                                     : test_crossing(edges[c.front_edge()], edges[c.behind]);
      const auto t = forward ? reference::ld(y.tn) / reference::ld(y.den)
                             : reference::ld(y.un) / reference::ld(y.den);
      cuts.push_back({c.behind, c.front_edge(), t});
    }
  return cuts;
}

}  // namespace

void precision_modes_section(const std::string& dir, int runs, std::ostringstream& md) {
  View view;  // the README's: azimuth 30, elevation 40, 20,000 x 16,000 steps
  const std::vector<World> worlds = {cube_world(28), torus_world(96, 48)};

  // 3a. Projection.
  md << "## 3. Precision modes, measured\n\n"
     << "### 3a. The view transform\n\n"
     << "World vertices to plot steps with the README's convention, four ways: the core's "
        "fixed-point Q16.16 and Q2.30, and float and double (benchmark-only). Error: distance of "
        "each projected coordinate from the long-double projection, in steps. Topological errors: "
        "CUT on the projected scene against CUT on the long-double scene rounded to steps "
        "(crossings missed, invented, and with front and back swapped). Time: median of "
     << runs << " runs, nanoseconds per vertex.\n\n"
     << "| scene | mode | ns / vertex | max error | mean error | missed / invented / flipped |\n"
     << "|---|---|---:|---:|---:|---:|\n";
  Series proj_pts{"projection", "#9467bd", {}};
  for (const World& w : worlds) {
    const auto exact = fit<long double>(view, rotate<long double>(view, w.vertices));
    std::vector<Point3> rounded;
    for (const auto& q : exact)
      rounded.push_back(
          {int32_t(std::lround(q[0])), int32_t(std::lround(q[1])), int32_t(std::lround(q[2]))});
    const auto ref_x = crossings(edges_of(rounded, w.pairs));
    struct Mode {
      const char* name;
      std::vector<Point3> (*fn)(const View&, const std::vector<Point3>&);
    };
    const Mode modes[] = {
        {"Q16.16 (core)",
         [](const View& v, const std::vector<Point3>& p) {
           std::vector<Point3> o(p.size());
           must(project_points_with<16>(v, p.data(), uint32_t(p.size()), o.data()));
           return o;
         }},
        {"Q2.30 (core, default)",
         [](const View& v, const std::vector<Point3>& p) {
           std::vector<Point3> o(p.size());
           must(project_points_with<30>(v, p.data(), uint32_t(p.size()), o.data()));
           return o;
         }},
        {"float (bench only)", &project_float<float>},
        {"double (bench only)", &project_float<double>}};
    for (const Mode& m : modes) {
      std::vector<double> t;
      std::vector<Point3> got;
      for (int r = 0; r < runs + 1; ++r) {
        const double t0 = now_ms();
        got = m.fn(view, w.vertices);
        if (r > 0) t.push_back(now_ms() - t0);
      }
      double worst = 0, sum = 0;
      for (size_t i = 0; i < got.size(); ++i) {
        const double e[3] = {double(std::fabs(got[i].x - exact[i][0])),
                             double(std::fabs(got[i].y - exact[i][1])),
                             double(std::fabs(got[i].z - exact[i][2]) / kCoordMax * 20000)};
        for (double x : e) worst = std::max(worst, x), sum += x;
      }
      const auto got_x = crossings(edges_of(got, w.pairs));
      size_t missed = 0, invented = 0, flipped = 0;
      for (const auto& c : ref_x)
        if (!got_x.count(c)) got_x.count({c.second, c.first}) ? ++flipped : ++missed;
      for (const auto& c : got_x)
        if (!ref_x.count(c) && !ref_x.count({c.second, c.first})) ++invented;
      const double ns = median(t) * 1e6 / double(w.vertices.size());
      md << "| " << w.name << " | " << m.name << " | " << fmt(ns, 1) << " | " << fmt(worst, 3)
         << " | " << fmt(sum / double(3 * got.size()), 4) << " | " << missed << " / " << invented
         << " / " << flipped << " |\n";
    }
  }
  md << "\nDepth errors are scaled to the plot's 20,000-step width so the columns compare. The "
        "rounded long-double scene is itself only a reference: a coordinate that lands within a "
        "hair of a half step can round either way, so a mode within 0.5 + epsilon steps can "
        "still differ from it by one step and change a crossing that is a near-tie.\n\n";

  // 3b. DRAW.
  md << "### 3b. DRAW: square roots and position grids\n\n"
     << "The paper's halo (W = 50) in six modes against the long-double reference of the same "
        "definition. Error: largest and mean distance, in steps, of a span end from the "
        "reference's, on edges cut into as many spans as the reference cuts them. Edges ±: edges "
        "cut into a different number of spans (a gap that grows may swallow a short span or "
        "merge with its neighbour): a change of topology in the drawing. CUT is exact in every "
        "mode, so no mode can miss a crossing or "
        "swap front and back.\n\n"
     << "| scene | square root | positions | DRAW ms | ns / edge | max error | mean error | "
        "edges ± |\n|---|---|---|---:|---:|---:|---:|---:|\n";
  std::map<std::string, std::pair<double, double>> front;  // mode -> (time ratio, max error)
  std::vector<std::pair<std::string, std::vector<Edge3>>> scenes;
  for (const World& w : worlds) {
    std::vector<Point3> p(w.vertices.size());
    must(project_points(view, w.vertices.data(), uint32_t(p.size()), p.data()));
    scenes.push_back({w.name, edges_of(p, w.pairs)});
  }
  scenes.push_back({"random, N = 20,000, L = 0.02", host::paper_random(20000, 20000, 8)});
  double worst_default = 0, default_ratio = 0, default_pipeline_ratio = 0;
  for (const auto& [name, edges] : scenes) {
    std::vector<uint64_t> storage;
    CutSet set;
    const double cut_ms = time_cut(edges, CutParams{}, runs, &storage, &set).total;
    const auto ref = reference::draw_ref(edges, reference_cuts(edges, set), 50, false);
    std::vector<ModeResult> results = {run_draw_mode<DrawPrecision<SqrtExact, PositionBits<32>>>(
                                           "exact root|Q0.32", set, ref, runs),
                                       run_draw_mode<DrawPrecision<SqrtNewton, PositionBits<32>>>(
                                           "Newton, 2 steps|Q0.32", set, ref, runs),
                                       run_draw_mode<DrawPrecision<SqrtTable, PositionBits<32>>>(
                                           "table, 256|Q0.32", set, ref, runs),
                                       run_draw_mode<DrawPrecision<SqrtExact, PositionBits<16>>>(
                                           "exact root|Q0.16", set, ref, runs),
                                       run_draw_mode<DrawPrecision<SqrtNewton, PositionBits<16>>>(
                                           "Newton, 2 steps|Q0.16", set, ref, runs),
                                       run_draw_mode<DrawPrecision<SqrtTable, PositionBits<16>>>(
                                           "table, 256|Q0.16", set, ref, runs)};
    double cheapest = 1e300;
    for (const auto& r : results) cheapest = std::min(cheapest, r.ms);
    for (const auto& r : results) {
      const std::string sqrt_name = r.name.substr(0, r.name.find('|'));
      const std::string pos_name = r.name.substr(r.name.find('|') + 1);
      const bool is_default = r.name == "exact root|Q0.32";
      md << "| " << name << " | " << sqrt_name << (is_default ? " **(default)**" : "") << " | "
         << pos_name << " | " << fmt(r.ms, 2) << " | " << fmt(r.ms * 1e6 / double(edges.size()), 1)
         << " | " << fmt(r.max_err, 3) << " | " << fmt(r.mean_err, 4) << " | " << r.span_diff
         << " |\n";
      auto& f = front[r.name];
      f.first = std::max(f.first, r.ms / cheapest);
      f.second = std::max(f.second, r.max_err);
      if (is_default) {
        worst_default = std::max(worst_default, r.max_err);
        default_ratio = std::max(default_ratio, r.ms / cheapest);
        default_pipeline_ratio =
            std::max(default_pipeline_ratio, (cut_ms + r.ms) / (cut_ms + cheapest));
      }
    }
  }
  std::vector<Series> series;
  const char* colors[] = {"#2ca02c", "#1f77b4", "#d62728", "#98df8a", "#aec7e8", "#ff9896"};
  int ci = 0;
  for (const auto& [mode, p] : front) {
    std::string label = mode;
    label.replace(label.find('|'), 1, ", ");
    if (mode == "exact root|Q0.32") label += " (default)";
    series.push_back({label, colors[ci++ % 6], {{p.first, p.second}}});
  }
  write_chart(dir + "/precision_pareto.svg",
              "DRAW modes: worst error against time (worst scene of each)",
              "time / cheapest mode on the same scene", "max error, steps", series, false);
  md << "\n![error against time for the DRAW modes](precision_pareto.png)\n\n"
     << "**The default** is exact roots with Q0.32 positions, and Q2.30 for the view: in this "
        "run its worst span error was "
     << fmt(worst_default, 3)
     << " steps (the goal: at most 0.5, which is the plotter grid's own "
        "rounding), with no topological error possible (CUT is exact), at "
     << fmt(default_ratio, 2) << "x the cheapest mode's DRAW time on the worst scene, and "
     << fmt(default_pipeline_ratio, 2)
     << "x its CUT + DRAW time (the goal: at most 1.2x; the mode changes DRAW only, so the "
        "plot's whole cost is CUT + DRAW). Time on a shared machine is noisy at a few hundred "
        "microseconds; "
        "sections 3b' and 3c count instructions instead, which noise cannot blur. The exact root "
        "is the table's upper bound, two "
        "Newton steps and a check of squares (exact against a 128-bit reference in the "
        "`numeric` test); the bit-pair root it replaced made DRAW 5x slower. "
        "The table root saves the two divisions (on the Cortex-M4 each is a library call of "
        "dozens of cycles) at worst errors of several steps where crossings are near-parallel, "
        "because W / sin(theta) magnifies its 0.8 % excess; Newton's 2.5 % is worse still. Q0.16 "
        "positions are the one mode whose error grows with the edges: "
        "a long edge's gap ends move by up to |edge| / 65536 steps.\n\n"
     << "### Coordinate resolution: why there is no separate 15-bit mode\n\n"
     << "The bit budgets, from `core/include/haloplot/geometry/contract.h` (static_asserted "
        "there):\n\n"
     << "| product | 15-bit coordinates | 20-bit coordinates | int64? |\n|---|---:|---:|---|\n"
     << "| coordinate difference | 16 | 21 | yes |\n"
     << "| orientation (cross product): CUT's crossing test | 32 | 42 | yes |\n"
     << "| exact depth at a crossing (coordinate x cross) | 47 | 62 | yes |\n"
     << "| exact halo discriminant b^2 - a c | 65 | 85 | no: 128-bit limbs |\n\n"
     << "Every CUT predicate already fits int64 at 20 bits, so a 15-bit mode would run the "
        "same instructions; the one product that needs more than 64 bits, the exact halo's "
        "discriminant, still does at 15 bits. The same instructions therefore run whatever "
        "part of the 20 bits a scene uses, and the plot area (about 2^14.3 steps) leaves five "
        "of them idle: section 4 spends them as sub-step units, which is the resolution axis "
        "that changes the drawing.\n\n";
}

size_t draw_once_in_mode(int k) {
  View view;
  const World w = cube_world(28);
  std::vector<Point3> p(w.vertices.size());
  must(project_points(view, w.vertices.data(), uint32_t(p.size()), p.data()));
  const std::vector<Edge3> edges = edges_of(p, w.pairs);
  std::vector<uint64_t> storage;
  CutSet set;
  time_cut(edges, CutParams{}, 1, &storage, &set);
  std::vector<Gap> scratch(draw_scratch_bytes(set) / sizeof(Gap) + 1);
  size_t spans = 0;
  const SpanSink sink{[](void* c, const Span&) {
                        ++*static_cast<size_t*>(c);
                        return Status::kOk;
                      },
                      &spans};
  const DrawParams dp{50, HaloMode::kPaper};
  void* s = scratch.data();
  const size_t b = scratch.size() * sizeof(Gap);
  switch (k) {
    case 0:
      must(draw_with<DrawPrecision<SqrtExact, PositionBits<32>>>(set, dp, s, b, sink, nullptr));
      break;
    case 1:
      must(draw_with<DrawPrecision<SqrtNewton, PositionBits<32>>>(set, dp, s, b, sink, nullptr));
      break;
    case 2:
      must(draw_with<DrawPrecision<SqrtTable, PositionBits<32>>>(set, dp, s, b, sink, nullptr));
      break;
    case 3:
      must(draw_with<DrawPrecision<SqrtExact, PositionBits<16>>>(set, dp, s, b, sink, nullptr));
      break;
    case 4:
      must(draw_with<DrawPrecision<SqrtNewton, PositionBits<16>>>(set, dp, s, b, sink, nullptr));
      break;
    default:
      must(draw_with<DrawPrecision<SqrtTable, PositionBits<16>>>(set, dp, s, b, sink, nullptr));
      break;
  }
  return spans;
}

}  // namespace bench
