#include "solid/face_crossing.h"

#include "haloplot/geometry/fraction.h"
#include "haloplot/geometry/wide.h"
#include "solid/pierce.h"

namespace haloplot {
namespace {

// A plane's normal (B - A) x (C - A): each component below 2^43 (solid/pierce.h's budget),
// and n . (P - A) below 2^66, in a Wide.
struct Normal {
  int64_t x, y, z;
};

Normal normal_of(const Point3 t[3]) {
  const int64_t ux = int64_t{t[1].x} - t[0].x, uy = int64_t{t[1].y} - t[0].y,
                uz = int64_t{t[1].z} - t[0].z;
  const int64_t vx = int64_t{t[2].x} - t[0].x, vy = int64_t{t[2].y} - t[0].y,
                vz = int64_t{t[2].z} - t[0].z;
  return Normal{uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
}

// The axis a triangle is read along: z (on paper) unless it is edge-on there. -1: degenerate.
int axis_of(const Normal& n) { return n.z != 0 ? 2 : (n.x != 0 ? 0 : (n.y != 0 ? 1 : -1)); }
int64_t component(const Normal& n, int axis) { return axis == 2 ? n.z : (axis == 0 ? n.x : n.y); }

// Coordinates turned so that `axis` becomes z. The turn is cyclic, so the turned triangle's
// z normal is the normal's `axis` component, and every coordinate keeps its range: the exact
// tests of solid/pierce.h hold their budget unchanged.
Point3 turn(const Point3& p, int axis) {
  return axis == 2 ? p : (axis == 0 ? Point3{p.y, p.z, p.x} : Point3{p.z, p.x, p.y});
}

int plane_side(const Normal& n, const Point3& on, const Point3& p) {
  return haloplot::plane_side(n.x, n.y, n.z, on, p);
}

// A point of t's plane inside t or on a side, read along `axis` (2-D crosses: below 2^43).
bool inside_closed(const Point3 t[3], const Normal& n, int axis, const Point3& p) {
  const int64_t nz = component(n, axis);
  const Point3 q = turn(p, axis);
  for (int s = 0; s < 3; ++s) {
    const Point3 a = turn(t[s], axis), b = turn(t[(s + 1) % 3], axis);
    const int64_t o =
        int64_t{b.x - a.x} * (int64_t{q.y} - a.y) - int64_t{b.y - a.y} * (int64_t{q.x} - a.x);
    if (o != 0 && (o > 0) != (nz > 0)) return false;
  }
  return true;
}

struct Candidates {
  Point3 p[12];
  int n = 0;
  int through = 0;  // ends where a side passes strictly through the other face
};

// Where p's sides pass through q (q read along its axis), rounded to units.
void sides_through(const Point3 p[3], const Point3 q[3], int axis, Candidates* c) {
  const Point3 A = turn(q[0], axis), B = turn(q[1], axis), C = turn(q[2], axis);
  for (int s = 0; s < 3; ++s) {
    const Point3 &a = p[s], &b = p[(s + 1) % 3];
    const int64_t t = pierce_q32(turn(a, axis), turn(b, axis), A, B, C);
    if (t < 0) continue;
    c->p[c->n++] = Point3{lerp_round(a.x, b.x - a.x, t), lerp_round(a.y, b.y - a.y, t),
                          lerp_round(a.z, b.z - a.z, t)};
    ++c->through;
  }
}

// p's corners that lie in q's plane, inside q.
void corners_in(const Point3 p[3], const Point3 q[3], const Normal& n, int axis, Candidates* c) {
  for (int k = 0; k < 3; ++k)
    if (plane_side(n, q[0], p[k]) == 0 && inside_closed(q, n, axis, p[k])) c->p[c->n++] = p[k];
}

// All three corners strictly on one side of the other plane, or all in it: no crossing.
bool one_side(const Normal& n, const Point3 q[3], const Point3 p[3]) {
  const int s0 = plane_side(n, q[0], p[0]), s1 = plane_side(n, q[0], p[1]),
            s2 = plane_side(n, q[0], p[2]);
  return s0 == s1 && s1 == s2;
}

int32_t abs_i32(int32_t v) { return v < 0 ? -v : v; }
int32_t chebyshev(const Point3& a, const Point3& b) {
  const int32_t dx = abs_i32(a.x - b.x), dy = abs_i32(a.y - b.y), dz = abs_i32(a.z - b.z);
  const int32_t m = dx > dy ? dx : dy;
  return m > dz ? m : dz;
}

}  // namespace

bool face_crossing(const Point3 p[3], const Point3 q[3], Edge3* out) {
  const Normal np = normal_of(p), nq = normal_of(q);
  const int ap = axis_of(np), aq = axis_of(nq);
  if (ap < 0 || aq < 0) return false;  // a triangle without area
  if (one_side(nq, q, p) || one_side(np, p, q)) return false;
  Candidates c;
  sides_through(p, q, aq, &c);
  sides_through(q, p, ap, &c);
  if (c.through == 0) return false;  // they only touch
  corners_in(p, q, nq, aq, &c);
  corners_in(q, p, np, ap, &c);
  // On one line: the pair farthest apart in any norm is its two ends.
  int32_t best = -1;
  for (int i = 0; i < c.n; ++i)
    for (int j = i + 1; j < c.n; ++j) {
      const int32_t d = chebyshev(c.p[i], c.p[j]);
      if (d > best) {
        best = d;
        *out = Edge3{c.p[i], c.p[j]};
      }
    }
  return best >= 0 && (out->a.x != out->b.x || out->a.y != out->b.y);
}

}  // namespace haloplot
