// The core on RV32IMAC (tests/firmware/qemu_riscv_test.sh): the haloed spans of a cube array,
// CUT then DRAW in static buffers, printed over semihosting as `haloplot plot --spans` writes
// them ("s EDGE X0 Y0 X1 Y1"), then "fw crossings=" and "fw spans=". The test plots the same
// scene (`haloplot demo-scene --cubes 4`, halo 50) on the host and compares every span.
#include <haloplot/cut/cut.h>
#include <haloplot/draw/draw.h>
#include <haloplot/memory/sized_stage.h>
#include <haloplot/scene/cube_array.h>

#include "platform/console.h"
#include "platform/semihosting.h"

using namespace haloplot;

namespace {

constexpr int32_t kCubes = 4;
constexpr int32_t kHalo = 50;
alignas(8) Edge3 edges[12 * kCubes * kCubes];
alignas(8) uint8_t arena[64 * 1024];
alignas(8) uint8_t scratch[32 * 1024];
fw::Console out;

int fail(const char* what, Status s) {
  char line[96];
  char* p = fw::append(line, "FAILED: ");
  p = fw::append(p, what);
  p = fw::append(p, ": ");
  p = fw::append(p, status_name(s));
  p = fw::append(p, "\n");
  out.flush();
  fw::semihost_write(line, uint32_t(p - line));
  return 1;
}

Status print_span(void* count, const Span& sp) {
  char line[80];
  char* p = fw::append(line, "s ");
  p = fw::append_u64(p, sp.edge);
  const int32_t ends[4] = {sp.x0, sp.y0, sp.x1, sp.y1};
  for (int32_t v : ends) {
    p = fw::append(p, " ");
    p = fw::append_i64(p, v);
  }
  p = fw::append(p, "\n");
  fw::Console::write(&out, line, uint32_t(p - line));
  ++*static_cast<uint32_t*>(count);
  return Status::kOk;
}

}  // namespace

int main() {
  CubeArrayParams scene;
  scene.cubes = kCubes;
  const uint32_t n = cube_array_edges(scene);
  Status s = cube_array(scene, edges, n);
  if (!ok(s)) return fail("cube_array", s);
  CutPlan plan;
  s = plan_cut(edges, n, CutParams{}, &plan);
  if (!ok(s)) return fail("plan_cut", s);
  CutSet crossings;
  CutStats cut_stats;
  CutStage cut{&plan, edges, &crossings, &cut_stats};
  StageNeeds needs;
  needs.crossings = 64;
  FixedMemory memory{arena, sizeof arena};
  s = run_sized(cut, memory.memory(), &needs);
  if (!ok(s)) return fail("CUT", s);
  if (draw_scratch_bytes(crossings) > sizeof scratch)
    return fail("DRAW scratch", Status::kBadParameter);
  DrawParams halo;
  halo.halo = kHalo;
  DrawStats draw_stats;
  uint32_t spans = 0;
  s = draw(crossings, halo, scratch, sizeof scratch, SpanSink{print_span, &spans}, &draw_stats);
  if (!ok(s)) return fail("DRAW", s);
  out.stat("crossings", crossings.n_crossings);
  out.stat("spans", spans);
  out.flush();
  return 0;
}
