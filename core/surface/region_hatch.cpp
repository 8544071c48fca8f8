#include "haloplot/surface/region_hatch.h"

#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/wide.h"
#include "memory/carve.h"
#include "solid/cover.h"
#include "sort/in_place_sort.h"

namespace haloplot {
namespace {

// w = n . p with n in Q2.30 and coordinates below 2^20: below 2^51. A level test at an end
// t = num / den multiplies a w difference by den (2^41) and adds num times another: < 2^94.
static_assert(kCoordBits + kTrigFractionBits + 1 + (kCrossBits - 1) + 1 < 126,
              "level tests must fit in Wide");

struct Hatching {
  int64_t nx, ny;   // the lines' normal (Q2.30); the lines run along (ny, -nx)
  int64_t spacing;  // in w units (steps << 30)
};

Hatching hatching_for(const SolidInput& in, uint32_t t, const HatchParams& p) {
  const SinCos d = hatch_direction(in, t, p);
  return Hatching{-d.sin, d.cos, int64_t{p.spacing} << kTrigFractionBits};
}

// The polygon a half-edge's cycle names, or kRegionBackground when it is not hatched.
uint32_t hatched_polygon(const SolidInput& in, const Regions& r, uint32_t h, const HatchParams& p) {
  if (!r.kept[h / 2]) return kRegionBackground;
  const uint32_t f = r.cycle_face[r.cycle[h]];
  if (f == kRegionBackground || f == kRegionUnnamed) return kRegionBackground;
  const uint32_t* v = in.triangles[f].v;
  const int64_t area = projected_area2(in.vertices[v[0]], in.vertices[v[1]], in.vertices[v[2]]);
  if (p.front_only ? area <= 0 : area == 0) return kRegionBackground;
  return in.triangles[f].polygon;
}

struct HalfEdgeRun {
  Edge3 e;               // the half-edge's edge, oriented as the half-edge runs
  PiecePosition p0, p1;  // its ends along e (exact)
  int64_t w0, w1;        // w at e's ends
};

HalfEdgeRun span_of(const SolidInput& in, const Regions& r, uint32_t h, const Hatching& hg) {
  const RegionSegment& s = r.segments[h / 2];
  HalfEdgeRun sp;
  sp.e = Edge3{in.vertices[in.edge_pairs[2 * s.edge]], in.vertices[in.edge_pairs[2 * s.edge + 1]]};
  sp.p0 = piece_end_position(in, s.edge, s.from);
  sp.p1 = piece_end_position(in, s.edge, s.to);
  sp.w0 = hg.nx * sp.e.a.x + hg.ny * sp.e.a.y;
  sp.w1 = hg.nx * sp.e.b.x + hg.ny * sp.e.b.y;
  return sp;
}

// Sign of w - level at position num / den along the edge.
int level_side(const HalfEdgeRun& s, const PiecePosition& at, int64_t level) {
  const Wide v = mul_i64(s.w0 - level, at.den) + mul_i64(at.num, s.w1 - s.w0);
  return v.negative() ? -1 : (v.is_zero() ? 0 : 1);
}

// The levels k whose line the span may meet (a superset, from its Q0.32 ends), then exactly.
template <typename Visit>
void span_levels(const HalfEdgeRun& s, const RegionSegment& g, const Hatching& hg, Visit visit) {
  auto w_at = [&](int64_t t) {
    const Wide d = mul_i64(s.w1 - s.w0, t);  // below 2^84: keep the integer part of / 2^32
    return s.w0 + static_cast<int64_t>((d.lo >> 32) | (d.hi << 32));
  };
  const int64_t wa = w_at(g.t0), wb = w_at(g.t1);
  const int64_t lo = wa < wb ? wa : wb, hi = wa < wb ? wb : wa;
  for (int64_t k = floor_div(lo, hg.spacing) - 1; k <= floor_div(hi, hg.spacing) + 1; ++k) {
    const int64_t level = k * hg.spacing;
    const bool below0 = level_side(s, s.p0, level) < 0, below1 = level_side(s, s.p1, level) < 0;
    if (below0 != below1) visit(k, level);
  }
}

struct Hit {
  int64_t k, u;    // level, and position along the line (Q22 * Q8)
  int32_t x8, y8;  // the point, in 1/256 steps
  int32_t delta;   // +1 entering the region, -1 leaving
};

}  // namespace

size_t region_hatch_bytes(const SolidInput& in, const Regions& r, const HatchParams& params) {
  // One Hit per (half-edge, level), for the largest polygon: counted exactly.
  ByteCounter c;
  c.take<uint32_t>(2 * size_t{r.n_segments});
  uint64_t total = 0;
  for (uint32_t h = 0; h < 2 * r.n_segments; ++h) {
    if (hatched_polygon(in, r, h, params) == kRegionBackground) continue;
    const Hatching hg = hatching_for(in, r.cycle_face[r.cycle[h]], params);
    span_levels(span_of(in, r, h, hg), r.segments[h / 2], hg, [&](int64_t, int64_t) { ++total; });
  }
  c.take<Hit>(size_t(total));
  return c.total + 16;
}

Status hatch_regions(const SolidInput& in, const Regions& r, const HatchParams& params,
                     void* buffer, size_t bytes, HatchSink sink, RegionHatchStats* stats) {
  if (params.spacing < 1 || params.spacing > kCoordMax) return Status::kBadParameter;
  RegionHatchStats st;
  Carver carve(buffer, bytes);
  uint32_t* hs = carve.take<uint32_t>(2 * size_t{r.n_segments});
  if (carve.short_) return Status::kWorkspaceTooSmall;
  uint32_t n = 0;
  for (uint32_t h = 0; h < 2 * r.n_segments; ++h)
    if (hatched_polygon(in, r, h, params) != kRegionBackground) hs[n++] = h;
  heap_sort(hs, n, [&](uint32_t a, uint32_t b) {
    const uint32_t pa = hatched_polygon(in, r, a, params), pb = hatched_polygon(in, r, b, params);
    return pa < pb || (pa == pb && a < b);
  });
  Hit* hits = reinterpret_cast<Hit*>(carve.next);
  const size_t room = carve.left / sizeof(Hit);
  Status s = Status::kOk;
  for (uint32_t i = 0; i < n && s == Status::kOk;) {
    const uint32_t poly = hatched_polygon(in, r, hs[i], params);
    uint32_t j = i;
    while (j < n && hatched_polygon(in, r, hs[j], params) == poly) ++j;
    const uint32_t face = r.cycle_face[r.cycle[hs[i]]];
    const Hatching hg = hatching_for(in, face, params);
    const int64_t ux = hg.ny >> 8, uy = -hg.nx >> 8;  // along the line, Q22
    size_t nh = 0;
    for (uint32_t q = i; q < j; ++q) {
      const uint32_t h = hs[q];
      HalfEdgeRun sp = span_of(in, r, h, hg);
      const int64_t dx = sp.e.b.x - sp.e.a.x, dy = sp.e.b.y - sp.e.a.y;
      // Entering when the line's direction points to the half-edge's left.
      const int64_t hx = (h & 1) ? -dx : dx, hy = (h & 1) ? -dy : dy;
      const int32_t delta = hx * uy - hy * ux > 0 ? 1 : -1;
      span_levels(sp, r.segments[h / 2], hg, [&](int64_t k, int64_t level) {
        if (nh >= room) {
          ++nh;
          return;
        }
        // The edge meets the level at t = (level - w0) / (w1 - w0).
        const int64_t num = level - sp.w0, den = sp.w1 - sp.w0;
        Hit& x = hits[nh++];
        x.k = k;
        x.x8 = static_cast<int32_t>(int64_t{sp.e.a.x} * 256 + scale_round(dx * 256, num, den));
        x.y8 = static_cast<int32_t>(int64_t{sp.e.a.y} * 256 + scale_round(dy * 256, num, den));
        x.u = ux * x.x8 + uy * x.y8;
        x.delta = delta;
      });
    }
    if (nh > room) {
      s = Status::kWorkspaceTooSmall;
      break;
    }
    st.crossings += nh;
    ++st.faces;
    heap_sort(hits, nh, [](const Hit& a, const Hit& b) {
      if (a.k != b.k) return a.k < b.k;
      if (a.u != b.u) return a.u < b.u;
      return a.delta > b.delta;  // enter first: regions meeting at a point join there
    });
    int32_t inside = 0;
    const Hit* start = nullptr;
    for (size_t q = 0; q < nh && s == Status::kOk; ++q) {
      if (q > 0 && hits[q].k != hits[q - 1].k) inside = 0;
      const int32_t was = inside;
      inside += hits[q].delta;
      if (was <= 0 && inside > 0) start = &hits[q];
      if (was > 0 && inside <= 0 && start != nullptr) {
        HatchStroke stroke{face, poly, Edge3{}};
        stroke.line.a = Point3{(start->x8 + 128) >> 8, (start->y8 + 128) >> 8, 0};
        stroke.line.b = Point3{(hits[q].x8 + 128) >> 8, (hits[q].y8 + 128) >> 8, 0};
        if (stroke.line.a.x == stroke.line.b.x && stroke.line.a.y == stroke.line.b.y) continue;
        ++st.strokes;
        s = sink.emit(sink.context, stroke);
      }
    }
    i = j;
  }
  if (stats) *stats = st;
  return s;
}

}  // namespace haloplot
