// Curves in bands (haloplot/band/curve_bands.h): every chord a banded plot draws is a chord of the
// unbanded curve DRAW (the job's settings, curve_job_params), the same edge, the same Q0.32
// ends and the same rounded segment, each drawn once, whatever the arena and band height; the
// knots' crossings at and through joints and gaps carried across joints included.
//
// `narrow-margin` (must fail): the bands take no margin beyond their own edges' rows (the
// margin pass skipped), so a gap carried over a joint from a crossing whose front edge lies
// outside those rows is lost: the check must see chords that differ.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>
#include <tuple>
#include <vector>

#include "check.h"
#include "demo/curve_scenes.h"
#include "haloplot/band/curve_bands.h"
#include "haloplot/job/job.h"
#include "pipeline/curve_pipeline.h"

using namespace haloplot;
using namespace haloplot::host;

namespace {

bool g_narrow = false;

auto key(const Span& s) { return std::make_tuple(s.edge, s.t0, s.t1, s.x0, s.y0, s.x1, s.y1); }

struct Banded {
  Status status = Status::kOk;
  std::vector<Span> chords;
  BandStats stats;
  uint64_t points = 0;
};

Banded run_bands(const CurveScene& sc, const CurveBandSpec& spec, size_t arena_bytes) {
  Banded out;
  std::vector<uint64_t> arena(arena_bytes / 8);
  CurveBands bands;
  out.status = bands.begin(spec, sc.curves.data(), uint32_t(sc.curves.size()), sc.segments.data(),
                           uint32_t(sc.segments.size()), arena.data(), arena.size() * 8);
  bands.set_observer(PieceObserver{
      [](void* ctx, const BandPiece& p) {
        static_cast<std::vector<Span>*>(ctx)->push_back(
            Span{{p.edge, p.t0, p.t1}, p.segment.x0, p.segment.y0, p.segment.x1, p.segment.y1});
      },
      &out.chords, nullptr});
  while (ok(out.status) && !bands.done()) {
    const PathPoint* pts = nullptr;
    uint32_t n = 0;
    out.status = bands.next(&pts, &n);
    out.points += n;
  }
  out.stats = bands.stats();
  std::sort(out.chords.begin(), out.chords.end(),
            [](const Span& a, const Span& b) { return key(a) < key(b); });
  return out;
}

// One scene at one halo: the unbanded chords, then bands in several arenas and heights.
void check_scene(const char* name, const CurveScene& sc, int32_t halo) {
  JobSpec job;
  job.draw.halo = halo;
  CurveCrossParams cp;
  CurveDrawParams dp;
  curve_job_params(job, &cp, &dp);
  HostCurveDraw whole;
  CHECK(ok(host_curve_draw(sc.curves, sc.segments, cp, dp, &whole)));
  std::vector<Span> want = whole.chords;
  std::sort(want.begin(), want.end(), [](const Span& a, const Span& b) { return key(a) < key(b); });
  CurveBandSpec spec;
  CHECK(ok(curve_band_spec(job, &spec)));
  const Banded one = run_bands(sc, spec, size_t{1} << 24);
  CHECK(ok(one.status));
  CHECK_EQ(one.stats.bands, 1u);
  const size_t peak = one.stats.peak_bytes;
  struct Try {
    size_t arena;
    int32_t rows;
  };
  const Try tries[] = {
      {peak, 0}, {peak * 3 / 4, 0}, {peak / 2, 0}, {size_t{1} << 24, 97}, {size_t{1} << 24, 1000}};
  for (const Try& t : tries) {
    CurveBandSpec s = spec;
    s.max_rows = t.rows;
    if (g_narrow) s.fixed_margin = 0;
    const Banded b = run_bands(sc, s, t.arena);
    if (b.status == Status::kArenaTooSmall) {  // too small for this scene: said, with the need
      CHECK(b.stats.need_bytes > t.arena);
      std::printf("%s halo %d arena %zu: too small (a band needs %zu)\n", name, halo, t.arena,
                  b.stats.need_bytes);
      continue;
    }
    CHECK(ok(b.status));
    size_t same = 0;
    for (size_t i = 0; i < want.size() && i < b.chords.size(); ++i)
      same += key(want[i]) == key(b.chords[i]);
    const bool equal = b.chords.size() == want.size() && same == want.size();
    CHECK(equal);
    if (t.arena < peak || t.rows > 0) CHECK(b.stats.bands > 1);
    CHECK(b.stats.peak_bytes <= t.arena);
    std::printf(
        "%s halo %d arena %zu rows %d: %u bands, margin %d, peak %zu of one band's %zu, "
        "%zu chords, %zu equal the unbanded DRAW's\n",
        name, halo, t.arena, t.rows, b.stats.bands, b.stats.margin, b.stats.peak_bytes, peak,
        b.chords.size(), same);
  }
}

}  // namespace

int main(int argc, char** argv) {
  g_narrow = argc > 1 && std::strcmp(argv[1], "narrow-margin") == 0;
  CurveView view;
  view.size = 15200;  // the demo's scenes (demo-scene --curve)
  view.margin = 400;
  for (int32_t halo : {80, 600}) {
    check_scene("trefoil 24", trefoil_knot(24, view), halo);
    check_scene("trefoil 100", trefoil_knot(100, view), halo);
    check_scene("torus 2-5, 42", torus_knot(2, 5, 42, view), halo);
    check_scene("torus 2-5, 40 (crossings at joints)", torus_knot(2, 5, 40, view), halo);
    CurveView tilted = view;
    tilted.tilt = 1.0;
    check_scene("helix with its axis", helix(4, 1.0, 24, true, tilted), halo);
  }
  // An arena too small for any band says so, with what a band asked for; a misaligned one is
  // refused before it is touched.
  CurveView v = view;
  const CurveScene sc = trefoil_knot(24, v);
  JobSpec job;
  job.draw.halo = 80;
  CurveBandSpec spec;
  CHECK(ok(curve_band_spec(job, &spec)));
  const Banded tiny = run_bands(sc, spec, 4096);
  CHECK(tiny.status == Status::kArenaTooSmall);
  CHECK(tiny.stats.need_bytes > 4096);
  std::vector<uint64_t> arena(8192);
  CurveBands bands;
  CHECK(bands.begin(spec, sc.curves.data(), uint32_t(sc.curves.size()), nullptr, 0,
                    reinterpret_cast<uint8_t*>(arena.data()) + 4,
                    60000) == Status::kMisalignedBuffer);
  job.draw.mode = HaloMode::kExact;  // the bands draw the paper's gap, as the controller
  CHECK(curve_band_spec(job, &spec) == Status::kBadParameter);
  return check::finish(g_narrow ? "curve_bands narrow-margin" : "curve_bands");
}
