#include "haloplot/curve/bezier.h"

namespace haloplot {

namespace {

FixPoint3 fix(const Point3& p) { return FixPoint3{to_fix(p.x), to_fix(p.y), to_fix(p.z)}; }

// The average of two coordinates in [0, 2^62): the sum stays below 2^63, and at level k every
// coordinate is a multiple of 2^(42 - 3k), so each of the three averages of a halving to level
// k + 1 <= 14 is exact (the shift drops a zero bit).
int64_t avg(int64_t a, int64_t b) { return (a + b) >> 1; }
FixPoint3 avg(const FixPoint3& a, const FixPoint3& b) {
  return FixPoint3{avg(a.x, b.x), avg(a.y, b.y), avg(a.z, b.z)};
}

int64_t abs64(int64_t v) { return v < 0 ? -v : v; }

// ceil(3/4 * max(|a0 - 2 a1 + a2|, |a1 - 2 a2 + a3|)), each second difference taken as a
// difference of differences so nothing exceeds 2^63.
uint64_t flat_bound(int64_t a0, int64_t a1, int64_t a2, int64_t a3) {
  const uint64_t m1 = static_cast<uint64_t>(abs64((a0 - a1) - (a1 - a2)));
  const uint64_t m2 = static_cast<uint64_t>(abs64((a1 - a2) - (a2 - a3)));
  const uint64_t m = m1 > m2 ? m1 : m2;
  return m - m / 4;  // = ceil(3m / 4)
}

int64_t min4(int64_t a, int64_t b, int64_t c, int64_t d) {
  const int64_t ab = a < b ? a : b, cd = c < d ? c : d;
  return ab < cd ? ab : cd;
}
int64_t max4(int64_t a, int64_t b, int64_t c, int64_t d) {
  const int64_t ab = a > b ? a : b, cd = c > d ? c : d;
  return ab > cd ? ab : cd;
}

}  // namespace

CurvePiece whole_piece(const BezierEdge3& e, uint32_t curve) {
  CurvePiece p;
  for (int i = 0; i < 4; ++i) p.p[i] = fix(e.p[i]);
  p.curve = curve;
  p.index = 0;
  p.level = 0;
  p.straight = false;
  return p;
}

CurvePiece segment_piece(const Edge3& e, uint32_t curve) {
  CurvePiece p;
  p.p[0] = p.p[1] = fix(e.a);
  p.p[2] = p.p[3] = fix(e.b);
  p.curve = curve;
  p.index = 0;
  p.level = 0;
  p.straight = true;
  return p;
}

void halve(const CurvePiece& in, CurvePiece* left, CurvePiece* right) {
  *left = in;
  *right = in;
  left->level = right->level = static_cast<uint8_t>(in.level + 1);
  left->index = in.index * 2;
  right->index = in.index * 2 + 1;
  if (in.straight) {
    const FixPoint3 mid = avg(in.p[0], in.p[3]);
    left->p[2] = left->p[3] = mid;
    right->p[0] = right->p[1] = mid;
    return;
  }
  const FixPoint3 m01 = avg(in.p[0], in.p[1]), m12 = avg(in.p[1], in.p[2]);
  const FixPoint3 m23 = avg(in.p[2], in.p[3]);
  const FixPoint3 m012 = avg(m01, m12), m123 = avg(m12, m23);
  const FixPoint3 mid = avg(m012, m123);
  left->p[1] = m01;
  left->p[2] = m012;
  left->p[3] = mid;
  right->p[0] = mid;
  right->p[1] = m123;
  right->p[2] = m23;
}

Flatness flatness(const CurvePiece& p) {
  if (p.straight) return Flatness{0, 0, 0};
  const FixPoint3* c = p.p;
  return Flatness{flat_bound(c[0].x, c[1].x, c[2].x, c[3].x),
                  flat_bound(c[0].y, c[1].y, c[2].y, c[3].y),
                  flat_bound(c[0].z, c[1].z, c[2].z, c[3].z)};
}

FixBox box_of(const CurvePiece& p) {
  const FixPoint3* c = p.p;
  return FixBox{min4(c[0].x, c[1].x, c[2].x, c[3].x), min4(c[0].y, c[1].y, c[2].y, c[3].y),
                max4(c[0].x, c[1].x, c[2].x, c[3].x), max4(c[0].y, c[1].y, c[2].y, c[3].y)};
}

}  // namespace haloplot
