// The stack each public entry that plots takes, measured on the chip (tests/firmware/
// stack_probe.sh, for the M0+, M4, M33 and RV32): the stack below the caller is painted, the
// entry runs on the scenes of firmware/selftest/misaligned_checks.h (3 x 3 cubes as edges, two
// solid cubes with faces) and a curve scene of its own, the band conductor's streamed entries on
// the bands of a plain run sent again, and the deepest word it overwrote gives its bytes, counted
// from the caller's stack pointer (its callees, the sinks and the call itself included). Prints
// "fw stack ENTRY=BYTES" per entry, then exits 0 if every entry ran well.
#include "haloplot/curve/bezier.h"
#include "platform/c_runtime.h"
#include "platform/semihosting.h"
#include "selftest/misaligned_checks.h"

using namespace haloplot;
using namespace haloplot::misaligned;

namespace {

uint32_t failures = 0;

__attribute__((noinline)) uintptr_t stack_pointer() {
  return reinterpret_cast<uintptr_t>(__builtin_frame_address(0));
}

// Paints from the stack's limit up to just below this function's own frame.
__attribute__((noinline)) void paint_stack() {
  volatile uint32_t here = 0;
  const uintptr_t top = reinterpret_cast<uintptr_t>(&here) - 32;
  for (uint32_t* p = &__stack_limit; reinterpret_cast<uintptr_t>(p) < top; ++p)
    *p = fw::kStackPaint;
}

// The lowest word the run overwrote.
__attribute__((noinline)) uintptr_t deepest_written() {
  const uint32_t* p = &__stack_limit;
  while (*p == fw::kStackPaint) ++p;
  return reinterpret_cast<uintptr_t>(p);
}

void report(const char* entry, uint32_t bytes, Status s) {
  char line[96];
  char* p = fw::append(line, "fw stack ");
  p = fw::append(p, entry);
  p = fw::append(p, "=");
  p = fw::append_u64(p, bytes);
  if (!ok(s)) {
    ++failures;
    p = fw::append(p, " FAILED: ");
    p = fw::append(p, status_name(s));
  }
  p = fw::append(p, "\n");
  fw::semihost_write(line, uint32_t(p - line));
}

// Runs `run()` on a painted stack and reports the bytes it took below this frame.
template <typename Run>
__attribute__((noinline)) void measure(const char* entry, Run run) {
  const uintptr_t sp = stack_pointer();
  paint_stack();
  const Status s = run();
  const uintptr_t low = deepest_written();
  report(entry, uint32_t(sp - low), s);
}

// A curve scene: four cubic Bezier edges, two rising and two falling across each other, and
// two straight edges through them, in plot steps.
BezierEdge3 curves[4];
Edge3 segments[2];
void build_curves() {
  for (int32_t i = 0; i < 4; ++i) {
    const int32_t y0 = i < 2 ? 0 : 4000, y1 = 4000 - y0, x = 3000 + 700 * i, z = 100 * i;
    curves[i] = BezierEdge3{{Point3{x, y0, z}, Point3{x + 3000, y0 + (y1 - y0) / 3, z},
                             Point3{x - 2000, y0 + 2 * (y1 - y0) / 3, z + 50},
                             Point3{x + 1500, y1, z + 80}}};
  }
  segments[0] = Edge3{Point3{1000, 2000, 30}, Point3{9000, 2100, 30}};
  segments[1] = Edge3{Point3{5000, 0, 350}, Point3{4800, 4000, 350}};
}

Status drain(BandConductor* bc) {
  for (;;) {
    const PathPoint* p = nullptr;
    uint32_t n = 0;
    const Status s = bc->next(&p, &n);
    if (!ok(s) || n == 0) return s;
  }
}

// A streamed plot's bands as a host sends them (host_sim/pipeline/band_stream.cpp's plan, made
// on the chip): the rows each band of a plain run committed, and what the band rule gathers
// for them, staged when the conductor asks for the band.
constexpr uint32_t kMaxBands = 64;
struct Stream {
  int32_t y0[kMaxBands], y1[kMaxBands];
  uint32_t n_bands = 0, next = 0;
  int32_t margin = 0;
  const SolidInput* solid = nullptr;  // a solid's bands (turn_wide off: rows of the page)
  Edge3 edges[kEdges];
  uint32_t ids[kEdges], pairs[2 * kEdges], vertex_ids[16];
  Point3 vertices[16];
  Triangle tris[24];
  StagedSolidBand staged;
};
Stream stream;

// The band rule's tests (core/band/band_rule.h, internal to the core): does an edge, or a
// triangle, reach a row of [lo, hi]?
bool edge_meets_rows(const Edge3& e, int64_t lo, int64_t hi) {
  const int32_t y0 = e.a.y < e.b.y ? e.a.y : e.b.y, y1 = e.a.y < e.b.y ? e.b.y : e.a.y;
  return y1 >= lo && y0 <= hi;
}
bool triangle_meets_rows(const Point3& a, const Point3& b, const Point3& c, int64_t lo,
                         int64_t hi) {
  const int32_t y0 = a.y < b.y ? (a.y < c.y ? a.y : c.y) : (b.y < c.y ? b.y : c.y);
  const int32_t y1 = a.y > b.y ? (a.y > c.y ? a.y : c.y) : (b.y > c.y ? b.y : c.y);
  return y1 >= lo && y0 <= hi;
}

PieceObserver band_noter() {
  PieceObserver o;
  o.band = [](void*, int32_t y0, int32_t y1) {
    if (stream.n_bands < kMaxBands) {
      stream.y0[stream.n_bands] = y0;
      stream.y1[stream.n_bands] = y1;
    }
    ++stream.n_bands;  // past kMaxBands: refused below
  };
  return o;
}

// The solid's part of band b: its drawn edges, triangles and vertices meeting rows [lo, hi].
void stage_solid(StreamedBand* band, int64_t lo, int64_t hi) {
  const SolidInput& in = *stream.solid;
  bool used[16] = {};
  uint32_t ne = 0, nt = 0, nv = 0;
  for (uint32_t i = 0; i < in.n_edges; ++i) {
    const uint32_t v0 = in.edge_pairs[2 * i], v1 = in.edge_pairs[2 * i + 1];
    if (!edge_meets_rows(Edge3{in.vertices[v0], in.vertices[v1]}, lo, hi)) continue;
    stream.ids[ne] = i;
    stream.pairs[2 * ne] = v0;
    stream.pairs[2 * ne++ + 1] = v1;
    used[v0] = used[v1] = true;
  }
  // Hatching reads whole polygons (runs of triangles with one id): all of one that meets.
  for (uint32_t t = 0; t < in.n_triangles;) {
    uint32_t end = t;
    bool meets = false;
    for (; end < in.n_triangles && in.triangles[end].polygon == in.triangles[t].polygon; ++end) {
      const uint32_t* v = in.triangles[end].v;
      meets = meets || triangle_meets_rows(in.vertices[v[0]], in.vertices[v[1]], in.vertices[v[2]],
                                           lo, hi + 1);
    }
    for (; meets && t < end; ++t) {
      const uint32_t* v = in.triangles[t].v;
      stream.tris[nt++] = in.triangles[t];
      used[v[0]] = used[v[1]] = used[v[2]] = true;
    }
    t = end;
  }
  for (uint32_t v = 0; v < in.n_vertices; ++v)
    if (used[v]) {
      stream.vertex_ids[nv] = v;
      stream.vertices[nv++] = in.vertices[v];
    }
  stream.staged =
      StagedSolidBand{stream.vertex_ids, stream.vertices, nv, stream.pairs, ne, stream.tris, nt};
  band->solid = &stream.staged;  // a solid band's edges travel in it: none beside (ids only)
  band->edges = nullptr;
  band->n = 0;
}

BandStream band_stream() {
  BandStream s;
  s.next = [](void*, StreamedBand* band, bool* end) {
    *end = stream.next == stream.n_bands;
    if (*end) return Status::kOk;
    const uint32_t b = stream.next++;
    band->y0 = stream.y0[b];
    band->y1 = stream.y1[b];
    band->edges = stream.edges;
    band->ids = stream.ids;
    if (stream.solid != nullptr) {
      stage_solid(band, band->y0, int64_t{band->y1} - 1);
      return Status::kOk;
    }
    const int64_t lo = int64_t{band->y0} - stream.margin,
                  hi = int64_t{band->y1} - 1 + stream.margin;
    band->n = 0;
    for (uint32_t i = 0; i < kEdges; ++i)
      if (edge_meets_rows(edges[i], lo, hi)) {
        stream.edges[band->n] = edges[i];
        stream.ids[band->n++] = i;
      }
    return Status::kOk;
  };
  s.release = [](void*) {};
  return s;
}

BandConductor conductor;
PreparedJob job;
alignas(8) uint8_t arena[128 * 1024];

// A job that prepared nothing to draw measured nothing: a failure.
Status drawn(Status s) { return ok(s) && job.n_points == 0 ? Status::kBadParameter : s; }

}  // namespace

