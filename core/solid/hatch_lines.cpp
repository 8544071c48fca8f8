#include "solid/hatch_lines.h"

#include "geometry/fraction.h"
#include "solid/cover.h"

namespace haloplot {
namespace {

// w = n . p with n in Q2.30 and coordinates below 2^20: below 2^51; the levels k S likewise.
static_assert(kCoordBits + kTrigFractionBits + 1 < 62, "a line's level fits in int64");

bool point_before(const Point3& p, const Point3& q) {
  if (p.x != q.x) return p.x < q.x;
  if (p.y != q.y) return p.y < q.y;
  return p.z < q.z;
}

// Where the side from p (w_p) to q (w_q) meets the level, strictly inside it, rounded to
// units from the side's lesser end: any triangle holding the side finds the same point.
Point3 side_point(Point3 p, Point3 q, int64_t a, int64_t b) {
  if (point_before(q, p)) {
    const Point3 t = p;
    p = q;
    q = t;
    const int64_t u = a;
    a = b;
    b = u;
  }
  const int64_t den = a - b > 0 ? a - b : b - a, num = a - b > 0 ? a : -a;
  return Point3{p.x + static_cast<int32_t>(scale_round(q.x - p.x, num, den)),
                p.y + static_cast<int32_t>(scale_round(q.y - p.y, num, den)),
                p.z + static_cast<int32_t>(scale_round(q.z - p.z, num, den))};
}

// Calls line(Edge3) for each hatch line of triangle t: the lattice line n . p = k S clipped to
// the triangle, ends rounded.
template <typename Line>
Status triangle_lines(const Topology& topo, uint32_t t, const HatchParams& p, Line line) {
  const SinCos d = hatch_direction(topo.triangles, topo.n_triangles, topo.vertices, t, p);
  const int64_t nx = -d.sin, ny = d.cos;  // the lines' normal, Q2.30
  const int64_t spacing = int64_t{p.spacing} << kTrigFractionBits;
  Point3 q[3];
  int64_t w[3];
  for (int k = 0; k < 3; ++k) {
    q[k] = topo.vertices[topo.triangles[t].v[k]];
    w[k] = nx * q[k].x + ny * q[k].y;
  }
  int64_t lo = w[0], hi = w[0];
  for (int k = 1; k < 3; ++k) {
    lo = w[k] < lo ? w[k] : lo;
    hi = w[k] > hi ? w[k] : hi;
  }
  const int64_t k0 = -floor_div(-lo, spacing), k1 = floor_div(hi, spacing);
  for (int64_t k = k0; k <= k1; ++k) {
    const int64_t level = k * spacing;
    Point3 ends[2];
    int n = 0;
    for (int i = 0; i < 3 && n < 2; ++i) {
      const int j = (i + 1) % 3;
      const int64_t a = w[i] - level, b = w[j] - level;
      Point3 at;
      if (a == 0)
        at = q[i];
      else if ((a < 0) != (b < 0) && b != 0)
        at = side_point(q[i], q[j], a, b);
      else
        continue;
      if (n == 1 && ends[0].x == at.x && ends[0].y == at.y) continue;
      ends[n++] = at;
    }
    if (n < 2) continue;
    const Status s = line(Edge3{ends[0], ends[1]});
    if (s != Status::kOk) return s;
  }
  return Status::kOk;
}

}  // namespace

bool hatched_face(const Topology& topo, const uint8_t* front, uint32_t t,
                  const HatchParams& params) {
  if (front != nullptr) return front[t] != 0;
  const uint32_t* v = topo.triangles[t].v;
  const int64_t area =
      projected_area2(topo.vertices[v[0]], topo.vertices[v[1]], topo.vertices[v[2]]);
  return params.front_only ? area > 0 : area != 0;
}

Status draw_hatch_lines(const Topology& topo, const uint8_t* front, const FaceGrid& fg,
                        const HatchParams& params, uint32_t first_index, LineSink sink,
                        HatchLineStats* stats, LineRows rows) {
  if (params.spacing < 1 || params.spacing > kCoordMax) return Status::kBadParameter;
  HatchLineStats st;
  uint32_t index = first_index;
  Status s = Status::kOk;
  for (uint32_t t = 0; t < topo.n_triangles && s == Status::kOk; ++t) {
    if (!hatched_face(topo, front, t, params)) continue;
    ++st.faces;
    s = triangle_lines(topo, t, params, [&](const Edge3& e) {
      const int32_t y0 = min_i32(e.a.y, e.b.y), y1 = max_i32(e.a.y, e.b.y);
      if (rows.on && (y1 < rows.lo || y0 >= rows.hi)) return Status::kOk;  // not in the band
      ++st.lines;
      const SegmentPass pass{topo, front, fg, &st, e, {t, kNoFace}, topo.triangles[t].polygon};
      return pass.run(index++, sink, rows);
    });
  }
  if (stats != nullptr) *stats = st;
  return s;
}

}  // namespace haloplot
