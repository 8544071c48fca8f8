// The banded plot is the unbanded plot. The band conductor (core/band) runs CUT and DRAW band
// by band in a small arena; the reference is the plain core CUT and DRAW over the whole scene
// in host memory. Every visible piece must come out once, with the same edge and the same
// Q0.32 ends, whatever the arena: no gap, no overlap, no piece lost or split at a border.
// The check is shown to see a lost gap: a margin forced below the measured one must fail it.
// A scene in sub-step units (BandSpec::substep_bits) bands the same, and its path draws each
// piece's segment rounded to whole steps (geometry/units.h), the rounding written out here.
#include <algorithm>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include "check.h"
#include "demo/cube_array.h"
#include "demo/random_scene.h"
#include "haloplot/band/conductor.h"
#include "pipeline/host_pipeline.h"
#include "support/scenes.h"

using namespace haloplot;

namespace {

using Piece = std::tuple<uint32_t, int64_t, int64_t>;  // edge, t0, t1

// The banded path's pen-down moves, each as an unordered segment, sorted.
using Ink = std::tuple<int32_t, int32_t, int32_t, int32_t>;
Ink unordered(int32_t x0, int32_t y0, int32_t x1, int32_t y1) {
  return std::make_tuple(x0, y0, x1, y1) < std::make_tuple(x1, y1, x0, y0) ? Ink{x0, y0, x1, y1}
                                                                           : Ink{x1, y1, x0, y0};
}

std::vector<Piece> unbanded(const std::vector<Edge3>& edges, const DrawParams& draw,
                            int32_t reach) {
  CutParams cp;
  cp.reach = reach;
  host::HostCut cut;
  if (!ok(host::host_cut(edges, cp, &cut))) return {};
  host::HostDraw d;
  if (!ok(host::host_draw(cut.set, draw, &d))) return {};
  std::vector<Piece> out;
  for (const Span& s : d.spans) out.emplace_back(s.edge, s.t0, s.t1);
  std::sort(out.begin(), out.end());
  return out;
}

struct Banded {
  Status status = Status::kOk;
  std::vector<Piece> pieces;
  std::vector<PathPoint> points;
  BandStats stats;
  bool segments_match = true;  // each piece's segment is its ends rounded, as DRAW rounds them
  std::vector<Ink> ink;        // the pieces' segments, unordered, sorted
};

Banded banded(const std::vector<Edge3>& edges, const BandSpec& spec, size_t arena_bytes) {
  Banded out;
  std::vector<uint64_t> arena(arena_bytes / 8);
  BandConductor bc;
  struct Ctx {
    Banded* out;
    const std::vector<Edge3>* edges;
  } ctx{&out, &edges};
  bc.set_observer(PieceObserver{[](void* c, const BandPiece& p) {
                                  auto* x = static_cast<Ctx*>(c);
                                  x->out->pieces.emplace_back(p.edge, p.t0, p.t1);
                                  Segment2 want;
                                  span_point((*x->edges)[p.edge], p.t0, &want.x0, &want.y0);
                                  span_point((*x->edges)[p.edge], p.t1, &want.x1, &want.y1);
                                  x->out->ink.push_back(unordered(p.segment.x0, p.segment.y0,
                                                                  p.segment.x1, p.segment.y1));
                                  if (want.x0 != p.segment.x0 || want.y0 != p.segment.y0 ||
                                      want.x1 != p.segment.x1 || want.y1 != p.segment.y1)
                                    x->out->segments_match = false;
                                },
                                &ctx});
  out.status = bc.begin(spec, array_edge_source(edges.data(), uint32_t(edges.size())), arena.data(),
                        arena.size() * 8);
  while (ok(out.status)) {
    const PathPoint* pts = nullptr;
    uint32_t n = 0;
    out.status = bc.next(&pts, &n);
    if (n == 0) break;
    out.points.insert(out.points.end(), pts, pts + n);
  }
  out.stats = bc.stats();
  std::sort(out.pieces.begin(), out.pieces.end());
  std::sort(out.ink.begin(), out.ink.end());
  return out;
}

// Pieces in the reference that the banded run lacks or adds, for the failure message.
std::string difference(const std::vector<Piece>& want, const std::vector<Piece>& got) {
  std::vector<Piece> lost, extra;
  std::set_difference(want.begin(), want.end(), got.begin(), got.end(), std::back_inserter(lost));
  std::set_difference(got.begin(), got.end(), want.begin(), want.end(), std::back_inserter(extra));
  char buf[160];
  std::snprintf(buf, sizeof buf, "%zu pieces lost, %zu extra (of %zu)", lost.size(), extra.size(),
                want.size());
  return buf;
}

// A coordinate in units of 2^-s steps to the nearest step, ties upward, by division (not the
// core's shift).
int32_t to_steps(int32_t u, int s) {
  const int64_t k = int64_t{1} << s;
  return int32_t((2 * int64_t{u} + k) / (2 * k));
}

std::vector<Ink> in_steps(const std::vector<Ink>& ink, int s) {
  std::vector<Ink> out;
  for (const Ink& i : ink)
    out.push_back(unordered(to_steps(std::get<0>(i), s), to_steps(std::get<1>(i), s),
                            to_steps(std::get<2>(i), s), to_steps(std::get<3>(i), s)));
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Ink> drawn(const std::vector<PathPoint>& pts) {
  std::vector<Ink> out;
  for (size_t i = 1; i < pts.size(); ++i)
    if (pts[i].pen_down) out.push_back(unordered(pts[i - 1].x, pts[i - 1].y, pts[i].x, pts[i].y));
  std::sort(out.begin(), out.end());
  return out;
}

void expect_same(const char* name, const std::vector<Edge3>& edges, const BandSpec& spec,
                 size_t arena, uint32_t min_bands) {
  const auto want = unbanded(edges, spec.draw, spec.cut.reach);
  const Banded got = banded(edges, spec, arena);
  CHECK_MSG(ok(got.status), std::string(name) + ": " + status_name(got.status) + ", needs " +
                                std::to_string(got.stats.need_bytes) + " bytes");
  CHECK_MSG(!want.empty(), std::string(name) + ": reference drew nothing");
  CHECK_MSG(got.pieces == want, std::string(name) + ": " + difference(want, got.pieces));
  CHECK_MSG(got.segments_match, std::string(name) + ": a segment is not its rounded ends");
  CHECK_MSG(got.stats.bands >= min_bands,
            std::string(name) + ": only " + std::to_string(got.stats.bands) + " bands");
  CHECK_MSG(got.stats.peak_bytes <= arena, std::string(name) + ": peak beyond the arena");
  // The path draws every piece's segment exactly once (zero-length ones too), whichever band
  // drew it: pieces deferred to join a polyline above are not lost or drawn twice.
  CHECK_MSG(drawn(got.points) == in_steps(got.ink, spec.substep_bits),
            std::string(name) + ": the path draws " + std::to_string(drawn(got.points).size()) +
                " segments, not the " + std::to_string(got.ink.size()) + " pieces' segments");
  std::printf(
      "%-28s edges=%zu pieces=%zu bands=%u margin_bands=%u splits=%u margin=%d "
      "most_edges=%u most_carry=%u peak=%zu arena=%zu\n",
      name, edges.size(), got.pieces.size(), got.stats.bands, got.stats.margin_bands,
      got.stats.splits, got.stats.margin, got.stats.most_edges, got.stats.most_carry,
      got.stats.peak_bytes, arena);
}

BandSpec haloed(int32_t halo, HaloMode mode = HaloMode::kPaper, int32_t reach = 0) {
  BandSpec s;
  // The path is checked against every piece, dots and overlaps too: the planner's clean-up
  // (tested on its own in path_export) would drop some.
  s.clean.on = false;
  s.draw = DrawParams{halo, mode};
  s.cut.compact_cells = false;
  s.cut.reach = reach;
  return s;
}

// Long edges crossing at shallow angles: paper gaps (W / sin theta) hundreds of rows long,
// reaching bands far from the crossing.
std::vector<Edge3> shallow_crossings() {
  std::vector<Edge3> e;
  scenes::Rng rng(7);
  for (int i = 0; i < 300; ++i) {
    const int32_t x = int32_t(rng.uniform(2000, 60000)), y = int32_t(rng.uniform(0, 60000));
    const int32_t len = int32_t(rng.uniform(2000, 30000));
    const int32_t slope = int32_t(rng.uniform(-40, 40));  // dx per 1000 dy
    e.push_back(scenes::edge(x, y, int32_t(rng.uniform(0, 1000000)), x + slope * len / 1000,
                             y + len, int32_t(rng.uniform(0, 1000000))));
  }
  return e;
}

// Level edges, edges that end exactly on rows a band may start at, and long steep ones that
// cross many bands without a gap.
std::vector<Edge3> lattice_and_levels() {
  std::vector<Edge3> e;
  for (int32_t i = 0; i < 40; ++i) {
    e.push_back(scenes::edge(0, i * 256, 100 + i, 20000, i * 256, 100 + i));         // level
    e.push_back(scenes::edge(i * 512, 0, 5000 + i, i * 512 + 37, 10240, 5000 - i));  // steep
    e.push_back(scenes::edge(i * 500, 10240, 9000, 20000 - i * 500, 0, 8000));       // down
  }
  e.push_back(scenes::edge(100, 100, 7, 100, 100, 7));  // a dot
  return e;
}

}  // namespace

int main() {
  // The README's demo, Figure 4: 28 x 28 cubes, 9408 edges, halo 50, in 64 KB.
  const auto fig4 = host::cube_array(CubeArrayParams{});
  expect_same("figure4_64k", fig4, haloed(50), 64 * 1024, 10);
  expect_same("figure4_32k", fig4, haloed(50), 32 * 1024, 30);
  expect_same("figure4_exact_halo", fig4, haloed(50, HaloMode::kExact, 50), 64 * 1024, 10);
  // 20,000 random edges, about one crossing per edge.
  const auto random20k = host::paper_random(20000, 10000, 20261201);
  expect_same("random_20k", random20k, haloed(2000), 64 * 1024, 10);
  // Gaps that reach far, near-parallel edges, the exact halo with near misses.
  const auto shallow = shallow_crossings();
  expect_same("shallow_paper", shallow, haloed(100), 16 * 1024, 3);
  expect_same("shallow_exact_near", shallow, haloed(100, HaloMode::kExact, 100), 16 * 1024, 2);
  const auto levels = lattice_and_levels();
  expect_same("levels_and_rows", levels, haloed(64), 24 * 1024, 4);
  // Every edge whole (no CUT), still in bands.
  BandSpec whole;
  whole.clean.on = false;
  whole.haloed = false;
  expect_same("figure4_all_edges", fig4, whole, 16 * 1024, 10);
  expect_same("figure4_halo_0", fig4, haloed(0), 16 * 1024, 10);
  // Figure 4 fitted 8 times finer (3 sub-step bits): the halo in units, the path in steps.
  {
    std::vector<Edge3> fine = fig4;
    for (Edge3& e : fine) e.a.x *= 8, e.a.y *= 8, e.b.x *= 8, e.b.y *= 8;
    BandSpec units = haloed(50 * 8);
    units.substep_bits = 3;
    expect_same("figure4_substep_3", fine, units, 64 * 1024, 10);
    // The conductor's path is in steps: none of its points lies beyond the scene in steps.
    const Banded b = banded(fine, units, 64 * 1024);
    int32_t most = 0;
    for (const PathPoint& p : b.points) most = std::max(most, std::max(p.x, p.y));
    int32_t scene_most = 0;
    for (const Edge3& e : fig4) scene_most = std::max({scene_most, e.a.x, e.a.y, e.b.x, e.b.y});
    CHECK_MSG(most <= scene_most, "a band's path point lies beyond the scene in steps");
  }
  // One band when the scene fits: no margin pass.
  {
    const Banded one = banded(levels, haloed(64), 1 << 20);
    CHECK_EQ(one.stats.bands, 1u);
    CHECK_EQ(one.stats.margin_bands, 0u);
    CHECK(one.pieces == unbanded(levels, DrawParams{64, HaloMode::kPaper}, 0));
  }
  // The check sees a lost gap: with the margin forced to 0, gaps cut from beyond a band's rows
  // are missing, so the pieces differ or the conductor finds a carried piece with no
  // continuation (the band above knew a gap the band below did not) and says so.
  {
    BandSpec blind = haloed(100);
    blind.fixed_margin = 0;
    const Banded b = banded(shallow, blind, 16 * 1024);
    const bool differs = b.pieces != unbanded(shallow, blind.draw, 0);
    std::printf("zero margin: %s, pieces %s\n", status_name(b.status),
                differs ? "differ" : "equal");
    CHECK_MSG(b.status == Status::kBandCarryLost || (ok(b.status) && differs),
              "a zero margin should lose gaps on the shallow scene");
    // A margin a little short on Figure 4 loses pieces too.
    BandSpec short_margin = haloed(50);
    short_margin.fixed_margin = 20;
    const Banded f = banded(fig4, short_margin, 32 * 1024);
    const bool f_differs = f.pieces != unbanded(fig4, short_margin.draw, 0);
    std::printf("figure 4, margin 20 of 36: %s, pieces %s\n", status_name(f.status),
                f_differs ? "differ" : "equal");
    CHECK_MSG(f.status == Status::kBandCarryLost || (ok(f.status) && f_differs),
              "a short margin should lose gaps on Figure 4");
  }
  // An arena too small for a band one row high: named, with the bytes it needed.
  {
    const Banded b = banded(fig4, haloed(50), 1024);
    CHECK(b.status == Status::kArenaTooSmall);
    CHECK(b.stats.need_bytes > 1024);
    std::printf("arena 1024: %s, needs %zu bytes\n", status_name(b.status), b.stats.need_bytes);
  }
  return check::finish("bands");
}
