// libFuzzer: the .cut reader on any bytes; whatever it accepts must be safe to DRAW.
#include <cstdlib>
#include <sstream>

#include "io/cut_file.h"
#include "pipeline/host_pipeline.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  haloplot::host::LoadedCut lc;
  if (haloplot::host::read_cut(in, "fuzz", &lc).failed()) return 0;
  for (haloplot::HaloMode mode : {haloplot::HaloMode::kPaper, haloplot::HaloMode::kExact}) {
    haloplot::host::HostDraw d;
    if (!ok(haloplot::host::host_draw(lc.set, haloplot::DrawParams{37, mode}, &d))) std::abort();
    for (const auto& s : d.spans)
      if (s.t0 < 0 || s.t1 > (int64_t{1} << 32) || s.t0 > s.t1 || s.edge >= lc.set.n_edges)
        std::abort();
  }
  return 0;
}
