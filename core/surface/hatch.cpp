#include "surface/hatch.h"

#include "cut/cut.h"
#include "draw/draw.h"
#include "geometry/fraction.h"
#include "geometry/wide.h"
#include "memory/carve.h"
#include "solid/cover.h"
#include "solid/face_grid.h"
#include "view/trig.h"

namespace haloplot {
namespace {

constexpr int64_t kOne = int64_t{1} << 32;

bool hatched(const SolidInput& in, uint32_t t, const HatchParams& p) {
  const uint32_t* v = in.triangles[t].v;
  const int64_t area = projected_area2(in.vertices[v[0]], in.vertices[v[1]], in.vertices[v[2]]);
  return p.front_only ? area > 0 : area != 0;
}

// Calls line(Edge3) for each hatch segment of triangle t: the lattice line n . p = k S clipped
// to the triangle, ends rounded to steps (depth too).
template <typename Line>
void triangle_lines(const SolidInput& in, uint32_t t, const HatchParams& p, Line line) {
  const SinCos d = hatch_direction(in, t, p);
  const int64_t nx = -d.sin, ny = d.cos;  // the lines' normal, Q2.30
  const int64_t spacing = int64_t{p.spacing} << kTrigFractionBits;
  Point3 q[3];
  int64_t w[3];
  for (int k = 0; k < 3; ++k) {
    q[k] = in.vertices[in.triangles[t].v[k]];
    w[k] = nx * q[k].x + ny * q[k].y;  // below 2^51
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
      if (a == 0) {
        at = q[i];
      } else if ((a < 0) != (b < 0) && b != 0) {
        // The side meets the line at t = a / (a - b), strictly inside the side.
        const int64_t den = a - b > 0 ? a - b : b - a, num = a - b > 0 ? a : -a;
        at.x = q[i].x + static_cast<int32_t>(scale_round(q[j].x - q[i].x, num, den));
        at.y = q[i].y + static_cast<int32_t>(scale_round(q[j].y - q[i].y, num, den));
        at.z = q[i].z + static_cast<int32_t>(scale_round(q[j].z - q[i].z, num, den));
      } else {
        continue;
      }
      if (n == 1 && ends[0].x == at.x && ends[0].y == at.y) continue;
      ends[n++] = at;
    }
    if (n == 2) line(Edge3{ends[0], ends[1]});
  }
}

struct Counts {
  uint32_t lines = 0;
};

Counts count_lines(const SolidInput& in, const HatchParams& p) {
  Counts c;
  for (uint32_t t = 0; t < in.n_triangles; ++t)
    if (hatched(in, t, p)) triangle_lines(in, t, p, [&](const Edge3&) { ++c.lines; });
  return c;
}

// Every corner of triangle u on the plane of triangle t (exact 3-D orientations).
bool coplanar(const SolidInput& in, uint32_t t, uint32_t u) {
  const Point3 a = in.vertices[in.triangles[t].v[0]], b = in.vertices[in.triangles[t].v[1]],
               c = in.vertices[in.triangles[t].v[2]];
  const int64_t ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const int64_t vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
  const int64_t nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  for (int k = 0; k < 3; ++k) {
    const Point3 q = in.vertices[in.triangles[u].v[k]];
    if (!(mul_i64(nx, q.x - a.x) + mul_i64(ny, q.y - a.y) + mul_i64(nz, q.z - a.z)).is_zero())
      return false;
  }
  return true;
}

}  // namespace

// The lines' direction for a polygon: its angle grows with its mean depth (Franklin's Figure 4).
// The polygon is the run of consecutive triangles with its id, so both halves of a quad agree.
SinCos hatch_direction(const SolidInput& in, uint32_t t, const HatchParams& p) {
  uint32_t s = t, e = t + 1;
  while (s > 0 && in.triangles[s - 1].polygon == in.triangles[t].polygon) --s;
  while (e < in.n_triangles && in.triangles[e].polygon == in.triangles[t].polygon) ++e;
  int64_t sum = 0, n = 0;
  for (uint32_t i = s; i < e; ++i)
    for (int k = 0; k < 3; ++k, ++n) sum += in.vertices[in.triangles[i].v[k]].z;
  const int64_t mean = n > 0 ? sum / n : 0;
  const int64_t angle = p.angle_mdeg + (int64_t{p.mdeg_per_depth} * mean >> kCoordBits);
  return sin_cos_mdeg(static_cast<int32_t>(angle % 360000));
}

size_t hatch_bytes(const SolidInput& in, const HatchParams& params, uint32_t crossing_capacity) {
  const Counts c = count_lines(in, params);
  const uint32_t n = 3 * in.n_triangles + c.lines;
  ByteCounter b;
  b.take<Edge3>(n);
  b.take<uint32_t>(c.lines);
  b.take<uint8_t>(face_grid_bytes(faces_only(in)));
  b.take<uint8_t>(cutset_bytes(n, crossing_capacity));
  // CUT's scratch is sized from its plan over these edges: bounded here by a plan on the fly.
  return b.total + 64 + size_t{n} * 64 + size_t{crossing_capacity} * 16;
}

