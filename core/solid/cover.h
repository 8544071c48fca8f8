// The one exact question every hidden-line rule asks: does triangle T cover the point P,
// nudged an infinitesimal step along direction `dir`, and is T in front of it there?
//
// The nudge is what makes the singular cases exact instead of special: P on a side of T,
// P on a corner of T (Heger's wedge test), P where a contour ends (half and quarter q.i.),
// and P on an edge running along a side of T (occluded edges). When `dir` itself runs along
// a side of T the point is exactly on T's boundary and T covers it by one half: the average
// of nudging it to either side, which is Heger's fractional q.i. Counts are therefore in
// halves: 2 = covers, 1 = on the boundary, 0 = does not.
//
// In front: T's plane is nearer (larger depth) than the point at P, or level with it there
// and rising faster along `dir` than the point's own line. Level and equally steep means the
// point lies in T's plane: not covered.
//
// Bit budget (geometry/contract.h: coordinates below 2^20): P is (x/d, y/d) with d = 1 or
// d = 2^32 (a Q0.32 position along an edge), so |x|, |y| < 2^52; a side test times d is a
// 21-bit difference times a 53-bit one, below 2^75; T's depth at P times its doubled area and
// d is below 2^97, times the point's depth denominator (up to 2^42) below 2^127. Those use
// geometry/wide.h. The slope comparison stays below 2^63 (static_assert in cover.cpp).
#pragma once
#include <stdint.h>

#include "haloplot/geometry/contract.h"
#include "haloplot/geometry/wide.h"

namespace haloplot {

struct CoverPoint {
  int64_t x = 0, y = 0, d = 1;   // P = (x / d, y / d); d is 1 or 2^32
  Wide zn;                       // the point's depth is zn / zd ...
  int64_t zd = 1;                // ... with zd == d, or d == 1 and 0 < zd < 2^42
  int32_t dir_x = 0, dir_y = 0;  // the nudge: never (0, 0)
  int32_t dir_z = 0;             // the point's depth change along dir (same scale as dir)
};

// A vertex of the mesh nudged toward `to` along the edge that joins them (inline: the QI walk
// asks two for every edge).
inline CoverPoint vertex_toward(const Point3& p, const Point3& to) {
  CoverPoint c;
  c.x = p.x;
  c.y = p.y;
  c.d = 1;
  c.zn = Wide::from_i64(p.z);
  c.zd = 1;
  c.dir_x = to.x - p.x;
  c.dir_y = to.y - p.y;
  c.dir_z = to.z - p.z;
  return c;
}

// The point at Q0.32 position m along e (0 <= m <= 2^32), nudged along e: the middle of a
// piece, as the midpoint tests ask it. cell_x / cell_y are its floors (its grid cell).
CoverPoint edge_point(const Edge3& e, int64_t m);
inline int32_t cell_x(const CoverPoint& p) { return static_cast<int32_t>(p.x >> 32); }
inline int32_t cell_y(const CoverPoint& p) { return static_cast<int32_t>(p.y >> 32); }

// Doubled signed area of the projection: > 0 is a front face (counter-clockwise on paper).
inline int64_t projected_area2(const Point3& a, const Point3& b, const Point3& c) {
  return int64_t{b.x - a.x} * (c.y - a.y) - int64_t{b.y - a.y} * (c.x - a.x);
}

// Halves of cover of P by front-facing T = (a, b, c) in front of P (0 for a back face).
int cover_halves(const Point3& a, const Point3& b, const Point3& c, const CoverPoint& p);

// cover_halves(a, b, c, p) where p is corner a's own point at a's depth (vertex_toward(a, to)):
// a vertex asked about the faces of its own star, the QI walk's commonest question by far. The
// same answer by fewer steps: the side opposite a is the doubled area, > 0, and T is level with
// P there, so only the nudge's two sides through a and the rise along it decide.
// Inline: the walk asks it a few times for every edge it walks. Its products are those of
// cover_halves' slope comparison (the same bound, static_assert'ed in cover.cpp) and side
// tests of 21-bit differences:
static_assert((int64_t{1} << 21) * (int64_t{1} << 21) * 2 <= (int64_t{1} << 43),
              "a corner's nudge test must fit int64_t");
inline int corner_cover_halves(const Point3& a, const Point3& b, const Point3& c,
                               const CoverPoint& p) {
  const int64_t area = projected_area2(a, b, c);
  if (area <= 0) return 0;
  // inside_halves' corner case for a: the side b -> c is 1, the two through a by the nudge
  // (nudge_side: the sign of cross(side, dir), 21-bit differences times 21-bit ones).
  const int64_t gx = int64_t{p.dir_x}, gy = int64_t{p.dir_y};
  const int64_t s0 = int64_t{b.x - a.x} * gy - int64_t{b.y - a.y} * gx;
  const int64_t s2 = int64_t{a.x - c.x} * gy - int64_t{a.y - c.y} * gx;
  if (s0 < 0 || s2 < 0) return 0;
  const int h = 2 - (s0 == 0) - (s2 == 0);
  if (h == 0) return 0;
  // at_corner(a, p): level at P, the rises decide, as in cover_halves (the doubled area times
  // the plane's rise along the nudge is the same whichever corner it starts from).
  const int64_t rise_t =
      int64_t{b.z - a.z} * (gx * (c.y - a.y) - gy * (c.x - a.x)) + int64_t{c.z - a.z} * s0;
  return rise_t > int64_t{p.dir_z} * area ? h : 0;
}

// Halves of cover of P by T's projection alone, whatever T's facing and depth (Kira's outline
// condition: is any face around this point at all?). 0 for an edge-on T.
int projection_cover_halves(const Point3& a, const Point3& b, const Point3& c, const CoverPoint& p);

// The sign of the depth of T's plane minus the point's depth, at P (without the nudge).
int plane_depth_sign(const Point3& a, const Point3& b, const Point3& c, const CoverPoint& p);

// Wide times a signed 64-bit value, for products the caller's budget keeps below 2^126.
Wide mul_wide_i64(Wide a, int64_t b);

}  // namespace haloplot
