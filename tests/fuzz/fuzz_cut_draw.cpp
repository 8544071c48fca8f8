// libFuzzer: the bytes become a small scene with many degenerate coincidences (coordinates
// drawn from a few values, range extremes, repeated points), and CUT must agree exactly with
// the brute-force reference; DRAW must then produce sane spans in both modes.
#include <cstdlib>
#include <vector>

#include "pipeline/host_pipeline.h"
#include "reference/brute_cut.h"
#include "support/run_core.h"

using namespace haloplot;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  // The first byte picks the coordinate palette: small grids make collinear and shared
  // points common; the extremes exercise the bit budget.
  const int32_t palettes[4][4] = {{0, 1, 2, 3},
                                  {0, 10, 20, 30},
                                  {0, kCoordMax / 2, kCoordMax - 1, kCoordMax},
                                  {5, 100, 4000, 1000000}};
  const int32_t* pal = palettes[data[0] & 3];
  std::vector<Edge3> edges;
  for (size_t i = 1; i + 6 <= size && edges.size() < 48; i += 6) {
    auto v = [&](size_t k) {
      const uint8_t b = data[i + k];
      return (b & 0x80) ? pal[b & 3] + (b >> 2 & 7) : int32_t(b) * 4099 % (kCoordMax + 1);
    };
    edges.push_back(Edge3{{v(0), v(1), v(2)}, {v(3), v(4), v(5)}});
  }
  for (auto& e : edges)
    for (int32_t* c : {&e.a.x, &e.a.y, &e.a.z, &e.b.x, &e.b.y, &e.b.z})
      if (*c > kCoordMax) *c = kCoordMax;
  const reference::Result ref = reference::brute_cut(edges);
  CutParams p;
  p.grid.lambda_q8 = 64 + (data[0] >> 2) * 16;  // the grid varies too
  host::HostCut c;
  if (!ok(host::host_cut(edges, p, &c))) std::abort();
  if (!support::cutset_well_formed(c.set) || support::records_of(c.set) != ref.records)
    std::abort();
  for (HaloMode mode : {HaloMode::kPaper, HaloMode::kExact}) {
    host::HostDraw d;
    if (!ok(host::host_draw(c.set, DrawParams{int32_t(data[0]) * 97, mode}, &d))) std::abort();
    for (const auto& s : d.spans)
      if (s.t0 < 0 || s.t1 > (int64_t{1} << 32) || s.t0 > s.t1) std::abort();
  }
  return 0;
}
