#include "solid/intersection_lines.h"

#include "geometry/fraction.h"
#include "geometry/predicates.h"
#include "solid/cover.h"
#include "solid/face_crossing.h"
#include "solid/pierce.h"

namespace haloplot {
namespace {

constexpr int64_t kOne = int64_t{1} << 32;

struct Box {
  int32_t x0, x1, y0, y1, z0, z1;
};

Box box_of(const Point3& a, const Point3& b, const Point3& c) {
  return Box{min_i32(a.x, min_i32(b.x, c.x)), max_i32(a.x, max_i32(b.x, c.x)),
             min_i32(a.y, min_i32(b.y, c.y)), max_i32(a.y, max_i32(b.y, c.y)),
             min_i32(a.z, min_i32(b.z, c.z)), max_i32(a.z, max_i32(b.z, c.z))};
}

bool overlap_on_paper(const Box& a, const Box& b) {
  return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
}

bool shares_corner(const Triangle& s, const Triangle& t) {
  for (uint32_t u : s.v)
    if (u == t.v[0] || u == t.v[1] || u == t.v[2]) return true;
  return false;
}

// One segment's pass: its cuts and the cover of each piece, its own two faces left out.
struct SegmentPass {
  const Topology& topo;
  const uint8_t* front;
  const FaceGrid& fg;
  IntersectionStats* st;
  Edge3 s;
  uint32_t own[2];

  bool asks(uint32_t k) const {
    return k != own[0] && k != own[1] && (front == nullptr || front[k] != 0);
  }

  // The first position after `after` where the segment crosses a face's side on paper, meets
  // a face's corner on paper, or passes through a face; kOne when there is none.
  int64_t next_cut(int64_t after) const {
    const Box sb = box_of(s.a, s.b, s.b);
    const int64_t ex = int64_t{s.b.x} - s.a.x, ey = int64_t{s.b.y} - s.a.y;
    const int64_t len2 = ex * ex + ey * ey;  // below 2^41: coordinates below 2^20
    int64_t best = kOne;
    auto consider = [&](int64_t t) {
      if (t > after && t < best) best = t;
    };
    for_each_cell(fg.grid, s, CellCover::kExact, 0, [&](uint32_t c) {
      for (const uint32_t* k = fg.faces + fg.first[c]; k != fg.faces + fg.first[c + 1]; ++k) {
        if (!asks(*k)) continue;
        const uint32_t* v = topo.triangles[*k].v;
        const Point3 p[3] = {topo.vertices[v[0]], topo.vertices[v[1]], topo.vertices[v[2]]};
        const Box fb = box_of(p[0], p[1], p[2]);
        if (!overlap_on_paper(sb, fb)) continue;
        for (int i = 0; i < 3; ++i) {
          const CrossingTest x = test_crossing(s, Edge3{p[i], p[(i + 1) % 3]});
          if (x.crosses) consider(frac_q32_small(x.tn, x.den));
          const int64_t px = int64_t{p[i].x} - s.a.x, py = int64_t{p[i].y} - s.a.y;
          const int64_t dot = px * ex + py * ey;
          if (ex * py - ey * px == 0 && dot > 0 && dot < len2) consider(frac_q32_small(dot, len2));
        }
        if (fb.z1 >= sb.z0 && fb.z0 <= sb.z1) consider(pierce_q32(s.a, s.b, p[0], p[1], p[2]));
      }
    });
    return best;
  }

  // Halves of cover at position m, by every face of its cell but the segment's own.
  int32_t cover_at(int64_t m) const {
    const CoverPoint p = edge_point(s, m);
    const int32_t cx = cell_x(p), cy = cell_y(p);
    int32_t q = 0;
    for (const uint32_t* k = fg.begin(cx, cy); k != fg.end(cx, cy); ++k) {
      if (!asks(*k)) continue;
      const uint32_t* v = topo.triangles[*k].v;
      const Point3 &a = topo.vertices[v[0]], &b = topo.vertices[v[1]], &c = topo.vertices[v[2]];
      ++st->face_tests;
      if (front != nullptr)
        q += cover_halves(a, b, c, p);
      else  // both sides hide: read every face counter-clockwise
        q += projected_area2(a, b, c) >= 0 ? cover_halves(a, b, c, p) : cover_halves(a, c, b, p);
    }
    ++st->tests;
    return q;
  }

  // Cut, test, merge equal neighbours, emit.
  Status run(uint32_t index, IntersectionSink sink) {
    IntersectionPiece pending{index, {own[0], own[1]}, &s, 0, 0, 0, false};
    bool have = false;
    int32_t q = 0;
    for (int64_t at = 0; at < kOne;) {
      const int64_t t = next_cut(at);
      // A piece too short for a point strictly inside keeps the q before it (solid/fallback.h).
      if (t - at >= 2) q = cover_at(at + (t - at) / 2);
      ++st->pieces;
      if (have && pending.q == q) {
        pending.t1 = t;
      } else {
        if (have) {
          const Status r = sink.emit(sink.context, pending);
          if (r != Status::kOk) return r;
        }
        pending.t0 = at;
        pending.t1 = t;
        pending.q = q;
        pending.hidden = q != 0;
        have = true;
      }
      at = t;
    }
    return have ? sink.emit(sink.context, pending) : Status::kOk;
  }
};

}  // namespace

Status draw_intersections(const Topology& topo, const uint8_t* front, const FaceGrid& fg,
                          IntersectionSink sink, IntersectionStats* stats) {
  IntersectionStats st;
  uint32_t index = 0;
  const Grid& g = fg.grid;
  for (uint32_t c = 0; c < g.cells(); ++c) {
    const uint32_t* first = fg.faces + fg.first[c];
    const uint32_t* last = fg.faces + fg.first[c + 1];
    for (const uint32_t* i = first; i != last; ++i) {
      if (front != nullptr && !front[*i]) continue;
      const Triangle& ti = topo.triangles[*i];
      const Point3 p[3] = {topo.vertices[ti.v[0]], topo.vertices[ti.v[1]], topo.vertices[ti.v[2]]};
      const Box bi = box_of(p[0], p[1], p[2]);
      for (const uint32_t* j = i + 1; j != last; ++j) {
        if (front != nullptr && !front[*j]) continue;
        const Triangle& tj = topo.triangles[*j];
        const Point3 q[3] = {topo.vertices[tj.v[0]], topo.vertices[tj.v[1]],
                             topo.vertices[tj.v[2]]};
        const Box bj = box_of(q[0], q[1], q[2]);
        if (!overlap_on_paper(bi, bj) || bi.z1 < bj.z0 || bj.z1 < bi.z0) continue;
        // Each pair once: in the cell of the boxes' common lower-left corner.
        if (g.cell_of(max_i32(bi.x0, bj.x0), max_i32(bi.y0, bj.y0)) != c) continue;
        if (shares_corner(ti, tj)) continue;
        ++st.pairs;
        SegmentPass pass{topo, front, fg, &st, Edge3{}, {*i, *j}};
        if (!face_crossing(p, q, &pass.s)) continue;
        ++st.segments;
        const Status s = pass.run(index++, sink);
        if (s != Status::kOk) {
          if (stats != nullptr) *stats = st;
          return s;
        }
      }
    }
  }
  if (stats != nullptr) *stats = st;
  return Status::kOk;
}

}  // namespace haloplot
