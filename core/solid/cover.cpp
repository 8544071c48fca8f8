#include "solid/cover.h"

namespace haloplot {
namespace {

// Slope comparison: z differences (|.| < 2^20) times cross products of differences (< 2^41),
// two of them summed; and dir_z times the doubled area.
static_assert((int64_t{1} << 20) * (int64_t{1} << 41) * 2 <= (int64_t{1} << 62),
              "the slope comparison must fit int64_t");

int wide_sign(Wide w) { return w.negative() ? -1 : (w.is_zero() ? 0 : 1); }

// Side of P against the directed line u -> v, times d: cross(v - u, P - u) * d.
Wide side_times_d(const Point3& u, const Point3& v, const CoverPoint& p) {
  const int64_t ex = v.x - u.x, ey = v.y - u.y;
  const int64_t px = p.x - int64_t{u.x} * p.d, py = p.y - int64_t{u.y} * p.d;
  return mul_i64(ex, py) - mul_i64(ey, px);
}

// A whole point (d = 1, every vertex test of the QI walk) needs no wide product: its side test
// is a 21-bit difference times a 21-bit one, twice, below 2^43.
static_assert((int64_t{1} << 21) * (int64_t{1} << 21) * 2 <= (int64_t{1} << 43),
              "a whole point's side test must fit int64_t");

// The sign of side_times_d.
int side_sign(const Point3& u, const Point3& v, const CoverPoint& p) {
  if (p.d == 1) {
    const int64_t s = int64_t{v.x - u.x} * (p.y - u.y) - int64_t{v.y - u.y} * (p.x - u.x);
    return (s > 0) - (s < 0);
  }
  return wide_sign(side_times_d(u, v, p));
}

// The sign P takes against u -> v after the nudge; 0 only when P is on the line and the nudge
// runs along it.
// The nudge's side of u -> v: what decides when P is on the line.
int nudge_side(const Point3& u, const Point3& v, const CoverPoint& p) {
  const int64_t c = int64_t{v.x - u.x} * p.dir_y - int64_t{v.y - u.y} * p.dir_x;
  return (c > 0) - (c < 0);
}

int nudged_side(const Point3& u, const Point3& v, const CoverPoint& p) {
  const int s = side_sign(u, v, p);
  return s != 0 ? s : nudge_side(u, v, p);
}

bool on_point(const Point3& u, const CoverPoint& p) { return p.d == 1 && p.x == u.x && p.y == u.y; }

// Halves of cover for a counter-clockwise triangle (area > 0), by the nudged sides alone.
int inside_halves(const Point3& a, const Point3& b, const Point3& c, const CoverPoint& p) {
  int s0, s1, s2;
  // P on a corner (a vertex asked about its own faces): both sides through it are 0 before the
  // nudge, and the side opposite is the doubled area, > 0; the same signs as the tests give.
  if (on_point(a, p)) {
    s0 = nudge_side(a, b, p), s1 = 1, s2 = nudge_side(c, a, p);
  } else if (on_point(b, p)) {
    s0 = nudge_side(a, b, p), s1 = nudge_side(b, c, p), s2 = 1;
  } else if (on_point(c, p)) {
    s0 = 1, s1 = nudge_side(b, c, p), s2 = nudge_side(c, a, p);
  } else {
    s0 = nudged_side(a, b, p), s1 = nudged_side(b, c, p), s2 = nudged_side(c, a, p);
  }
  if (s0 < 0 || s1 < 0 || s2 < 0) return 0;
  const int zeros = (s0 == 0) + (s1 == 0) + (s2 == 0);
  return zeros == 0 ? 2 : (zeros == 1 ? 1 : 0);
}

// Is P the point of corner u, at u's depth?
bool at_corner(const Point3& u, const CoverPoint& p) {
  return p.d == 1 && p.zd == 1 && p.x == u.x && p.y == u.y && p.zn == Wide::from_i64(u.z);
}

}  // namespace

Wide mul_wide_i64(Wide a, int64_t b) {
  const bool neg = a.negative() != (b < 0);
  const Wide ma = a.negative() ? -a : a;
  const uint64_t mb = b < 0 ? uint64_t(0) - uint64_t(b) : uint64_t(b);
  const Wide r = mul_wide_u64(ma, mb);
  return neg ? -r : r;
}

CoverPoint edge_point(const Edge3& e, int64_t m) {
  constexpr int64_t kOne = int64_t{1} << 32;
  const int64_t dx = e.b.x - e.a.x, dy = e.b.y - e.a.y, dz = e.b.z - e.a.z;
  CoverPoint c;
  c.d = kOne;
  c.x = int64_t{e.a.x} * kOne + dx * m;
  c.y = int64_t{e.a.y} * kOne + dy * m;
  c.zn = Wide::from_i64(int64_t{e.a.z} * kOne + dz * m);
  c.zd = kOne;
  c.dir_x = static_cast<int32_t>(dx);
  c.dir_y = static_cast<int32_t>(dy);
  c.dir_z = static_cast<int32_t>(dz);
  return c;
}

int plane_depth_sign(const Point3& a, const Point3& b, const Point3& c, const CoverPoint& p) {
  int64_t area = projected_area2(a, b, c);
  if (area == 0) return 0;
  // z_T(P) * A * d = za*A*d + (zb - za) * cross(P - a, c - a) * d + (zc - za) * cross(b - a, P - a)
  // * d
  const Wide cb = side_times_d(c, a, p);  // cross(a - c, P - c)*d equals cross(P - a, c - a)*d
  const Wide cc = side_times_d(a, b, p);  // cross(b - a, P - a) * d
  Wide lhs = mul_i64(int64_t{a.z} * area, p.d) + mul_wide_i64(cb, int64_t{b.z} - a.z) +
             mul_wide_i64(cc, int64_t{c.z} - a.z);
  Wide rhs;
  if (p.zd == p.d) {
    rhs = mul_wide_i64(p.zn, area);
  } else {
    lhs = mul_wide_i64(lhs, p.zd);  // d == 1 here
    rhs = mul_wide_i64(p.zn, area);
  }
  // Dividing by A flips the comparison for a clockwise triangle.
  const int s = compare(lhs, rhs);
  return area > 0 ? s : -s;
}

int cover_halves(const Point3& a, const Point3& b, const Point3& c, const CoverPoint& p) {
  const int64_t area = projected_area2(a, b, c);
  if (area <= 0) return 0;  // back faces and edge-on faces hide nothing in the count
  const int h = inside_halves(a, b, c, p);
  if (h == 0) return 0;
  // P on one of T's corners at that corner's depth (a vertex asked about its own faces, the
  // QI walk's commonest question) is level with T's plane: no need to work the depth out.
  const int s =
      at_corner(a, p) || at_corner(b, p) || at_corner(c, p) ? 0 : plane_depth_sign(a, b, c, p);
  if (s != 0) return s > 0 ? h : 0;
  // Level at P: compare the rise along the nudge, both times A.
  const int64_t gx = int64_t{p.dir_x}, gy = int64_t{p.dir_y};
  const int64_t rise_t = int64_t{b.z - a.z} * (gx * (c.y - a.y) - gy * (c.x - a.x)) +
                         int64_t{c.z - a.z} * (int64_t{b.x - a.x} * gy - int64_t{b.y - a.y} * gx);
  const int64_t rise_p = int64_t{p.dir_z} * area;
  return rise_t > rise_p ? h : 0;
}

int projection_cover_halves(const Point3& a, const Point3& b, const Point3& c,
                            const CoverPoint& p) {
  const int64_t area = projected_area2(a, b, c);
  if (area == 0) return 0;
  return area > 0 ? inside_halves(a, b, c, p) : inside_halves(a, c, b, p);
}

}  // namespace haloplot
