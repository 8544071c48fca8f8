// libFuzzer: the banded plot is the unbanded plot. The bytes become a small scene on a coarse
// lattice (endpoints on the rows a band may start at, level edges, shared and collinear points,
// end-on edges), a halo width and mode, and an arena small enough for several bands; every
// visible piece of the banded run (edge, Q0.32 ends) must equal the unbanded CUT and DRAW's,
// and the pen path must draw each piece's segment once. A too small arena may only say so.
#include <algorithm>
#include <cstdlib>
#include <tuple>
#include <vector>

#include "haloplot/band/conductor.h"
#include "pipeline/host_pipeline.h"

using namespace haloplot;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 3) return 0;
  const int32_t step = 1 << (data[0] & 7);  // lattice of 1 to 128 steps
  std::vector<Edge3> edges;
  for (size_t i = 3; i + 6 <= size && edges.size() < 64; i += 6) {
    auto v = [&](size_t k) { return int32_t(data[i + k] & 63) * step; };
    edges.push_back(Edge3{{v(0), v(1), int32_t(data[i + 2]) * 4111},
                          {v(3), v(4), int32_t(data[i + 5]) * 4111}});
  }
  const HaloMode mode = (data[0] & 8) ? HaloMode::kExact : HaloMode::kPaper;
  const DrawParams draw{int32_t(data[1] & 63) * step / 4, mode};
  const int32_t reach = mode == HaloMode::kExact ? draw.halo : 0;
  // The unbanded reference.
  CutParams cp;
  cp.reach = reach;
  host::HostCut cut;
  if (!ok(host::host_cut(edges, cp, &cut))) std::abort();
  host::HostDraw whole;
  if (!ok(host::host_draw(cut.set, draw, &whole))) std::abort();
  std::vector<std::tuple<uint32_t, int64_t, int64_t>> want, got;
  for (const Span& s : whole.spans) want.emplace_back(s.edge, s.t0, s.t1);
  std::sort(want.begin(), want.end());
  // Banded, in 1 to 16 KB.
  BandSpec spec;
  spec.draw = draw;
  spec.cut.reach = reach;
  spec.haloed = (data[0] & 16) == 0 || draw.halo > 0;
  // Every span drawn as given: the pen-downs below count the spans (the clean-up would drop a
  // span that rounds to a point or overlaps another; path_export tests it).
  spec.clean.on = false;
  std::vector<uint64_t> arena((1024 + size_t(data[2]) * 64) / 8);
  BandConductor bc;
  bc.set_observer(PieceObserver{[](void* ctx, const BandPiece& p) {
                                  static_cast<decltype(got)*>(ctx)->emplace_back(p.edge, p.t0,
                                                                                 p.t1);
                                },
                                &got});
  Status s = bc.begin(spec, array_edge_source(edges.data(), uint32_t(edges.size())), arena.data(),
                      arena.size() * 8);
  size_t pen_down = 0;
  while (ok(s) && !bc.done()) {
    const PathPoint* p = nullptr;
    uint32_t n = 0;
    s = bc.next(&p, &n);
    for (uint32_t k = 0; k < n; ++k) pen_down += p[k].pen_down;
  }
  if (s == Status::kArenaTooSmall) return 0;
  if (!ok(s)) std::abort();
  std::sort(got.begin(), got.end());
  if (spec.haloed && got != want) std::abort();
  if (!spec.haloed && got.size() != edges.size()) std::abort();
  if (pen_down != got.size()) std::abort();
  return 0;
}
