#include "solid/intersection_lines.h"

#include "geometry/fraction.h"
#include "geometry/predicates.h"
#include "geometry/rows.h"
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

  // The first kBatch distinct positions after `after`, ascending, where the segment crosses a
  // face's side on paper, meets a face's corner on paper, or passes through a face. Fewer than
  // kBatch: there are no more. One look along the segment's cells finds a batch, so a segment
  // with few cuts costs one.
  static constexpr int kBatch = 16;
  int next_cuts(int64_t after, int64_t cuts[kBatch]) const {
    const Box sb = box_of(s.a, s.b, s.b);
    const int64_t ex = int64_t{s.b.x} - s.a.x, ey = int64_t{s.b.y} - s.a.y;
    const int64_t len2 = ex * ex + ey * ey;  // below 2^41: coordinates below 2^20
    int n = 0;
    auto consider = [&](int64_t t) {
      if (t <= after || t >= kOne || (n == kBatch && t >= cuts[n - 1])) return;
      int k = n;  // insert in order, once
      while (k > 0 && cuts[k - 1] > t) --k;
      if (k > 0 && cuts[k - 1] == t) return;
      if (n < kBatch) ++n;
      for (int m = n - 1; m > k; --m) cuts[m] = cuts[m - 1];
      cuts[k] = t;
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
    return n;
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

  // Cut, test, merge equal neighbours, emit: the whole segment, or its part in the rows.
  Status run(uint32_t index, IntersectionSink sink, IntersectionRows rows) {
    const RowWindow w = rows.on ? row_window(s, rows.lo, rows.hi) : RowWindow{0, kOne};
    if (w.lo >= w.hi) return Status::kOk;
    // The lower border cut a piece unless a cut lies exactly on it.
    bool clipped = w.lo > 0;
    IntersectionPiece pending{index, {own[0], own[1]}, &s, 0, 0, 0, false};
    bool have = false;
    int32_t q = 0;
    auto piece = [&](int64_t t0, int64_t t1) {
      // A piece too short for a point strictly inside keeps the q before it (solid/fallback.h);
      // a sliver the lower border cut is asked at the border, inside the piece it came from.
      if (t1 - t0 >= 2)
        q = cover_at(t0 + (t1 - t0) / 2);
      else if (t0 == w.lo && clipped)
        q = cover_at(t0);
      ++st->pieces;
      if (have && pending.q == q) {
        pending.t1 = t1;
        return Status::kOk;
      }
      const Status r = have ? sink.emit(sink.context, pending) : Status::kOk;
      pending.t0 = t0;
      pending.t1 = t1;
      pending.q = q;
      pending.hidden = q != 0;
      have = true;
      return r;
    };
    int64_t at = w.lo, after = w.lo > 0 ? w.lo - 1 : 0;  // a cut on the border too
    for (;;) {
      int64_t cuts[kBatch];
      const int n = next_cuts(after, cuts);
      bool done = n < kBatch;
      for (int k = 0; k < n; ++k) {
        if (cuts[k] >= w.hi) {
          done = true;
          break;
        }
        if (cuts[k] == w.lo) {  // the border falls on a cut: the first piece starts there
          clipped = false;
          continue;
        }
        const Status r = piece(at, cuts[k]);
        if (r != Status::kOk) return r;
        at = cuts[k];
      }
      if (done) break;
      after = cuts[n - 1];
    }
    const Status r = piece(at, w.hi);
    if (r != Status::kOk) return r;
    return sink.emit(sink.context, pending);
  }
};

}  // namespace

Status draw_intersections(const Topology& topo, const uint8_t* front, const FaceGrid& fg,
                          IntersectionSink sink, IntersectionStats* stats, IntersectionRows rows) {
  IntersectionStats st;
  uint32_t index = 0;
  const Grid& g = fg.grid;
  auto box = [&](uint32_t t) {
    const uint32_t* v = topo.triangles[t].v;
    return box_of(topo.vertices[v[0]], topo.vertices[v[1]], topo.vertices[v[2]]);
  };
  auto asked = [&](uint32_t t) { return front == nullptr || front[t] != 0; };
  uint32_t c = 0;  // the cell whose pairs are read
  // One pair of the cell's faces: the exact question if their boxes overlap in depth too and
  // this cell holds their boxes' common lower-left corner (so each pair is asked once).
  auto pair = [&](uint32_t i, const Box& bi, uint32_t j, const Box& bj) {
    if (!overlap_on_paper(bi, bj) || bi.z1 < bj.z0 || bj.z1 < bi.z0) return Status::kOk;
    if (g.cell_of(max_i32(bi.x0, bj.x0), max_i32(bi.y0, bj.y0)) != c) return Status::kOk;
    const Triangle &ti = topo.triangles[i], &tj = topo.triangles[j];
    if (shares_corner(ti, tj)) return Status::kOk;
    const Point3 p[3] = {topo.vertices[ti.v[0]], topo.vertices[ti.v[1]], topo.vertices[ti.v[2]]};
    const Point3 q[3] = {topo.vertices[tj.v[0]], topo.vertices[tj.v[1]], topo.vertices[tj.v[2]]};
    ++st.pairs;
    SegmentPass pass{topo, front, fg, &st, Edge3{}, {i, j}};
    if (!face_crossing(p, q, &pass.s)) return Status::kOk;
    ++st.segments;
    return pass.run(index++, sink, rows);
  };
  for (; c < g.cells(); ++c) {
    const uint32_t* first = fg.faces + fg.first[c];
    const uint32_t* last = fg.faces + fg.first[c + 1];
    // The cell's asked faces with their boxes, each box found once instead of once a pair;
    // past kCached of them (rare: about one face per cell) the rest find theirs as they go.
    constexpr uint32_t kCached = 24;
    uint32_t ids[kCached];
    Box boxes[kCached];
    uint32_t m = 0;
    const uint32_t* spill = last;
    for (const uint32_t* f = first; f != last && spill == last; ++f) {
      if (!asked(*f)) continue;
      if (m == kCached) {
        spill = f;
      } else {
        ids[m] = *f;
        boxes[m++] = box(*f);
      }
    }
    Status s = Status::kOk;
    for (uint32_t i = 0; i < m && ok(s); ++i)
      for (uint32_t j = i + 1; j < m && ok(s); ++j) s = pair(ids[i], boxes[i], ids[j], boxes[j]);
    for (const uint32_t* f = spill; f != last && ok(s); ++f) {
      if (!asked(*f)) continue;
      const Box bf = box(*f);
      for (uint32_t i = 0; i < m && ok(s); ++i) s = pair(ids[i], boxes[i], *f, bf);
      for (const uint32_t* h = f + 1; h != last && ok(s); ++h)
        if (asked(*h)) s = pair(*f, bf, *h, box(*h));
    }
    if (!ok(s)) {
      if (stats != nullptr) *stats = st;
      return s;
    }
  }
  if (stats != nullptr) *stats = st;
  return Status::kOk;
}

}  // namespace haloplot
