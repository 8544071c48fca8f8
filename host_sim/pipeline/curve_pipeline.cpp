#include "pipeline/curve_pipeline.h"

#include <algorithm>
#include <chrono>

namespace haloplot::host {
namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

Status collect_chord(void* context, const Span& s) {
  static_cast<std::vector<Span>*>(context)->push_back(s);
  return Status::kOk;
}

Status collect_interval(void* context, const CurveInterval& i) {
  static_cast<std::vector<CurveInterval>*>(context)->push_back(i);
  return Status::kOk;
}

}  // namespace

Status host_curve_draw(const std::vector<BezierEdge3>& curves, const std::vector<Edge3>& segments,
                       const CurveCrossParams& cross, const CurveDrawParams& params,
                       HostCurveDraw* out, bool exact) {
  *out = HostCurveDraw();
  CurveCrossParams cp = cross;
  cp.segment_pairs = true;
  auto t0 = std::chrono::steady_clock::now();
  CurveCrossPlan plan;
  Status s = plan_curve_cross(curves.data(), uint32_t(curves.size()), segments.data(),
                              uint32_t(segments.size()), cp, &plan);
  if (!ok(s)) return s;
  std::vector<uint64_t> scratch(plan.scratch_bytes / 8 + 1);
  out->cross_scratch_bytes = plan.scratch_bytes;
  out->hits.resize(64);
  uint32_t n = 0;
  for (int attempt = 0; attempt < 3; ++attempt) {
    s = run_curve_cross(plan, curves.data(), segments.data(), scratch.data(), scratch.size() * 8,
                        out->hits.data(), uint32_t(out->hits.size()), &n, &out->cross_stats);
    if (s != Status::kCrossingCapacity) break;
    out->hits.resize(out->cross_stats.needed);
  }
  out->hits.resize(n);
  out->cross_ms = ms_since(t0);
  if (!ok(s)) return s;
  t0 = std::chrono::steady_clock::now();
  CurveDrawPlan dplan;
  s = (exact ? plan_curve_draw_exact : plan_curve_draw)(curves.data(), uint32_t(curves.size()),
                                                        segments.data(), uint32_t(segments.size()),
                                                        out->hits.data(), n, params, &dplan);
  if (!ok(s)) return s;
  std::vector<uint64_t> dscratch(dplan.scratch_bytes / 8 + 1);
  out->draw_scratch_bytes = dplan.scratch_bytes;
  const CurveIntervalSink intervals{&collect_interval, &out->intervals};
  s = (exact ? run_curve_draw_exact : run_curve_draw)(
      dplan, curves.data(), segments.data(), out->hits.data(), n, dscratch.data(),
      dscratch.size() * 8, SpanSink{&collect_chord, &out->chords}, &intervals, &out->stats);
  out->draw_ms = ms_since(t0);
  return s;
}

Status host_banded_curve_draw(const std::vector<BezierEdge3>& curves,
                              const std::vector<Edge3>& segments, const CurveBandSpec& spec,
                              size_t arena_bytes, HostCurveDraw* out, BandStats* bands) {
  *out = HostCurveDraw();
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<uint64_t> arena(arena_bytes / 8);
  CurveBands plot;
  Status s = plot.begin(spec, curves.data(), uint32_t(curves.size()), segments.data(),
                        uint32_t(segments.size()), arena.data(), arena.size() * 8);
  auto keep = [](void* ctx, const BandPiece& p) {
    static_cast<std::vector<Span>*>(ctx)->push_back(
        Span{{p.edge, p.t0, p.t1}, p.segment.x0, p.segment.y0, p.segment.x1, p.segment.y1});
  };
  plot.set_observer(PieceObserver{keep, &out->chords, nullptr});
  while (ok(s) && !plot.done()) {
    const PathPoint* points = nullptr;
    uint32_t n = 0;
    s = plot.next(&points, &n);
  }
  *bands = plot.stats();
  out->draw_ms = ms_since(t0);
  std::sort(out->chords.begin(), out->chords.end(), [](const Span& a, const Span& b) {
    return a.edge != b.edge ? a.edge < b.edge : a.t0 < b.t0;
  });
  out->stats.chords = out->chords.size();
  return s;
}

}  // namespace haloplot::host
