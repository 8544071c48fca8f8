#include "pipeline/band_stream.h"

#include <algorithm>

#include "haloplot/band/band_rule.h"

namespace haloplot::host {

namespace {

PieceObserver band_noter(BandPlan* out) {
  PieceObserver observer;
  observer.ctx = out;
  observer.band = [](void* ctx, int32_t y0, int32_t y1) {
    PlannedBand b;
    b.y0 = y0;
    b.y1 = y1;
    static_cast<BandPlan*>(ctx)->bands.push_back(std::move(b));
  };
  return observer;
}

}  // namespace

Status plan_streamed_bands(const std::vector<Edge3>& edges, const BandSpec& spec,
                           size_t arena_bytes, BandPlan* out) {
  *out = BandPlan{};
  std::vector<uint64_t> arena(arena_bytes / 8);
  BandConductor conductor;
  conductor.set_observer(band_noter(out));
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

Status plan_streamed_solid(const SolidInput& in, bool closed, const BandSpec& spec,
                           size_t arena_bytes, BandPlan* out) {
  *out = BandPlan{};
  out->solid = true;
  out->closed = closed;
  std::vector<uint64_t> arena(arena_bytes / 8);
  BandConductor conductor;
  conductor.set_observer(band_noter(out));
  Status s =
      conductor.begin_solid(spec, array_solid_source(&in, closed), arena.data(), arena.size() * 8);
  if (ok(s)) s = run_all_bands(conductor);
  out->stats = conductor.stats();
  if (!ok(s)) return s;
  // A turned plan's rows are the turned frame's (geometry/quarter_turn.h): each band gathers
  // by the turned vertices, and sends the page's.
  out->turned = out->stats.turned;
  std::vector<Point3> frame(in.vertices, in.vertices + in.n_vertices);
  if (out->turned)
    for (Point3& p : frame) p = turn_point(p);
  // What each band gathers: the conductor's own rule (solid_band.cpp), in scene order.
  for (PlannedBand& b : out->bands) {
    const int64_t lo = b.y0, hi = int64_t{b.y1} - 1;
    for (uint32_t i = 0; i < in.n_edges; ++i) {
      const uint32_t v0 = in.edge_pairs[2 * i], v1 = in.edge_pairs[2 * i + 1];
      if (!edge_meets_rows(Edge3{frame[v0], frame[v1]}, lo, hi)) continue;
      b.ids.push_back(i);
      b.pairs.insert(b.pairs.end(), {v0, v1});
      b.vertex_ids.insert(b.vertex_ids.end(), {v0, v1});
    }
    auto read = [&](uint32_t t, Triangle* tri, bool* meets) {
      *tri = in.triangles[t];
      const uint32_t* v = tri->v;
      *meets = triangle_meets_rows(frame[v[0]], frame[v[1]], frame[v[2]], lo, hi + 1);
      return Status::kOk;
    };
    s = for_band_triangles(in.n_triangles, spec.hatch, read, [&](uint32_t, Triangle t) {
      b.triangles.push_back(t);
      b.vertex_ids.insert(b.vertex_ids.end(), {t.v[0], t.v[1], t.v[2]});
    });
    if (!ok(s)) return s;
    std::sort(b.vertex_ids.begin(), b.vertex_ids.end());
    b.vertex_ids.erase(std::unique(b.vertex_ids.begin(), b.vertex_ids.end()), b.vertex_ids.end());
    for (uint32_t v : b.vertex_ids) b.vertices.push_back(in.vertices[v]);
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
    if (self->plan->solid) {
      self->staged = StagedSolidBand{
          b.vertex_ids.data(),    b.vertices.data(),  uint32_t(b.vertices.size()), b.pairs.data(),
          uint32_t(b.ids.size()), b.triangles.data(), uint32_t(b.triangles.size())};
      band->solid = &self->staged;
    }
    return Status::kOk;
  };
  return s;
}

}  // namespace haloplot::host