Status hatch_faces(const SolidInput& in, const HatchParams& params, uint32_t crossing_capacity,
                   void* buffer, size_t bytes, HatchSink sink, HatchStats* stats) {
  if (params.spacing < 1 || params.spacing > kCoordMax) return Status::kBadParameter;
  for (uint32_t v = 0; v < in.n_vertices; ++v)
    if (!in_range(in.vertices[v])) return Status::kCoordinateOutOfRange;
  HatchStats st;
  const Counts c = count_lines(in, params);
  st.lines = c.lines;
  const uint32_t sides = 3 * in.n_triangles, n = sides + c.lines;
  Carver carve(buffer, bytes);
  Edge3* edges = carve.take<Edge3>(n);
  uint32_t* owner = carve.take<uint32_t>(c.lines);
  const Topology topo = faces_only(in);
  const size_t grid_bytes = face_grid_bytes(topo);
  uint8_t* grid_mem = carve.take<uint8_t>(grid_bytes);
  const size_t cs_bytes = cutset_bytes(n, crossing_capacity);
  uint8_t* cs_mem = carve.take<uint8_t>(cs_bytes);
  if (carve.short_) {
    st.bytes_needed = bytes + grid_bytes + cs_bytes + size_t{n} * sizeof(Edge3);
    if (stats) *stats = st;
    return Status::kWorkspaceTooSmall;
  }
  // Every triangle side (the occluders' boundaries), then the hatch lines.
  for (uint32_t t = 0; t < in.n_triangles; ++t)
    for (int k = 0; k < 3; ++k)
      edges[3 * t + k] =
          Edge3{in.vertices[in.triangles[t].v[k]], in.vertices[in.triangles[t].v[(k + 1) % 3]]};
  uint32_t h = 0;
  for (uint32_t t = 0; t < in.n_triangles; ++t)
    if (hatched(in, t, params))
      triangle_lines(in, t, params, [&](const Edge3& e) {
        owner[h] = t;
        edges[sides + h++] = e;
      });
  FaceGrid fg;
  Status s = build_face_grid(topo, grid_mem, grid_bytes, &fg);
  if (s != Status::kOk) return s;
  CutPlan plan;
  s = plan_cut(edges, n, CutParams{}, &plan);
  if (s != Status::kOk) return s;
  const size_t used = bytes - carve.left;
  uint8_t* scratch = carve.take<uint8_t>(plan.scratch_bytes);
  if (scratch == nullptr) {
    st.bytes_needed = used + plan.scratch_bytes + 16;
    if (stats) *stats = st;
    return Status::kWorkspaceTooSmall;
  }
  CutSet cs;
  CutStats cut;
  s = run_cut(plan, edges, scratch, plan.scratch_bytes, cs_mem, cs_bytes, &cs, &cut);
  st.crossings = cut.crossings;
  if (s != Status::kOk) {
    if (stats) *stats = st;
    return s;
  }
  for (uint32_t i = 0; i < c.lines; ++i) {
    const uint32_t e = sides + i;
    const Edge3& ed = edges[e];
    const uint32_t poly = in.triangles[owner[i]].polygon;
    auto visible = [&](int64_t t0, int64_t t1) {
      if (t1 - t0 < 2) return false;
      const int64_t m = t0 + (t1 - t0) / 2;
      const CoverPoint pt = edge_point(ed, m);
      ++st.midpoint_tests;
      const int32_t cx = cell_x(pt), cy = cell_y(pt);
      for (const uint32_t* f = fg.begin(cx, cy); f != fg.end(cx, cy); ++f) {
        // Its own face, and the rest of its polygon when flat: it lies on them. A bent
        // polygon's other half can fold over it, and is asked like any face.
        if (*f == owner[i] || (in.triangles[*f].polygon == poly && coplanar(in, owner[i], *f)))
          continue;
        const uint32_t* v = in.triangles[*f].v;
        const Point3 &a = in.vertices[v[0]], &b = in.vertices[v[1]], &cc = in.vertices[v[2]];
        const int cover = projected_area2(a, b, cc) >= 0 ? cover_halves(a, b, cc, pt)
                                                         : cover_halves(a, cc, b, pt);
        if (cover != 0) return false;
      }
      return true;
    };
    int64_t at = 0, run_start = -1;
    auto close_run = [&](int64_t end) -> Status {
      if (run_start < 0) return Status::kOk;
      HatchStroke stroke{owner[i], poly, Edge3{}};
      span_point(ed, run_start, &stroke.line.a.x, &stroke.line.a.y);
      span_point(ed, end, &stroke.line.b.x, &stroke.line.b.y);
      run_start = -1;
      ++st.visible_pieces;
      return sink.emit(sink.context, stroke);
    };
    auto piece = [&](int64_t t0, int64_t t1) -> Status {
      if (t1 <= t0) return Status::kOk;
      ++st.pieces;
      if (visible(t0, t1)) {
        if (run_start < 0) run_start = t0;
        return Status::kOk;
      }
      return close_run(t0);
    };
    for (const Crossing* x = cs.begin(e); s == Status::kOk && x != cs.begin(e) + cs.count(e); ++x) {
      if (x->front_edge() >= sides) continue;  // another hatch line hides nothing
      s = piece(at, x->t);
      at = x->t;
    }
    if (s == Status::kOk) s = piece(at, kOne);
    if (s == Status::kOk) s = close_run(kOne);
    if (s != Status::kOk) break;
  }
  if (stats) *stats = st;
  return s;
}

}  // namespace haloplot
