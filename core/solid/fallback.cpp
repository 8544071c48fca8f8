#include "solid/fallback.h"

#include "geometry/rows.h"
#include "geometry/wide.h"
#include "memory/carve.h"
#include "solid/classify.h"
#include "solid/cover.h"
#include "solid/face_grid.h"
#include "solid/qi.h"

namespace haloplot {
namespace {

constexpr int64_t kOne = int64_t{1} << 32;

enum Vc : uint8_t { kVcUnknown = 0, kVcVisible = 1, kVcHidden = 2, kVcUnusable = 3 };

}  // namespace

size_t fallback_bytes(const Topology& topo) {
  ByteCounter c;
  c.take<uint8_t>(face_grid_bytes(topo));
  c.take<uint8_t>(topo.n_vertices);
  return c.total + 8;
}

Status run_fallback(const Topology& topo, const uint8_t* front, const CutSet& cutset,
                    const Incidences& inc, const FallbackParams& params, void* buffer, size_t bytes,
                    FallbackSink sink, FallbackStats* stats) {
  if (cutset.n_edges != topo.n_edges) return Status::kBadParameter;
  if ((params.use_classes || params.use_vc || !params.any_facing) && front == nullptr)
    return Status::kBadParameter;
  Carver carve(buffer, bytes);
  const size_t grid_bytes = face_grid_bytes(topo);
  uint8_t* grid_buffer = carve.take<uint8_t>(grid_bytes);
  uint8_t* vc = carve.take<uint8_t>(topo.n_vertices);
  if (carve.short_) return Status::kWorkspaceTooSmall;
  FaceGrid fg;
  const Status gs = build_face_grid(topo, grid_buffer, grid_bytes, &fg);
  if (gs != Status::kOk) return gs;
  FallbackStats st;
  st.grid_cells = fg.grid.cells();
  st.cell_faces = fg.pairs;

  // The V.C. table starts unknown except where it must never be used.
  for (uint32_t v = 0; v < topo.n_vertices; ++v) {
    const bool singular = inc.same_next[v] != v || inc.vertex_first[v] != inc.vertex_first[v + 1];
    vc[v] = (params.use_vc && !singular) ? kVcUnknown : kVcUnusable;
  }
  if (params.use_vc) {
    // Contour vectors run with the front face on their right (Kira): count starts and ends.
    // Peculiar vertices, and vertices on a hidden fold (H2), keep no V.C.
    for (uint32_t v = 0; v < topo.n_vertices; ++v) {
      uint32_t starts = 0, ends = 0;
      bool h2 = false;
      for (uint32_t k = topo.vertex_edge_first[v]; k < topo.vertex_edge_first[v + 1]; ++k) {
        const SolidEdge& e = topo.edges[topo.vertex_edges[k]];
        if (e.cls == EdgeClass::kH2) h2 = true;
        if (e.cls != EdgeClass::kH3) continue;
        // Front face on the left of v0 -> v1 means the vector runs v1 -> v0.
        const bool from_v1 = front_face_side(topo, front, topo.vertex_edges[k]) > 0;
        const uint32_t start = from_v1 ? e.v1 : e.v0;
        ++(start == v ? starts : ends);
      }
      if (ends >= 2) ++st.peculiar_a;
      if (starts >= 2) ++st.peculiar_b;
      if (ends >= 2 || starts >= 2 || h2) vc[v] = kVcUnusable;
    }
  }

  const bool use_front = !params.any_facing;
  for (uint32_t e = 0; e < topo.n_drawn; ++e) {
    const SolidEdge& se = topo.edges[e];
    const Point3 a = topo.vertices[se.v0], b = topo.vertices[se.v1];
    const int64_t dx = b.x - a.x, dy = b.y - a.y;
    if (dx == 0 && dy == 0) continue;  // a point on paper: nothing to draw
    // The part of the edge this run draws: all of it, or the band's rows.
    int64_t lo = 0, hi = kOne;
    if (params.window) {
      const RowWindow w = row_window(Edge3{a, b}, params.row_lo, params.row_hi);
      lo = w.lo;
      hi = w.hi;
      if (lo >= hi) continue;
    }
    const bool by_class =
        params.use_classes && (se.cls == EdgeClass::kH1 || se.cls == EdgeClass::kH2);
    const bool vc_edge = params.use_vc && (se.cls == EdgeClass::kH3 || se.cls == EdgeClass::kH4);
    FallbackPiece pending{e, 0, 0, 0, false, true};
    bool have = false;
    Status status = Status::kOk;
    int32_t last_q = 0;
    bool last_hidden = false;
    auto emit = [&](int64_t t0, int64_t t1) {
      if (t0 < lo) t0 = lo;
      if (t1 > hi) t1 = hi;
      if (t1 <= t0 || status != Status::kOk) return;
      ++st.pieces;
      int32_t q = kQiUnknown;
      bool hidden = false, tested = true;
      if (by_class) {
        ++st.class_saved;
        hidden = true;
      } else if (t1 - t0 < 2) {
        ++st.short_pieces;
        q = last_q;
        hidden = last_hidden;
        tested = false;
      } else {
        const uint32_t end_v = t0 == 0 ? se.v0 : (t1 == kOne ? se.v1 : kNoFace);
        if (vc_edge && end_v != kNoFace && (vc[end_v] == kVcVisible || vc[end_v] == kVcHidden)) {
          ++st.vc_saved;
          hidden = vc[end_v] == kVcHidden;
        } else {
          const int64_t m = t0 + (t1 - t0) / 2;
          const CoverPoint p = edge_point(Edge3{a, b}, m);
          const int32_t cx = cell_x(p), cy = cell_y(p);
          q = 0;
          for (const uint32_t* k = fg.begin(cx, cy); k != fg.end(cx, cy); ++k) {
            const uint32_t t = *k;
            const uint32_t* v = topo.triangles[t].v;
            const Point3 &fa = topo.vertices[v[0]], &fb = topo.vertices[v[1]],
                         &fc = topo.vertices[v[2]];
            ++st.face_tests;
            if (use_front) {
              if (front[t]) q += cover_halves(fa, fb, fc, p);
            } else {
              q += projected_area2(fa, fb, fc) >= 0 ? cover_halves(fa, fb, fc, p)
                                                    : cover_halves(fa, fc, fb, p);
            }
          }
          ++st.tests;
          hidden = q != 0;
          if (vc_edge && end_v != kNoFace && vc[end_v] == kVcUnknown)
            vc[end_v] = hidden ? kVcHidden : kVcVisible;
        }
      }
      last_q = q;
      last_hidden = hidden;
      if (have && !params.window && pending.q == q && pending.hidden == hidden &&
          pending.t1 == t0) {
        pending.t1 = t1;
        return;
      }
      if (have) status = sink.emit(sink.context, pending);
      pending = FallbackPiece{e, t0, t1, q, hidden, tested};
      have = true;
    };
    // Cut points: every crossing behind another edge, every vertex the edge passes through.
    const Crossing* cx = cutset.begin(e);
    const uint32_t ncx = cutset.count(e);
    const Incidence* ix = inc.by_edge + inc.edge_first[e];
    const uint32_t nix = inc.edge_first[e + 1] - inc.edge_first[e];
    int64_t at = 0;
    uint32_t i = 0, j = 0;
    while (i < ncx || j < nix) {
      int64_t t;
      if (j >= nix || (i < ncx && cx[i].t <= ix[j].t))
        t = cx[i++].t;
      else
        t = ix[j++].t;
      // A cut at floor(t * 2^32): the true point lies in [t, t + 1). The middle of [at, t) is
      // at least at + 1 and at most t - 1, so strictly between the true cut points.
      emit(at, t);
      at = t;
    }
    emit(at, kOne);
    if (have && status == Status::kOk) status = sink.emit(sink.context, pending);
    if (status != Status::kOk) return status;
  }
  if (stats != nullptr) *stats = st;
  return Status::kOk;
}

}  // namespace haloplot
