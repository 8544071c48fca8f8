#include "haloplot/solid/intersection_lines.h"

#include "solid/face_crossing.h"

namespace haloplot {
namespace {

bool shares_corner(const Triangle& s, const Triangle& t) {
  for (uint32_t u : s.v)
    if (u == t.v[0] || u == t.v[1] || u == t.v[2]) return true;
  return false;
}

}  // namespace

Status draw_intersections(const Topology& topo, const uint8_t* front, const FaceGrid& fg,
                          LineSink sink, IntersectionStats* stats, LineRows rows) {
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
  auto pair = [&](uint32_t i, const FaceBox& bi, uint32_t j, const FaceBox& bj) {
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
    FaceBox boxes[kCached];
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
      const FaceBox bf = box(*f);
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
