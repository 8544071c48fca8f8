// The stack each public entry that plots takes, measured on the chip (tests/firmware/
// stack_probe.sh, for the M0+, M4, M33 and RV32): the stack below the caller is painted, the
// entry runs on the scenes of firmware/selftest/misaligned_checks.h (3 x 3 cubes as edges, two
// solid cubes with faces) and a curve scene of its own, and the deepest word it overwrote gives its
// bytes, counted from the caller's stack pointer (its callees, the sinks and the call itself
// included). Prints "fw stack ENTRY=BYTES" per entry, then exits 0 if every entry ran well.
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
    return drawn(
        job_prepare(spec, edges, kEdges, kCrossingCapacity, arena, sizeof arena, &job, nullptr));
  });
  JobSpec wider = spec;
  wider.draw.halo = 40;
  measure("job_redraw", [&] {
    return drawn(job_redraw(wider, kEdges, kCrossingCapacity, arena, sizeof arena, &job, nullptr));
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
  return failures == 0 ? 0 : 1;
}
