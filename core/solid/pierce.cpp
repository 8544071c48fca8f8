#include "solid/pierce.h"

#include "haloplot/cut/grid.h"
#include "haloplot/geometry/contract.h"
#include "haloplot/geometry/wide.h"

namespace haloplot {
namespace {

// The bit budget of the header comment: a normal's component is a difference of two products
// of differences; g sums three normal-times-difference products; the inside test multiplies
// the denominator (|g(a)| + |g(b)|) by a cross product of differences.
constexpr int kNormalBits = 2 * kDiffBits + 1;       // 43
constexpr int kGBits = kNormalBits + kDiffBits + 2;  // 66: three terms
constexpr int kDenBits = kGBits + 1;                 // 67: |g(a)| + |g(b)|
constexpr int kInsideBits = kDenBits + kCrossBits + 1;
static_assert(kNormalBits <= 62, "a normal component fits int64 (mul_i64 takes it)");
static_assert(kInsideBits <= 126, "D * o(a) + N * k fits a signed Wide");
static_assert(kDenBits + 1 <= 126, "the long division doubles a remainder below D");
// plane_side's estimate: n / 8 (floor) times a difference, three terms, fits int64; the
// remainders (below 8 each) leave an error below 3 * 8 * 2^21 in 8 * estimate.
constexpr int kEstimateBits = (kNormalBits - 3) + kDiffBits + 2;
static_assert(kEstimateBits <= 63, "plane_side's estimate fits int64");
constexpr int64_t kDecided = int64_t{3} << kDiffBits;  // |estimate| >= this: its sign is g's

int sign(Wide w) { return w.negative() ? -1 : (w.is_zero() ? 0 : 1); }
Wide abs_wide(Wide w) { return w.negative() ? -w : w; }

// m * v for m >= 0 below 2^67 and |v| < 2^43.
Wide mul_signed(Wide m, int64_t v) {
  const Wide p = mul_wide_u64(m, v < 0 ? 0 - uint64_t(v) : uint64_t(v));
  return v < 0 ? -p : p;
}

// Twice the signed area of (p0, p1, p) on paper.
int64_t orient(const Point3& p0, const Point3& p1, int64_t px, int64_t py) {
  return int64_t{p1.x - p0.x} * (py - p0.y) - int64_t{p1.y - p0.y} * (px - p0.x);
}

// floor(2^32 n / d) for 0 <= n < d < 2^67, by 32 steps of binary long division.
int64_t fraction_q32(Wide n, Wide d) {
  int64_t q = 0;
  Wide r = n;
  for (int i = 0; i < 32; ++i) {
    r = r + r;
    q <<= 1;
    if (d <= r) {
      r = r - d;
      q |= 1;
    }
  }
  return q;
}

}  // namespace

int plane_side(int64_t nx, int64_t ny, int64_t nz, const Point3& on, const Point3& p) {
  const int64_t dx = int64_t{p.x} - on.x, dy = int64_t{p.y} - on.y, dz = int64_t{p.z} - on.z;
  const int64_t estimate = (nx >> 3) * dx + (ny >> 3) * dy + (nz >> 3) * dz;
  if (estimate >= kDecided) return 1;
  if (estimate <= -kDecided) return -1;
  return sign(mul_i64(nx, dx) + mul_i64(ny, dy) + mul_i64(nz, dz));
}

int64_t pierce_q32(const Point3& a, const Point3& b, const Point3& A, const Point3& B,
                   const Point3& C, PierceSide* how) {
  const int64_t ux = int64_t{B.x} - A.x, uy = int64_t{B.y} - A.y, uz = int64_t{B.z} - A.z;
  const int64_t vx = int64_t{C.x} - A.x, vy = int64_t{C.y} - A.y, vz = int64_t{C.z} - A.z;
  const int64_t nz = ux * vy - uy * vx;
  if (nz == 0) return -1;  // edge-on: it covers nothing, it hides nothing
  const int64_t nx = uy * vz - uz * vy, ny = uz * vx - ux * vz;
  // Most segments do not reach the plane: both ends on one side, decided by the estimate.
  const int side_a = plane_side(nx, ny, nz, A, a);
  if (side_a == 0 || side_a == plane_side(nx, ny, nz, A, b)) return -1;
  auto g = [&](const Point3& p) {
    return mul_i64(nx, int64_t{p.x} - A.x) + mul_i64(ny, int64_t{p.y} - A.y) +
           mul_i64(nz, int64_t{p.z} - A.z);
  };
  const Wide ga = g(a), gb = g(b);
  const int sa = sign(ga), sb = sign(gb);
  if (sa == 0 || sb == 0 || sa == sb) return -1;
  const Wide n = abs_wide(ga), d = n + abs_wide(gb);  // t = n / d, strictly inside (0, 1)
  // The point a + t (b - a) on paper against each side of the triangle, times d > 0:
  // d o(a) + n k, with k the side's cross product with the edge's direction.
  const int64_t ex = int64_t{b.x} - a.x, ey = int64_t{b.y} - a.y;
  const Point3* corner[3] = {&A, &B, &C};
  bool on_side = false;
  for (int s = 0; s < 3; ++s) {
    const Point3& p0 = *corner[s];
    const Point3& p1 = *corner[(s + 1) % 3];
    const int64_t k = int64_t{p1.x - p0.x} * ey - int64_t{p1.y - p0.y} * ex;
    const Wide side = mul_signed(d, orient(p0, p1, a.x, a.y)) + mul_signed(n, k);
    const int ss = sign(side);
    if (ss != 0 && (ss > 0) != (nz > 0)) return -1;  // outside this side
    on_side = on_side || ss == 0;
  }
  if (how != nullptr) {
    how->on_side = on_side;
    // a starts in front of the plane (nearer the viewer, +z) where g's sign is nz's.
    how->a_in_front = (sa > 0) == (nz > 0);
  }
  return fraction_q32(n, d);
}

namespace {

// Every face of the grid that edge e may pass through (not one of its own, boxes and depth
// ranges meeting), tested exactly: visit(face, t, how) for each it passes through after `after`.
template <typename Visit>
void pierced_faces(const Topology& topo, const FaceGrid& fg, const uint8_t* front, uint32_t e,
                   int64_t after, uint64_t* face_tests, Visit visit) {
  const SolidEdge& se = topo.edges[e];
  const Point3 a = topo.vertices[se.v0], b = topo.vertices[se.v1];
  const int32_t x0 = min_i32(a.x, b.x), x1 = max_i32(a.x, b.x);
  const int32_t y0 = min_i32(a.y, b.y), y1 = max_i32(a.y, b.y);
  const int32_t z0 = min_i32(a.z, b.z), z1 = max_i32(a.z, b.z);
  for_each_cell(fg.grid, Edge3{a, b}, CellCover::kExact, 0, [&](uint32_t c) {
    for (const uint32_t* k = fg.faces + fg.first[c]; k != fg.faces + fg.first[c + 1]; ++k) {
      if (front != nullptr && !front[*k]) continue;
      const uint32_t* v = topo.triangles[*k].v;
      if (v[0] == se.v0 || v[1] == se.v0 || v[2] == se.v0 || v[0] == se.v1 || v[1] == se.v1 ||
          v[2] == se.v1)
        continue;
      const Point3 &A = topo.vertices[v[0]], &B = topo.vertices[v[1]], &C = topo.vertices[v[2]];
      // The pierce point lies in both boxes, its depth in both depth ranges.
      if (max_i32(A.x, max_i32(B.x, C.x)) < x0 || min_i32(A.x, min_i32(B.x, C.x)) > x1 ||
          max_i32(A.y, max_i32(B.y, C.y)) < y0 || min_i32(A.y, min_i32(B.y, C.y)) > y1 ||
          max_i32(A.z, max_i32(B.z, C.z)) < z0 || min_i32(A.z, min_i32(B.z, C.z)) > z1)
        continue;
      ++*face_tests;
      PierceSide how;
      const int64_t t = pierce_q32(a, b, A, B, C, &how);
      if (t > after) visit(*k, t, how);
    }
  });
}

}  // namespace

int64_t next_pierce(const Topology& topo, const FaceGrid& fg, const uint8_t* front, uint32_t e,
                    int64_t after, uint64_t* face_tests) {
  int64_t best = kNoPierce;
  pierced_faces(topo, fg, front, e, after, face_tests, [&](uint32_t, int64_t t, PierceSide) {
    if (t < best) best = t;
  });
  return best;
}

PierceEvent next_pierce_event(const Topology& topo, const FaceGrid& fg, const uint8_t* front,
                              uint32_t e, int64_t after, uint64_t* face_tests) {
  PierceEvent ev{kNoPierce, 0, true};
  // A face listed in several cells is found once per cell: each counts once at its place.
  uint32_t seen[kPierceFacesAtOnce];
  uint32_t n_seen = 0;
  pierced_faces(topo, fg, front, e, after, face_tests, [&](uint32_t f, int64_t t, PierceSide how) {
    if (t > ev.t) return;
    if (t < ev.t) {
      ev = PierceEvent{t, 0, true};
      n_seen = 0;
    }
    for (uint32_t i = 0; i < n_seen; ++i)
      if (seen[i] == f) return;
    if (n_seen == kPierceFacesAtOnce || how.on_side) {
      ev.exact = false;  // through a face's side, or too many faces at one point
      return;
    }
    seen[n_seen++] = f;
    ev.change += how.a_in_front ? 2 : -2;
  });
  return ev;
}

}  // namespace haloplot