int main() {
  if (!ok(build_scenes())) return 1;
  build_curves();
  JobSpec spec;
  spec.draw = DrawParams{20, HaloMode::kPaper};
  spec.cut.compact_cells = false;
  measure("job_prepare", [&] {
    return drawn(job_prepare(spec, Edges{edges, kEdges}, kCrossingCapacity, arena, sizeof arena,
                             &job, nullptr));
  });
  JobSpec wider = spec;
  wider.draw.halo = 40;
  measure("job_redraw", [&] {
    return drawn(job_redraw(wider, Edges{edges, kEdges}, kCrossingCapacity, arena, sizeof arena,
                            &job, nullptr));
  });
  JobSpec hidden = spec;
  hidden.drawing = DrawingEffect::kHiddenRemoved;
  hidden.hidden.outline = true;  // the deepest solid job: outlines and hatching too
  hidden.hidden.hatch = true;
  measure("job_prepare_solid", [&] {
    HiddenReport r;
    return drawn(
        job_prepare_solid(hidden, solid.in, 64, 32, arena, sizeof arena, &job, nullptr, &r));
  });
  JobSpec curve_spec;
  curve_spec.draw.halo = 60;
  measure("job_prepare_curves", [&] {
    const CurveJobScene scene{curves, 4, segments, 2};
    return drawn(job_prepare_curves(curve_spec, scene, 64, arena, sizeof arena, &job, nullptr));
  });
  BandSpec band;
  band.draw = DrawParams{20, HaloMode::kPaper};
  band.cut.compact_cells = false;
  measure("BandConductor::begin", [&] {
    return conductor.begin(band, array_edge_source(edges, kEdges), arena, 24 * 1024);
  });
  measure("BandConductor::next", [&] { return drain(&conductor); });
  const BandSpec solid_band = band_spec(hidden);
  measure("BandConductor::begin_solid", [&] {
    return conductor.begin_solid(solid_band, array_solid_source(&solid.in, true), arena, 24 * 1024);
  });
  measure("BandConductor::next (solid)", [&] { return drain(&conductor); });
  // Streamed: the bands of a plain run (its rows noted, the margin it measured), sent again.
  band.max_rows = 2000;  // several bands, so carries cross their borders
  conductor.set_observer(band_noter());
  if (!ok(conductor.begin(band, array_edge_source(edges, kEdges), arena, 24 * 1024)) ||
      !ok(drain(&conductor)))
    return 1;
  stream.margin = conductor.stats().margin;
  if (stream.n_bands < 2 || stream.n_bands > kMaxBands) return 1;  // one band carries nothing
  conductor.set_observer(PieceObserver{});
  measure("BandConductor::begin_streamed", [&] {
    return conductor.begin_streamed(band, stream.margin, band_stream(), arena, 24 * 1024);
  });
  measure("BandConductor::next (streamed)", [&] { return drain(&conductor); });
  BandSpec solid_rows = solid_band;
  solid_rows.turn_wide = false;  // the bands in the page's rows, as stage_solid() gathers them
  solid_rows.max_rows = 3000;    // of the solid's 16,000 rows: six bands
  stream = Stream{};
  stream.solid = &solid.in;
  conductor.set_observer(band_noter());
  if (!ok(conductor.begin_solid(solid_rows, array_solid_source(&solid.in, true), arena,
                                24 * 1024)) ||
      !ok(drain(&conductor)) || stream.n_bands < 2 || stream.n_bands > kMaxBands)
    return 1;
  conductor.set_observer(PieceObserver{});
  measure("BandConductor::begin_streamed_solid", [&] {
    return conductor.begin_streamed_solid(solid_rows, SolidStreamFlags::kClosed, band_stream(),
                                          arena, 24 * 1024);
  });
  measure("BandConductor::next (streamed solid)", [&] { return drain(&conductor); });
  return failures == 0 ? 0 : 1;
}
