// The memory contract, checked on every public entry that takes a caller buffer: with the
// buffer at offsets 1 to 7 from an 8-byte boundary the entry returns kMisalignedBuffer and
// leaves every byte of the buffer as it was; at offset 8 (another aligned address) it gives
// what it gave at offset 0. Freestanding, so the same checks run on the host (CTest
// `misaligned_buffers`) and on the Cortex-M4 and M3 under QEMU (`firmware_misaligned`,
// `firmware_mps2_misaligned`), where an access a misaligned buffer causes would fault.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/band/conductor.h"
#include "haloplot/band/edge_source.h"
#include "haloplot/band/solid_source.h"
#include "haloplot/cut/cut.h"
#include "haloplot/draw/draw.h"
#include "haloplot/job/job.h"
#include "haloplot/motion/path_plan.h"
#include "haloplot/motion/planner.h"
#include "haloplot/protocol/job_server.h"
#include "haloplot/scene/cube_array.h"
#include "haloplot/solid/hidden_lines.h"
#include "haloplot/surface/hidden_surface.h"
#include "haloplot/view/projection.h"
#include "haloplot/view2d/polygon_view.h"

namespace haloplot::misaligned {

// How a platform reports: each entry's verdict per offset, as text it can print.
struct Report {
  void (*result)(void* ctx, const char* entry, uint32_t offset, Status got, bool pass);
  void* ctx;
};

// FNV-1a over the values a run gives (field by field: never struct padding).
struct Digest {
  uint64_t h = 1469598103934665603ull;
  void add(uint64_t v) {
    for (int i = 0; i < 8; ++i) {
      h ^= (v >> (8 * i)) & 0xff;
      h *= 1099511628211ull;
    }
  }
  void add_edge(const Edge3& e) {
    add(uint64_t(uint32_t(e.a.x)) << 32 | uint32_t(e.a.y));
    add(uint64_t(uint32_t(e.b.x)) << 32 | uint32_t(e.b.y));
  }
};

constexpr size_t kPoolBytes = 32 * 1024;
constexpr uint8_t kPattern = 0xa5;
alignas(8) inline uint8_t pool[kPoolBytes + 16];
alignas(8) inline uint8_t aux[kPoolBytes];  // a second, aligned buffer (CUTSETs, other halves)

inline void fill_pool() {
  for (uint8_t& b : pool) b = kPattern;
}
inline bool pool_untouched() {
  for (uint8_t b : pool)
    if (b != kPattern) return false;
  return true;
}

// Runs `run(buffer, bytes, digest)` at offsets 0..8 of the pool with `bytes` each time; returns
// the failures. Offset 0 must give kOk (else nothing was tested); 1..7 kMisalignedBuffer with
// the pool untouched; 8 kOk and offset 0's digest.
template <typename Run>
uint32_t probe(const Report& report, const char* entry, size_t bytes, Run run) {
  uint32_t failures = 0;
  uint64_t reference = 0;
  for (uint32_t offset = 0; offset <= 8; ++offset) {
    fill_pool();
    Digest d;
    const Status s =
        bytes > kPoolBytes ? Status::kWorkspaceTooSmall : run(pool + offset, bytes, &d);
    bool pass;
    if (offset == 0) {
      pass = ok(s);
      reference = d.h;
    } else if (offset == 8) {
      pass = ok(s) && d.h == reference;
    } else {
      pass = s == Status::kMisalignedBuffer && pool_untouched();
    }
    report.result(report.ctx, entry, offset, s, pass);
    if (!pass) ++failures;
  }
  return failures;
}

// The scenes: 3 x 3 cubes as projected edges (CUT, DRAW, the path, bands, jobs), and 2 solid
// cubes with faces (hidden lines and surfaces).
constexpr CubeArrayParams kCubes{3, 6000, 5000, 200};
constexpr uint32_t kEdges = 12 * 3 * 3;
inline Edge3 edges[kEdges];
constexpr uint32_t kCrossingCapacity = 128;  // the scene has 82

struct Solid {
  Point3 world[16], screen[16];
  uint32_t pairs[2 * 24];
  Triangle tris[24];
  SolidInput in;
};
inline Solid solid;

inline Status build_scenes() {
  const Status s = cube_array(kCubes, edges, kEdges);
  if (!ok(s)) return s;
  static const int kQuads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                   {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  uint32_t nv = 0, ne = 0, nt = 0;
  for (int32_t c = 0; c < 2; ++c) {
    const uint32_t base = nv;
    for (int k = 0; k < 8; ++k)
      solid.world[nv++] =
          Point3{c * 70 + (k & 1) * 100, c * 40 + ((k >> 1) & 1) * 100, ((k >> 2) & 1) * 100};
    for (int q = 0; q < 6; ++q) {
      const uint32_t v[4] = {base + uint32_t(kQuads[q][0]), base + uint32_t(kQuads[q][1]),
                             base + uint32_t(kQuads[q][2]), base + uint32_t(kQuads[q][3])};
      const uint32_t poly = nt / 2;
      solid.tris[nt++] = Triangle{{v[0], v[1], v[2]}, poly};
      solid.tris[nt++] = Triangle{{v[0], v[2], v[3]}, poly};
    }
    for (uint32_t a = 0; a < 8; ++a)
      for (uint32_t bit = 1; bit < 8; bit <<= 1)
        if (!(a & bit)) {
          solid.pairs[ne++] = base + a;
          solid.pairs[ne++] = base + (a | bit);
        }
  }
  View view;
  view.substep_bits = 0;
  const Status ps = project_points(view, solid.world, nv, solid.screen);
  solid.in = SolidInput{solid.screen, nv, solid.pairs, ne / 2, solid.tris, nt, nullptr};
  return ps;
}

inline SpanSink span_digest(Digest* d) {
  return SpanSink{[](void* ctx, const Span& s) {
                    auto* dg = static_cast<Digest*>(ctx);
                    dg->add(s.edge);
                    dg->add(uint64_t(s.t0));
                    dg->add(uint64_t(s.t1));
                    return Status::kOk;
                  },
                  d};
}

inline void add_points(Digest* d, const PathPoint* p, uint32_t n) {
  for (uint32_t i = 0; i < n; ++i) d->add(uint64_t(uint32_t(p[i].x)) << 32 | uint32_t(p[i].y));
  d->add(n);
}

// CUT (both of its buffers), DRAW, the path and the planner, one buffer misaligned at a time.
inline uint32_t check_cut_draw_path(const Report& r) {
  CutParams params;
  params.compact_cells = false;
  CutPlan plan;
  if (!ok(plan_cut(edges, kEdges, params, &plan))) return 1;
  const size_t storage = cutset_bytes(kEdges, kCrossingCapacity);
  auto digest_cutset = [](const CutSet& cs, Digest* d) {
    d->add(cs.n_crossings);
    for (uint32_t i = 0; i < cs.n_crossings; ++i)
      d->add(uint64_t(cs.crossings[i].behind) << 32 ^ cs.crossings[i].front ^ cs.crossings[i].t);
  };
  uint32_t f = probe(r, "run_cut scratch", plan.scratch_bytes, [&](void* b, size_t n, Digest* d) {
    CutSet cs;
    const Status s = run_cut(plan, edges, b, n, aux, storage, &cs, nullptr);
    digest_cutset(cs, d);
    return s;
  });
  f += probe(r, "run_cut cutset storage", storage, [&](void* b, size_t n, Digest* d) {
    CutSet cs;
    const Status s = run_cut(plan, edges, aux, plan.scratch_bytes, b, n, &cs, nullptr);
    digest_cutset(cs, d);
    return s;
  });
  // One aligned CUTSET in aux for DRAW; the spans it draws for the path.
  CutSet cs;
  const size_t storage_round = (storage + 7) & ~size_t{7};
  if (!ok(run_cut(plan, edges, aux + storage_round, kPoolBytes - storage_round, aux, storage, &cs,
                  nullptr)))
    return f + 1;
  const DrawParams dp{20, HaloMode::kPaper};
  f += probe(r, "draw scratch", draw_scratch_bytes(cs), [&](void* b, size_t n, Digest* d) {
    return draw(cs, dp, b, n, span_digest(d), nullptr);
  });
  static Segment2 spans[kEdges];
  static PathPoint points[2 * kEdges];
  for (uint32_t i = 0; i < kEdges; ++i)
    spans[i] = Segment2{edges[i].a.x, edges[i].a.y, edges[i].b.x, edges[i].b.y};
  f += probe(r, "plan_path workspace", path_plan_bytes(kEdges), [&](void* b, size_t n, Digest* d) {
    uint32_t count = 0;
    const Status s =
        plan_path(spans, kEdges, PenAt{0, 0}, b, n, points, 2 * kEdges, &count, nullptr, PathEnd{});
    add_points(d, points, count);
    return s;
  });
  Machine m;
  PlotterEffects fx;
  fx.acceleration = true;
  f += probe(r, "MotionPlanner::init workspace", MotionPlanner::workspace_bytes(fx),
             [&](void* b, size_t n, Digest* d) {
               MotionPlanner planner;
               const Status s = planner.init(m, fx, points, 2 * kEdges, b, n);
               MotionItem item;
               while (ok(s) && planner.next(&item)) {
                 d->add(uint64_t(uint32_t(item.delta[0])) << 32 | uint32_t(item.delta[1]));
                 d->add(item.entry_v2 ^ item.exit_v2);
               }
               return s;
             });
  return f;
}

// A concave polygon seen from outside: the 2-D visibility stage.
inline uint32_t check_view2d(const Report& r) {
  static const Point2 poly[] = {{0, 0}, {400, 0}, {400, 300}, {200, 100}, {0, 300}};
  const uint32_t n = 5;
  return probe(r, "view2d scratch", view2d_scratch_bytes(n), [&](void* b, size_t bytes, Digest* d) {
    return view2d(poly, n, Point2{200, 900}, b, bytes,
                  VisibleSink{[](void* ctx, const VisibleSpan& s) {
                                auto* dg = static_cast<Digest*>(ctx);
                                dg->add(s.edge);
                                dg->add(uint64_t(s.s0.num) ^ uint64_t(s.s1.num));
                                return Status::kOk;
                              },
                              d},
                  nullptr);
  });
}

// Hidden lines and hidden surfaces of the two solid cubes.
inline uint32_t check_solids(const Report& r) {
  HiddenParams hp;
  hp.crossing_capacity = 64;
  hp.incidence_capacity = 32;
  hp.outline = true;
  uint32_t f = probe(r, "hidden_lines buffer", 16 * 1024, [&](void* b, size_t n, Digest* d) {
    HiddenReport report;
    return hidden_lines(solid.in, hp, b, n,
                        HiddenSink{nullptr,
                                   [](void* ctx, const HiddenPiece& p) {
                                     auto* dg = static_cast<Digest*>(ctx);
                                     dg->add(p.edge);
                                     dg->add(uint64_t(p.t0) ^ uint64_t(p.t1) ^ uint64_t(p.hidden));
                                     return Status::kOk;
                                   },
                                   nullptr, d},
                        &report);
  });
  HatchParams hatch;
  hatch.spacing = 300;  // 130 strokes
  // The query leaves out the hatching's crossing list: a run that ends short says the bytes.
  size_t hs_bytes = hidden_surface_bytes(solid.in, FranklinParams{}, 64, 32, 64);
  auto surfaces = [&](void* b, size_t n, Digest* d, HiddenSurfaceStats* st) {
    return hidden_surface(solid.in, FranklinParams{}, hatch, 64, 32, 64, b, n,
                          FranklinSink{[](void* ctx, const FranklinPiece& p) {
                                         auto* dg = static_cast<Digest*>(ctx);
                                         dg->add(p.edge);
                                         dg->add(uint64_t(p.t0) ^ uint64_t(p.t1) ^ p.hidden);
                                         return Status::kOk;
                                       },
                                       d},
                          HatchSink{[](void* ctx, const HatchStroke& s) {
                                      auto* dg = static_cast<Digest*>(ctx);
                                      dg->add(s.face);
                                      dg->add_edge(s.line);
                                      return Status::kOk;
                                    },
                                    d},
                          st);
  };
  Digest unused;
  HiddenSurfaceStats first;
  for (int round = 0; round < 3 && hs_bytes <= kPoolBytes; ++round)
    if (surfaces(aux, hs_bytes, &unused, &first) == Status::kWorkspaceTooSmall &&
        first.bytes_needed > hs_bytes)
      hs_bytes = first.bytes_needed;
  f += probe(r, "hidden_surface buffer", hs_bytes, [&](void* b, size_t n, Digest* d) {
    HiddenSurfaceStats st;
    return surfaces(b, n, d, &st);
  });
  return f;
}

// Every band's path points, drained from a conductor that began well.
inline Status drain_bands(BandConductor* bc, Status begun, Digest* d) {
  if (!ok(begun)) return begun;
  for (;;) {
    const PathPoint* p = nullptr;
    uint32_t n = 0;
    const Status s = bc->next(&p, &n);
    if (!ok(s) || n == 0) return s;
    add_points(d, p, n);
  }
}

// The band conductor's arena, for an edge plot and a solid's.
inline uint32_t check_bands(const Report& r) {
  static BandConductor bc;
  BandSpec spec;
  spec.draw = DrawParams{20, HaloMode::kPaper};
  spec.cut.compact_cells = false;
  uint32_t f = probe(r, "BandConductor::begin arena", 24 * 1024, [&](void* b, size_t n, Digest* d) {
    return drain_bands(&bc, bc.begin(spec, array_edge_source(edges, kEdges), b, n), d);
  });
  JobSpec hidden;
  hidden.drawing = DrawingEffect::kHiddenRemoved;
  const BandSpec solid_spec = band_spec(hidden);
  f += probe(r, "BandConductor::begin_solid arena", 24 * 1024, [&](void* b, size_t n, Digest* d) {
    return drain_bands(&bc, bc.begin_solid(solid_spec, array_solid_source(&solid.in, true), b, n),
                       d);
  });
  return f;
}

// The job: prepare (edges and solids), redraw from the CUTSET it left, and the planner.
inline uint32_t check_jobs(const Report& r) {
  JobSpec spec;
  spec.draw = DrawParams{20, HaloMode::kPaper};
  spec.cut.compact_cells = false;
  JobBytes jb;
  if (!ok(job_bytes(spec, Edges{edges, kEdges}, kCrossingCapacity, &jb))) return 1;
  static PreparedJob job;
  uint32_t f = probe(r, "job_prepare buffer", jb.total(), [&](void* b, size_t n, Digest* d) {
    const Status s =
        job_prepare(spec, Edges{edges, kEdges}, kCrossingCapacity, b, n, &job, nullptr);
    add_points(d, job.points, job.n_points);
    return s;
  });
  JobSpec wider = spec;
  wider.draw.halo = 40;
  f += probe(r, "job_redraw buffer", jb.total(), [&](void* b, size_t n, Digest* d) {
    // The CUTSET a redraw starts from: prepared in the same buffer when it is aligned (at a
    // misaligned one the redraw must refuse before it reads anything).
    Status s = Status::kOk;
    if (!buffer_misaligned(b))
      s = job_prepare(spec, Edges{edges, kEdges}, kCrossingCapacity, b, n, &job, nullptr);
    if (ok(s)) s = job_redraw(wider, Edges{edges, kEdges}, kCrossingCapacity, b, n, &job, nullptr);
    add_points(d, job.points, job.n_points);
    return s;
  });
  JobSpec hidden = spec;
  hidden.drawing = DrawingEffect::kHiddenRemoved;
  f += probe(r, "job_prepare_solid buffer", 20 * 1024, [&](void* b, size_t n, Digest* d) {
    HiddenReport report;
    const Status s = job_prepare_solid(hidden, solid.in, 64, 32, b, n, &job, nullptr, &report);
    add_points(d, job.points, job.n_points);
    return s;
  });
  // The counting passes that size the jobs.
  f += probe(r, "job_crossings buffer", jb.total(), [&](void* b, size_t n, Digest* d) {
    uint32_t capacity = 0;
    const Status s = job_crossings(spec, Edges{edges, kEdges}, b, n, &capacity);
    d->add(capacity);
    return s;
  });
  f += probe(r, "job_solid_bytes buffer", 20 * 1024, [&](void* b, size_t n, Digest* d) {
    HiddenReport report;
    StageNeeds needs;
    const Status s = job_solid_bytes(hidden, solid.in, b, n, &needs, &report);
    d->add(needs.crossings);
    d->add(needs.incidences);
    d->add(needs.bytes);
    return s;
  });
  // The planner of a job prepared in aux.
  PreparedJob ready;
  if (!ok(job_prepare(spec, Edges{edges, kEdges}, kCrossingCapacity, aux, kPoolBytes, &ready,
                      nullptr)))
    return f + 1;
  f += probe(r, "init_planner workspace", MotionPlanner::workspace_bytes(spec.effects),
             [&](void* b, size_t n, Digest* d) {
               MotionPlanner planner;
               const Status s = init_planner(&planner, spec, ready, b, n);
               MotionItem item;
               while (ok(s) && planner.next(&item)) d->add(item.length_q8);
               return s;
             });
  return f;
}

// Everything; the failures (0: the contract holds).
inline uint32_t check_all(const Report& r) {
  if (!ok(build_scenes())) return 1;
  return check_cut_draw_path(r) + check_view2d(r) + check_solids(r) + check_bands(r) +
         check_jobs(r);
}

}  // namespace haloplot::misaligned
