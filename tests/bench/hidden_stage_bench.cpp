// The hidden-line stage of `haloplot plot MODEL --mode hidden-removed --view AZ,EL`, run RUNS
// times in one process on the same scene, for tools/bench_lineart.sh: the first run is the
// stage as a fresh `plot` runs it (its code executed for the first time, its caches and page
// tables cold), the later ones warm, as a warm Blender re-evaluates its Line Art modifier. The
// model is read, welded and projected as `plot` does it (cli/scene_input.h), and the stage is
// the same call `plot` makes (run_solid_options); each run prints "wall_ms cpu_ms", the
// stage's own clocks (SolidRun::ms_total and cpu_ms_total, `plot --stats`' hidden_ms and
// hidden_cpu_ms). Usage: hidden_stage_bench MODEL AZ,EL THREADS RUNS
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cli/scene_input.h"
#include "cli/solid_options.h"
#include "pipeline/host_memory.h"
#include "pipeline/thread_parts.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

using namespace haloplot;
using namespace haloplot::host;

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: hidden_stage_bench MODEL AZ,EL THREADS RUNS\n");
    return 2;
  }
#if defined(__GLIBC__)
  // The heap as the tool's main() keeps it (cli/main.cpp): freed memory kept for reuse.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  mallopt(M_TOP_PAD, 16 << 20);
#endif
  const std::string path = argv[1];
  Options o;
  o.positional = {path};
  o.values = {{"--mode", "hidden-removed"}, {"--view", argv[2]}};
  o = with_model_defaults(o, path);
  std::string error;
  SolidOptions so;
  SolidScene scene;
  TriangulateStats tri;
  if (!parse_solid_options(o, &so, &error) || !load_solid_scene(o, path, &scene, &tri, &error)) {
    std::fprintf(stderr, "hidden_stage_bench: %s\n", error.c_str());
    return 1;
  }
  so.parts = thread_parts(uint32_t(std::atoi(argv[3])));
  give_back_freed_memory();  // as cmd_plot_solid does before the stage
  for (int i = std::atoi(argv[4]); i > 0; --i) {
    SolidRun run;
    if (run_solid_options(scene, so, &run) != Status::kOk) return 1;
    std::printf("%.3f %.3f\n", run.ms_total, run.cpu_ms_total);
  }
  return 0;
}
