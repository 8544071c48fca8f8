// A bare-metal image that runs CUT from the installed package on a fixed buffer: no heap, no
// startup code beyond an entry point. It is linked, not run: the test checks its symbols.
#include "cut/cut.h"
#include "memory/sized_stage.h"
#include "scene/cube_array.h"

using namespace haloplot;

namespace {
alignas(8) Edge3 edges[48];
alignas(8) uint8_t arena[16384];
}  // namespace

int main() {
  CubeArrayParams p;
  p.cubes = 2;
  if (!ok(cube_array(p, edges, 48))) return 1;
  CutPlan plan;
  if (!ok(plan_cut(edges, 48, CutParams{}, &plan))) return 1;
  CutSet set;
  CutStats stats;
  CutStage stage{&plan, edges, &set, &stats};
  StageNeeds needs;
  needs.crossings = 64;
  FixedMemory memory{arena, sizeof arena};
  return ok(run_sized(stage, memory.memory(), &needs)) ? int(set.n_crossings) : -1;
}

extern "C" [[noreturn]] void _start() {
  main();
  for (;;) {
  }
}
