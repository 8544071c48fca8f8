#include "haloplot/draw/draw.h"

#include "haloplot/geometry/fraction.h"
#include "sort/in_place_sort.h"

namespace haloplot {

size_t draw_scratch_bytes(const CutSet& cutset) {
  uint32_t most = 0;
  for (uint32_t e = 0; e < cutset.n_edges; ++e)
    if (cutset.count(e) > most) most = cutset.count(e);
  return size_t{most} * sizeof(Gap);
}

void span_point(const Edge3& e, int64_t t32, int32_t* x, int32_t* y) {
  *x = lerp_round(e.a.x, e.b.x - e.a.x, t32);
  *y = lerp_round(e.a.y, e.b.y - e.a.y, t32);
}

namespace {

Status emit(const SpanSink& sink, const Edge3& edge, uint32_t e, int64_t t0, int64_t t1,
            DrawStats& st) {
  Span s{{e, t0, t1}, 0, 0, 0, 0};
  span_point(edge, t0, &s.x0, &s.y0);
  span_point(edge, t1, &s.x1, &s.y1);
  ++st.spans;
  return sink.emit(sink.context, s);
}

}  // namespace

template <typename Precision>
Gap record_gap(const CutSet& cs, const Crossing& c, const DrawParams& params) {
  using Sqrt = typename Precision::Sqrt;
  using Position = typename Precision::Position;
  const Edge3& edge = cs.edges[c.behind];
  const Edge3& front = cs.edges[c.front_edge()];
  Gap g;
  if (params.mode == HaloMode::kExact)
    g = exact_gap<Sqrt>(edge, front, params.halo);
  else if (c.near_miss())
    return Gap{1, 0};  // the paper's DRAW knows only crossings
  else
    g = paper_gap<Sqrt>(edge, front, c.t, params.halo);
  g.lo = Position::floor(g.lo);
  g.hi = Position::ceil(g.hi);
  if (g.lo < 0) g.lo = 0;  // clip to the edge (a halo running off its end)
  if (g.hi > kFracOne) g.hi = kFracOne;
  return g;
}

template <typename Precision>
Status draw_with(const CutSet& cs, const DrawParams& params, void* scratch, size_t scratch_bytes,
                 SpanSink sink, DrawStats* stats) {
  DrawStats st;
  if (params.halo < 0 || params.halo > kCoordMax) return Status::kBadParameter;
  if (buffer_misaligned(scratch)) return Status::kMisalignedBuffer;
  if (scratch_bytes < draw_scratch_bytes(cs)) return Status::kWorkspaceTooSmall;
  st.reach_short = params.mode == HaloMode::kExact && params.halo > cs.reach;
  Gap* gaps = static_cast<Gap*>(scratch);

  for (uint32_t e = 0; e < cs.n_edges; ++e) {
    const Edge3& edge = cs.edges[e];
    // D2.1-D2.2: one gap per place this edge passes behind another.
    uint32_t k = 0;
    if (params.halo > 0) {
      const Crossing* c = cs.begin(e);
      for (uint32_t i = 0; i < cs.count(e); ++i) {
        const Gap g = record_gap<Precision>(cs, c[i], params);
        if (!g.empty()) gaps[k++] = g;
      }
    }
    st.gaps += k;
    // D2.4-D2.5: sort gap starts along the edge, then sweep: the edge is visible wherever no
    // gap covers it, which is the paper's "+ count exceeds - count" rule without the counts.
    sort_in_place(gaps, k, [](const Gap& a, const Gap& b) { return a.lo < b.lo; });
    int64_t cursor = 0;
    bool drew = false;
    for (uint32_t i = 0; i < k; ++i) {
      if (gaps[i].lo > cursor) {
        const Status s = emit(sink, edge, e, cursor, gaps[i].lo, st);
        if (!ok(s)) return s;
        drew = true;
      }
      if (gaps[i].hi > cursor) cursor = gaps[i].hi;
    }
    if (cursor < kFracOne) {
      const Status s = emit(sink, edge, e, cursor, kFracOne, st);
      if (!ok(s)) return s;
      drew = true;
    }
    if (!drew) ++st.hidden_edges;
  }
  if (stats) *stats = st;
  return Status::kOk;
}

Status draw(const CutSet& cs, const DrawParams& params, void* scratch, size_t scratch_bytes,
            SpanSink sink, DrawStats* stats) {
  return draw_with<DefaultDrawPrecision>(cs, params, scratch, scratch_bytes, sink, stats);
}

#define HALOPLOT_DRAW_WITH(S, B)                                                             \
  template Status draw_with<DrawPrecision<S, PositionBits<B>>>(                              \
      const CutSet&, const DrawParams&, void*, size_t, SpanSink, DrawStats*);                \
  template Gap record_gap<DrawPrecision<S, PositionBits<B>>>(const CutSet&, const Crossing&, \
                                                             const DrawParams&);
HALOPLOT_DRAW_WITH(SqrtExact, 32)
HALOPLOT_DRAW_WITH(SqrtNewton, 32)
HALOPLOT_DRAW_WITH(SqrtTable, 32)
HALOPLOT_DRAW_WITH(SqrtExact, 16)
HALOPLOT_DRAW_WITH(SqrtNewton, 16)
HALOPLOT_DRAW_WITH(SqrtTable, 16)
#undef HALOPLOT_DRAW_WITH

}  // namespace haloplot
