// Size queries that are bounds: each query of the core, asked for a test scene, must answer at
// least what its run uses and at most 1.5 times it. "Used" is measured from outside, never read
// from the run's own report: the smallest capacity, or the smallest fixed buffer, with which the
// run succeeds (a binary search over runs; a run's success is monotone in both). Freestanding,
// so the same checks run on the host (CTest `size_bounds`) and on the chip under QEMU
// (`riscv_qemu`). `scale_permille` scales every answer before it is judged: the control asks
// with 900 (each query 10 % short), and every check must then fail.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/cut/cut.h"
#include "haloplot/draw/draw.h"
#include "haloplot/job/job.h"
#include "haloplot/motion/path_plan.h"
#include "haloplot/motion/planner.h"
#include "haloplot/scene/cube_array.h"
#include "haloplot/scene/random_edges.h"
#include "haloplot/solid/hidden_lines.h"
#include "haloplot/surface/hidden_surface.h"
#include "haloplot/view/projection.h"
#include "haloplot/view2d/polygon_view.h"

namespace haloplot::size_bounds {

// How a platform reports: one line per (query, scene).
struct Report {
  void (*result)(void* ctx, const char* query, const char* scene, uint64_t asked, uint64_t used,
                 bool pass);
  void* ctx;
};

constexpr size_t kPoolBytes = 256 * 1024;
alignas(8) inline uint8_t pool[kPoolBytes];
alignas(8) inline uint8_t aux[64 * 1024];  // a second buffer (a CUTSET for DRAW)

// The smallest value in [1, limit] at which fits() holds (fits is monotone); 0 if none does.
template <typename Fits>
uint64_t smallest_fit(uint64_t limit, Fits fits) {
  if (limit == 0 || !fits(limit)) return 0;
  uint64_t lo = 0, hi = limit;  // fits(hi), !fits(lo) (or lo == 0)
  while (hi - lo > 1) {
    const uint64_t mid = lo + (hi - lo) / 2;
    if (fits(mid))
      hi = mid;
    else
      lo = mid;
  }
  return hi;
}

struct Checker {
  Report report;
  uint32_t scale_permille = 1000;
  uint32_t failures = 0;
  uint32_t checks = 0;
  // Judges one query's answer against the measured use.
  void judge(const char* query, const char* scene, uint64_t answer, uint64_t used) {
    const uint64_t asked = answer * scale_permille / 1000;
    const bool pass = used > 0 && asked >= used && 2 * asked <= 3 * used;
    ++checks;
    if (!pass) ++failures;
    report.result(report.ctx, query, scene, asked, used, pass);
  }
};

// ---- Scenes -------------------------------------------------------------------------------

constexpr uint32_t kMaxEdges = 12 * 4 * 4;
struct EdgeScene {
  const char* name;
  Edge3 edges[kMaxEdges];
  uint32_t n;
};
inline EdgeScene edge_scenes[4];

inline Status build_edge_scenes() {
  const CubeArrayParams cubes[3] = {
      {2, 6000, 5000, 200}, {3, 6000, 5000, 200}, {4, 20000, 16000, 400}};
  const char* names[3] = {"cubes 2x2", "cubes 3x3", "cubes 4x4"};
  for (int i = 0; i < 3; ++i) {
    edge_scenes[i].name = names[i];
    edge_scenes[i].n = cube_array_edges(cubes[i]);
    const Status s = cube_array(cubes[i], edge_scenes[i].edges, kMaxEdges);
    if (!ok(s)) return s;
  }
  edge_scenes[3].name = "random 150";
  edge_scenes[3].n = 150;
  random_edges(150, 150000, 7, edge_scenes[3].edges);
  return Status::kOk;
}

// Solid cubes with faces, k x k of them overlapping in a view from above and aside.
constexpr uint32_t kMaxCubes = 9;
struct SolidScene {
  const char* name;
  Point3 world[8 * kMaxCubes], screen[8 * kMaxCubes];
  uint32_t pairs[2 * 12 * kMaxCubes];
  Triangle tris[12 * kMaxCubes];
  SolidInput in;
};
inline SolidScene solid_scenes[2];

inline Status build_solid(SolidScene* sc, const char* name, int32_t k, int32_t step) {
  static const int kQuads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                   {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  sc->name = name;
  uint32_t nv = 0, ne = 0, nt = 0;
  for (int32_t c = 0; c < k * k; ++c) {
    const uint32_t base = nv;
    const int32_t cx = (c % k) * step + (c / k) * 30, cy = (c / k) * step, cz = (c % 3) * 40;
    for (int v = 0; v < 8; ++v)
      sc->world[nv++] =
          Point3{cx + (v & 1) * 100, cy + ((v >> 1) & 1) * 100, cz + ((v >> 2) & 1) * 100};
    for (int q = 0; q < 6; ++q) {
      const uint32_t v[4] = {base + uint32_t(kQuads[q][0]), base + uint32_t(kQuads[q][1]),
                             base + uint32_t(kQuads[q][2]), base + uint32_t(kQuads[q][3])};
      const uint32_t poly = nt / 2;
      sc->tris[nt++] = Triangle{{v[0], v[1], v[2]}, poly};
      sc->tris[nt++] = Triangle{{v[0], v[2], v[3]}, poly};
    }
    for (uint32_t a = 0; a < 8; ++a)
      for (uint32_t bit = 1; bit < 8; bit <<= 1)
        if (!(a & bit)) {
          sc->pairs[ne++] = base + a;
          sc->pairs[ne++] = base + (a | bit);
        }
  }
  View view;
  view.substep_bits = 0;
  const Status s = project_points(view, sc->world, nv, sc->screen);
  sc->in = SolidInput{sc->screen, nv, sc->pairs, ne / 2, sc->tris, nt, nullptr};
  return s;
}

inline Status build_solid_scenes() {
  const Status s = build_solid(&solid_scenes[0], "solid cubes 2x2", 2, 70);
  return ok(s) ? build_solid(&solid_scenes[1], "solid cubes 3x3", 3, 70) : s;
}

// ---- Edge jobs, CUT, DRAW, the path ---------------------------------------------------------

inline JobSpec haloed_spec() {
  JobSpec spec;
  spec.draw = DrawParams{20, HaloMode::kPaper};
  spec.cut.compact_cells = false;
  return spec;
}

// job_prepare's crossing capacity (job_crossings) and its bytes (job_bytes) on one scene.
inline void check_edge_job(Checker& c, const EdgeScene& sc, const JobSpec& spec,
                           const char* bytes_query) {
  PreparedJob job;
  uint32_t capacity = 0;
  if (spec.drawing == DrawingEffect::kHaloed) {
    if (!ok(job_crossings(spec, Edges{sc.edges, sc.n}, pool, kPoolBytes, &capacity))) capacity = 0;
    const uint64_t used = smallest_fit(4 * (uint64_t{capacity} + 16), [&](uint64_t k) {
      return ok(job_prepare(spec, Edges{sc.edges, sc.n}, uint32_t(k - 1), pool, kPoolBytes, &job,
                            nullptr));
    });
    // Capacities start at 0: both sides one more, so a scene without crossings is judged too.
    c.judge("job_crossings", sc.name, uint64_t{capacity} + 1, used);
  }
  JobBytes b;
  if (!ok(job_bytes(spec, Edges{sc.edges, sc.n}, capacity, &b))) b.peak = 0;
  const uint64_t used = smallest_fit(kPoolBytes, [&](uint64_t bytes) {
    return ok(
        job_prepare(spec, Edges{sc.edges, sc.n}, capacity, pool, size_t(bytes), &job, nullptr));
  });
  c.judge(bytes_query, sc.name, b.total(), used);
}

// CUT as a sized stage, DRAW's scratch and the path's workspace on one scene.
inline void check_cut_draw_path(Checker& c, const EdgeScene& sc) {
  const JobSpec spec = haloed_spec();
  CutPlan plan;
  if (!ok(plan_cut(sc.edges, sc.n, spec.cut, &plan))) return c.judge("CutStage", sc.name, 0, 0);
  CutSet cs;
  CutStats st;
  CutStage stage{&plan, sc.edges, &cs, &st};
  StageNeeds needs;
  needs.crossings = 2048;  // generous: the count the run reports is then exact
  StageNeeds want = needs;
  if (!ok(stage.run(needs, pool, kPoolBytes, &want))) return c.judge("CutStage", sc.name, 0, 0);
  needs.crossings = cs.n_crossings;
  const uint64_t cut_used = smallest_fit(kPoolBytes, [&](uint64_t bytes) {
    StageNeeds w = needs;
    return ok(stage.run(needs, pool, size_t(bytes), &w));
  });
  c.judge("CutStage::bytes", sc.name, stage.bytes(needs), cut_used);

  // DRAW from a CUTSET of its own in aux.
  const size_t store = (cutset_bytes(sc.n, cs.n_crossings) + 7) & ~size_t{7};
  if (store + plan.scratch_bytes > sizeof aux ||
      !ok(run_cut(plan, sc.edges, aux + store, sizeof aux - store, aux, store, &cs, nullptr)))
    return c.judge("draw_scratch_bytes", sc.name, 0, 0);
  static Segment2 spans[kMaxEdges * 8];
  uint32_t n_spans = 0;
  struct Spans {
    Segment2* out;
    uint32_t* n;
    const Edge3* edges;
  } sink_ctx{spans, &n_spans, sc.edges};
  const SpanSink sink{[](void* ctx, const Span& s) {
                        auto* k = static_cast<Spans*>(ctx);
                        if (*k->n >= kMaxEdges * 8) return Status::kSinkFull;
                        const Edge3& e = k->edges[s.edge];
                        k->out[(*k->n)++] = Segment2{e.a.x, e.a.y, e.b.x, e.b.y};
                        return Status::kOk;
                      },
                      &sink_ctx};
  const uint64_t draw_used = smallest_fit(kPoolBytes, [&](uint64_t bytes) {
    n_spans = 0;
    return ok(draw(cs, spec.draw, pool, size_t(bytes), sink, nullptr));
  });
  c.judge("draw_scratch_bytes", sc.name, draw_scratch_bytes(cs), draw_used);
  n_spans = 0;  // every span, for the path (the search's last run may have been short)
  if (!ok(draw(cs, spec.draw, pool, kPoolBytes, sink, nullptr)))
    return c.judge("path_plan_bytes", sc.name, 0, 0);

  static Segment2 work[kMaxEdges * 8];
  static PathPoint points[kMaxEdges * 16];
  const uint64_t path_used = smallest_fit(kPoolBytes, [&](uint64_t bytes) {
    for (uint32_t i = 0; i < n_spans; ++i) work[i] = spans[i];
    uint32_t count = 0;
    return ok(plan_path(work, n_spans, PenAt{0, 0}, pool, size_t(bytes), points, kMaxEdges * 16,
                        &count, nullptr, PathEnd{}));
  });
  c.judge("path_plan_bytes", sc.name, path_plan_bytes(n_spans), path_used);

  // The planner's look-ahead workspace for the path's points, acceleration on.
  uint32_t n_points = 0;
  for (uint32_t i = 0; i < n_spans; ++i) work[i] = spans[i];
  if (!ok(plan_path(work, n_spans, PenAt{0, 0}, pool, kPoolBytes, points, kMaxEdges * 16, &n_points,
                    nullptr, PathEnd{})))
    return c.judge("MotionPlanner::workspace_bytes", sc.name, 0, 0);
  PlotterEffects fx;
  fx.acceleration = true;
  static MotionPlanner planner;
  const uint64_t ws_used = smallest_fit(kPoolBytes, [&](uint64_t bytes) {
    return ok(planner.init(spec.machine, fx, points, n_points, pool, size_t(bytes)));
  });
  c.judge("MotionPlanner::workspace_bytes", sc.name, MotionPlanner::workspace_bytes(fx), ws_used);
}

// The 2-D view of polygons: a concave one, and a comb of many teeth, seen from outside.
inline void check_view2d(Checker& c) {
  static Point2 comb[2 * 40 + 2];
  uint32_t n = 0;
  for (int32_t k = 0; k < 40; ++k) {
    comb[n++] = Point2{k * 100, 0};
    comb[n++] = Point2{k * 100 + 50, 400 + 37 * (k % 5)};
  }
  comb[n++] = Point2{4000, -300};
  comb[n++] = Point2{0, -300};
  for (uint32_t i = 0; i < n / 2; ++i) {  // counter-clockwise, as the concave one
    const Point2 t = comb[i];
    comb[i] = comb[n - 1 - i];
    comb[n - 1 - i] = t;
  }
  static const Point2 concave[] = {{0, 0}, {400, 0}, {400, 300}, {200, 100}, {0, 300}};
  const VisibleSink sink{[](void*, const VisibleSpan&) { return Status::kOk; }, nullptr};
  auto one = [&](const char* name, const Point2* poly, uint32_t count, Point2 eye) {
    const uint64_t used = smallest_fit(kPoolBytes, [&](uint64_t bytes) {
      return ok(view2d(poly, count, eye, pool, size_t(bytes), sink, nullptr));
    });
    c.judge("view2d_scratch_bytes", name, view2d_scratch_bytes(count), used);
  };
  one("concave 5", concave, 5, Point2{200, 900});
  one("comb 82", comb, n, Point2{2000, 5000});
}

// ---- Solids ---------------------------------------------------------------------------------

inline void check_solid(Checker& c, const SolidScene& sc) {
  JobSpec spec = haloed_spec();
  spec.drawing = DrawingEffect::kHiddenRemoved;
  spec.hidden.outline = true;
  StageNeeds needs;
  HiddenReport r;
  if (!ok(job_solid_bytes(spec, sc.in, pool, kPoolBytes, &needs, &r))) needs = StageNeeds{};
  PreparedJob job;
  const uint64_t k_used = smallest_fit(4 * (uint64_t{needs.crossings} + 16), [&](uint64_t k) {
    return ok(job_prepare_solid(spec, sc.in, uint32_t(k - 1), needs.incidences + 64, pool,
                                kPoolBytes, &job, nullptr, &r));
  });
  c.judge("job_solid_bytes crossings", sc.name, uint64_t{needs.crossings} + 1, k_used);
  const uint64_t i_used = smallest_fit(4 * (uint64_t{needs.incidences} + 16), [&](uint64_t i) {
    return ok(job_prepare_solid(spec, sc.in, needs.crossings, uint32_t(i - 1), pool, kPoolBytes,
                                &job, nullptr, &r));
  });
  c.judge("job_solid_bytes incidences", sc.name, uint64_t{needs.incidences} + 1, i_used);
  const uint64_t used = smallest_fit(kPoolBytes, [&](uint64_t bytes) {
    return ok(job_prepare_solid(spec, sc.in, needs.crossings, needs.incidences, pool, size_t(bytes),
                                &job, nullptr, &r));
  });
  c.judge("job_solid_bytes", sc.name, needs.bytes, used);

  // The hidden surfaces (no hatching: its crossing list is the run's to report), with the
  // capacities its runs ask for.
  const FranklinParams fp;
  HiddenSurfaceStats st;
  const FranklinSink lines{[](void*, const FranklinPiece&) { return Status::kOk; }, nullptr};
  HiddenSurfaceStage hs{&sc.in, fp, HatchParams{}, lines, HatchSink{}, &st};
  StageNeeds cap;
  cap.crossings = cap.incidences = cap.segments = 1;
  for (int round = 0; round < 8; ++round) {
    StageNeeds want = cap;
    want.bytes = 0;
    const Status s = hs.run(cap, pool, kPoolBytes, &want);
    if (!is_shortfall(s) || !raise_needs(&cap, want)) break;
  }
  const uint32_t k = cap.crossings, i = cap.incidences, seg = cap.segments;
  const uint64_t hs_used = smallest_fit(kPoolBytes, [&](uint64_t bytes) {
    StageNeeds want = cap;
    return ok(hs.run(cap, pool, size_t(bytes), &want));
  });
  c.judge("hidden_surface_bytes", sc.name, hidden_surface_bytes(sc.in, fp, k, i, seg), hs_used);
}

// ---- Curves ---------------------------------------------------------------------------------

// Four cubic Bezier edges, two rising and two falling across each other, and two straight
// edges through them (the stack probe's scene, tests/firmware/stack).
struct CurveScene {
  BezierEdge3 curves[4];
  Edge3 segments[2];
};
inline CurveScene curve_scene;

inline void build_curve_scene() {
  for (int32_t i = 0; i < 4; ++i) {
    const int32_t y0 = i < 2 ? 0 : 4000, y1 = 4000 - y0, x = 3000 + 700 * i, z = 100 * i;
    curve_scene.curves[i] = BezierEdge3{{Point3{x, y0, z}, Point3{x + 3000, y0 + (y1 - y0) / 3, z},
                                         Point3{x - 2000, y0 + 2 * (y1 - y0) / 3, z + 50},
                                         Point3{x + 1500, y1, z + 80}}};
  }
  curve_scene.segments[0] = Edge3{Point3{1000, 2000, 30}, Point3{9000, 2100, 30}};
  curve_scene.segments[1] = Edge3{Point3{5000, 0, 350}, Point3{4800, 4000, 350}};
}

inline void check_curves(Checker& c) {
  JobSpec spec;
  spec.draw.halo = 60;
  const CurveJobScene scene{curve_scene.curves, 4, curve_scene.segments, 2};
  PreparedJob job;
  // The hit capacity and the bytes, from the counting passes.
  size_t bytes = 0;
  uint32_t hits = 0;
  if (!ok(job_curves_bytes(spec, scene, pool, kPoolBytes, &hits, &bytes))) bytes = 0;
  const uint64_t hits_used = smallest_fit(4 * (uint64_t{hits} + 16), [&](uint64_t k) {
    return ok(job_prepare_curves(spec, scene, uint32_t(k - 1), pool, kPoolBytes, &job, nullptr));
  });
  c.judge("job_curves_bytes hits", "curves 4+2", uint64_t{hits} + 1, hits_used);
  const uint64_t used = smallest_fit(kPoolBytes, [&](uint64_t b) {
    return ok(job_prepare_curves(spec, scene, hits, pool, size_t(b), &job, nullptr));
  });
  c.judge("job_curves_bytes", "curves 4+2", bytes, used);
}

// Every query on every scene; returns the failures (and the checks made, in *checks).
inline uint32_t check_all(const Report& report, uint32_t scale_permille, uint32_t* checks) {
  Checker c{report, scale_permille};
  if (!ok(build_edge_scenes()) || !ok(build_solid_scenes())) return 1;
  build_curve_scene();
  for (const EdgeScene& sc : edge_scenes) {
    check_edge_job(c, sc, haloed_spec(), "job_bytes (haloed)");
    JobSpec all = haloed_spec();
    all.drawing = DrawingEffect::kAllEdges;
    check_edge_job(c, sc, all, "job_bytes (all edges)");
    check_cut_draw_path(c, sc);
  }
  for (const SolidScene& sc : solid_scenes) check_solid(c, sc);
  check_curves(c);
  check_view2d(c);
  if (checks) *checks = c.checks;
  return c.failures;
}

}  // namespace haloplot::size_bounds
