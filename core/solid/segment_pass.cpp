#include "haloplot/solid/segment_pass.h"

#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/predicates.h"
#include "haloplot/geometry/rows.h"
#include "haloplot/geometry/wide.h"
#include "solid/cover.h"
#include "solid/pierce.h"

namespace haloplot {
namespace {

constexpr int64_t kOne = int64_t{1} << 32;

}  // namespace

bool coplanar_faces(const Topology& topo, uint32_t t, uint32_t u) {
  const uint32_t* v = topo.triangles[t].v;
  const Point3 a = topo.vertices[v[0]], b = topo.vertices[v[1]], c = topo.vertices[v[2]];
  const int64_t ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const int64_t vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const int64_t nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  for (int k = 0; k < 3; ++k) {
    const Point3 q = topo.vertices[topo.triangles[u].v[k]];
    if (!(mul_i64(nx, q.x - a.x) + mul_i64(ny, q.y - a.y) + mul_i64(nz, q.z - a.z)).is_zero())
      return false;
  }
  return true;
}

namespace {

// The corner of triangle t that is not u or v.
Point3 third_corner(const Topology& topo, uint32_t t, uint32_t u, uint32_t v) {
  const uint32_t* c = topo.triangles[t].v;
  return topo.vertices[c[0] != u && c[0] != v ? c[0] : c[1] != u && c[1] != v ? c[1] : c[2]];
}

// The side of the line through a and b that p lies on, on paper: -1, 0 or 1.
int side_of(const Point3& a, const Point3& b, const Point3& p) {
  return sign(
      cross(int64_t{b.x} - a.x, int64_t{b.y} - a.y, int64_t{p.x} - a.x, int64_t{p.y} - a.y));
}

}  // namespace

bool SegmentPass::neighbour(uint32_t k) const {
  const uint32_t* v = topo.triangles[k].v;
  for (uint32_t t = own_first; t < own_end; ++t) {
    const uint32_t* u = topo.triangles[t].v;
    uint32_t side[3];
    int shared = 0;
    for (int i = 0; i < 3; ++i)
      if (v[i] == u[0] || v[i] == u[1] || v[i] == u[2]) side[shared++] = v[i];
    if (shared < 2) continue;
    if (front != nullptr) return true;
    // Both sides hide (open meshes): a neighbour folded over the side on paper (one of the
    // two seen from the back) can cover the segment's faces, so it is passed only where it
    // lies strictly across the side and none of those faces reaches over the side's line.
    const Point3 a = topo.vertices[side[0]], b = topo.vertices[side[1]];
    const int across = side_of(a, b, third_corner(topo, k, side[0], side[1]));
    if (across != 0 && side_of(a, b, third_corner(topo, t, side[0], side[1])) == -across &&
        own_faces_short_of(a, b, across))
      return true;
  }
  return false;
}

bool SegmentPass::own_faces_short_of(const Point3& a, const Point3& b, int across) const {
  for (uint32_t t = own_first; t < own_end; ++t)
    for (int i = 0; i < 3; ++i)
      if (side_of(a, b, topo.vertices[topo.triangles[t].v[i]]) == across) return false;
  return true;
}

bool SegmentPass::asks(uint32_t k) const {
  if (k == own[0] || k == own[1] || (front != nullptr && front[k] == 0)) return false;
  if (own_end > own_first && neighbour(k)) return false;
  return own_polygon == kNoFace || topo.triangles[k].polygon != own_polygon ||
         !coplanar_faces(topo, own[0], k);
}

// The first kBatch distinct positions after `after`, ascending, where the segment crosses a
// face's side on paper, meets a face's corner on paper, or passes through a face. Fewer than
// kBatch: there are no more. One look along the segment's cells finds a batch, so a segment
// with few cuts costs one.
int SegmentPass::next_cuts(int64_t after, int64_t cuts[kBatch]) const {
  const FaceBox sb = box_of(s.a, s.b, s.b);
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
      const uint32_t* v = topo.triangles[*k].v;
      const Point3 p[3] = {topo.vertices[v[0]], topo.vertices[v[1]], topo.vertices[v[2]]};
      const FaceBox fb = box_of(p[0], p[1], p[2]);
      // The box first: asks() may test a plane exactly (a large flat region's own faces).
      if (!overlap_on_paper(sb, fb) || !asks(*k)) continue;
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
int32_t SegmentPass::cover_at(int64_t m) const {
  const CoverPoint p = edge_point(s, m);
  const int32_t cx = cell_x(p), cy = cell_y(p);
  int32_t q = 0;
  for (const uint32_t* k = fg.begin(cx, cy); k != fg.end(cx, cy); ++k) {
    const uint32_t* v = topo.triangles[*k].v;
    const Point3 &a = topo.vertices[v[0]], &b = topo.vertices[v[1]], &c = topo.vertices[v[2]];
    // Outside the face's box on paper: no cover, exactly (p is (x / d, y / d), d <= 2^32).
    const FaceBox fb = box_of(a, b, c);
    if (p.x < fb.x0 * p.d || p.x > fb.x1 * p.d || p.y < fb.y0 * p.d || p.y > fb.y1 * p.d) continue;
    if (!asks(*k)) continue;
    ++st->face_tests;
    if (front != nullptr)
      q += cover_halves(a, b, c, p);
    else  // both sides hide: read every face counter-clockwise
      q += projected_area2(a, b, c) >= 0 ? cover_halves(a, b, c, p) : cover_halves(a, c, b, p);
  }
  ++st->tests;
  return q;
}

Status SegmentPass::run(uint32_t index, LineSink sink, LineRows rows) const {
  const RowWindow w = rows.on ? row_window(s, rows.lo, rows.hi) : RowWindow{0, kOne};
  if (w.lo >= w.hi) return Status::kOk;
  // The lower border cut a piece unless a cut lies exactly on it; the upper likewise (known
  // once the cuts reach it).
  bool clipped = w.lo > 0, clipped_top = w.hi < kOne;
  LinePiece pending{{index, 0, 0}, {own[0], own[1]}, &s, 0, false};
  bool have = false;
  int32_t q = 0;
  auto piece = [&](int64_t t0, int64_t t1) {
    // A piece too short for a point strictly inside keeps the q before it (solid/fallback.h);
    // a sliver a border cut is asked at the border, inside the piece it came from (which is
    // long enough to have been tested whole: the border lies strictly between its cuts). Every
    // face that covers a point of the border row meets the band's rows or the row above.
    if (t1 - t0 >= 2)
      q = cover_at(t0 + (t1 - t0) / 2);
    else if (t0 == w.lo && clipped)
      q = cover_at(t0);
    else if (t1 == w.hi && clipped_top)
      q = cover_at(t1);
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
        if (cuts[k] == w.hi) clipped_top = false;  // the border falls on a cut
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

}  // namespace haloplot
