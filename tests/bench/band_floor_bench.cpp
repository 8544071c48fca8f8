// Band floor benchmark: what a solid job's bands need at the least. For a hidden-line job (a
// .job file naming an .obj model; its own `arena` key is ignored) the band conductor plots the
// whole model in bands one row high (BandSpec::max_rows, no motion) in a large arena: the peak
// is then the most bytes any band one row high took (its stages at their highest, its strokes,
// what it carried), the least arena the job can plot in. Then, for each ARENA given, whether
// the job plots in it as `haloplot sim` plans it (the bands, their peak, or what the band that
// did not fit asked for).
// Usage: band_floor_bench JOB [ARENA...]
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "cli/job_file.h"
#include "cli/scene_input.h"
#include "haloplot/band/conductor.h"
#include "haloplot/job/job.h"
#include "pipeline/solid_pipeline.h"

using namespace haloplot;
using namespace haloplot::host;

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: band_floor_bench JOB [ARENA...]\n");
    return 2;
  }
  JobFile jf;
  const InputError ie = read_job_file(argv[1], &jf);
  if (ie.failed()) {
    std::fprintf(stderr, "%s\n", ie.message().c_str());
    return 2;
  }
  SolidScene solid;
  std::string error;
  // The job's hidden-line keys (dash, outline, hatch) and the scene's sub-steps go into its
  // spec, as `haloplot sim` puts them (host_sim/cli/main.cpp).
  if (!load_solid_job_scene(jf, &solid, &jf.spec.hidden, &error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 2;
  }
  jf.spec.substep_bits = solid.substep_bits;
  const SolidInput in = solid_input(solid);
  const bool closed = model_closed(solid);
  auto plan = [&](size_t arena, int32_t max_rows, BandStats* stats) {
    BandSpec spec = band_spec(jf.spec);
    spec.max_rows = max_rows;
    std::vector<uint64_t> buffer(arena / 8);
    BandConductor conductor;
    Status s = conductor.begin_solid(spec, array_solid_source(&in, closed), buffer.data(),
                                     buffer.size() * 8);
    if (ok(s)) s = run_all_bands(conductor);
    *stats = conductor.stats();
    return s;
  };
  BandStats st;
  Status s = plan(size_t{1} << 20, 1, &st);
  if (!ok(s)) {
    std::fprintf(stderr, "%s: bands one row high in 1 MB: %s\n", argv[1], status_name(s));
    return 1;
  }
  std::printf("%s: %u bands one row high, peak %zu bytes\n", argv[1], st.bands, st.peak_bytes);
  for (int i = 2; i < argc; ++i) {
    const size_t arena = std::strtoull(argv[i], nullptr, 10);
    s = plan(arena, 0, &st);
    if (ok(s))
      std::printf("  in %zu bytes: %u bands, peak %zu\n", arena, st.bands, st.peak_bytes);
    else
      std::printf("  in %zu bytes: %s (asked for %zu)\n", arena, status_name(s), st.need_bytes);
  }
  return 0;
}
