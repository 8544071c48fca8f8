#include "pipeline/host_pipeline.h"

#include <algorithm>
#include <chrono>

#include "pipeline/host_memory.h"

namespace haloplot::host {
namespace {

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

Status collect(void* context, const Span& s) {
  static_cast<std::vector<Span>*>(context)->push_back(s);
  return Status::kOk;
}

}  // namespace

Status host_cut(std::vector<Edge3> edges, const CutParams& params, HostCut* out) {
  out->edges = std::move(edges);
  const uint32_t n = static_cast<uint32_t>(out->edges.size());
  if (out->edges.size() > kMaxEdges) return Status::kTooManyEdges;
  const auto t0 = std::chrono::steady_clock::now();
  Status s = plan_cut(out->edges.data(), n, params, &out->plan);
  if (!ok(s)) return s;
  // A first guess at the record count; a short guess costs one more run, never a wrong answer.
  StageNeeds needs;
  needs.crossings = 4 * n + 1024;
  CutStage stage{&out->plan, out->edges.data(), &out->set, &out->stats};
  PartedMemory memory{params.parts, {}};  // cleared in CUT's parts on threads
  int rounds = 0;
  s = run_sized(stage, memory.memory(), &needs, &rounds);
  out->storage = std::move(memory.words);  // the CUTSET lives at its start
  out->cut_ms = ms_since(t0);
  out->retries = rounds - 1;
  out->scratch_bytes = out->plan.scratch_bytes;
  return s;
}

Status host_draw(const CutSet& set, const DrawParams& params, HostDraw* out) {
  out->spans.clear();
  out->scratch_bytes = draw_scratch_bytes(set);
  std::vector<Gap> scratch(out->scratch_bytes / sizeof(Gap) + 1);
  const auto t0 = std::chrono::steady_clock::now();
  const Status s = draw(set, params, scratch.data(), scratch.size() * sizeof(Gap),
                        SpanSink{&collect, &out->spans}, &out->stats);
  out->draw_ms = ms_since(t0);
  return s;
}

Status host_banded_draw(const std::vector<Edge3>& edges, const CutParams& cut,
                        const DrawParams& draw, size_t arena_bytes, HostDraw* out, BandStats* bands,
                        int32_t substep_bits) {
  out->spans.clear();
  BandSpec spec;
  spec.substep_bits = substep_bits;
  spec.draw = draw;
  spec.cut = cut;
  std::vector<uint64_t> arena(arena_bytes / 8);
  BandConductor conductor;
  conductor.set_observer(PieceObserver{
      [](void* ctx, const BandPiece& p) {
        static_cast<std::vector<Span>*>(ctx)->push_back(
            Span{{p.edge, p.t0, p.t1}, p.segment.x0, p.segment.y0, p.segment.x1, p.segment.y1});
      },
      &out->spans});
  const auto t0 = std::chrono::steady_clock::now();
  Status s = conductor.begin(spec, array_edge_source(edges.data(), uint32_t(edges.size())),
                             arena.data(), arena.size() * 8);
  if (ok(s)) s = run_all_bands(conductor);
  out->draw_ms = ms_since(t0);
  *bands = conductor.stats();
  out->scratch_bytes = bands->peak_bytes;
  out->stats.spans = out->spans.size();
  std::sort(out->spans.begin(), out->spans.end(), [](const Span& a, const Span& b) {
    return a.edge != b.edge ? a.edge < b.edge : a.t0 < b.t0;
  });
  return s;
}

}  // namespace haloplot::host
