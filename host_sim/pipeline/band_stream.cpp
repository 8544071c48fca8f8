#include "pipeline/band_stream.h"

#include "band/band_rule.h"

namespace haloplot::host {

Status plan_streamed_bands(const std::vector<Edge3>& edges, const BandSpec& spec,
                           size_t arena_bytes, BandPlan* out) {
  *out = BandPlan{};
  std::vector<uint64_t> arena(arena_bytes / 8);
  BandConductor conductor;
  PieceObserver observer;
  observer.ctx = out;
  observer.band = [](void* ctx, int32_t y0, int32_t y1) {
    PlannedBand b;
    b.y0 = y0;
    b.y1 = y1;
    static_cast<BandPlan*>(ctx)->bands.push_back(std::move(b));
  };
  conductor.set_observer(observer);
  Status s = conductor.begin(spec, array_edge_source(edges.data(), uint32_t(edges.size())),
                             arena.data(), arena.size() * 8);
  if (ok(s)) s = run_all_bands(conductor);
  out->stats = conductor.stats();  // with the bytes a band asked for, when one did not fit
  if (!ok(s)) return s;
  out->margin = out->stats.margin;
  // What each band gathers: the conductor's own rule (band_rule.h), in scene order.
  for (PlannedBand& b : out->bands) {
    const int64_t lo = int64_t{b.y0} - out->margin, hi = int64_t{b.y1} - 1 + out->margin;
    for (uint32_t i = 0; i < edges.size(); ++i)
      if (edge_meets_rows(edges[i], lo, hi)) {
        b.edges.push_back(edges[i]);
        b.ids.push_back(i);
      }
  }
  return Status::kOk;
}

BandStream PlanStream::stream() {
  BandStream s;
  s.ctx = this;
  s.next = [](void* ctx, StreamedBand* band, bool* end) {
    auto* self = static_cast<PlanStream*>(ctx);
    *end = self->next == self->plan->bands.size();
    if (*end) return Status::kOk;
    if (self->busy_left > 0) {
      --self->busy_left;
      ++self->busy_answers;
      return Status::kBusy;
    }
    const PlannedBand& b = self->plan->bands[self->next++];
    self->busy_left = self->busy_every;
    band->y0 = b.y0;
    band->y1 = b.y1;
    band->edges = b.edges.data();
    band->ids = b.ids.data();
    band->n = uint32_t(b.edges.size());
    return Status::kOk;
  };
  return s;
}

}  // namespace haloplot::host
