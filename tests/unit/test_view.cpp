// The view transform against long double: Q2.30 sine and cosine within 4 units of 2^-30 on
// every millidegree of the first octant and on random angles; projected points within the
// documented 1/2 + 2^-9 steps of an exact-real fit computed independently here; bad views,
// out-of-range world points and bad edge indices refused by name.
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "../check.h"
#include "haloplot/view/facing.h"
#include "haloplot/view/projection.h"
#include "haloplot/view/trig.h"

using namespace haloplot;

namespace {

constexpr long double kPi = 3.141592653589793238462643383279502884L;

void check_trig() {
  long double worst = 0;
  auto one = [&](int32_t mdeg) {
    const SinCos sc = sin_cos_mdeg(mdeg);
    const long double a = (long double)mdeg * kPi / 180000.0L;
    const long double es = std::fabs(sc.sin - std::sin(a) * kTrigOne);
    const long double ec = std::fabs(sc.cos - std::cos(a) * kTrigOne);
    worst = std::max(worst, std::max(es, ec));
  };
  for (int32_t m = 0; m <= 45000; ++m) one(m);
  std::mt19937_64 rng(7);
  for (int k = 0; k < 200000; ++k) one(int32_t(rng() % 4000001) - 2000000);
  for (int32_t m : {0, 90000, 180000, 270000, 360000, -90000, 45000, 135000}) one(m);
  CHECK_MSG(worst <= 4, "trig error " + std::to_string((double)worst) + " units of 2^-30");
  // Exact values where they are exact.
  CHECK_EQ(sin_cos_mdeg(0).cos, kTrigOne);
  CHECK_EQ(sin_cos_mdeg(90000).sin, kTrigOne);
  CHECK_EQ(sin_cos_mdeg(180000).cos, -kTrigOne);
  CHECK_EQ(sin_cos_mdeg(-90000).sin, -kTrigOne);
}

// The projective depths d D / (D - d) of the points, in world units (perspective only).
void reference_depths(const View& v, const std::vector<Point3>& w, std::vector<long double>* out) {
  const long double az = v.azimuth_mdeg * kPi / 180000.0L, el = v.elevation_mdeg * kPi / 180000.0L;
  for (const Point3& p : w) {
    const long double y1 = p.x * std::sin(az) + p.y * std::cos(az);
    const long double d = p.z * std::sin(el) - y1 * std::cos(el);
    out->push_back(d * v.perspective / (v.perspective - d));
  }
}

// The reference fit: the README's convention in long double, then the same uniform fit.
std::vector<Point3> reference(const View& v, const std::vector<Point3>& w,
                              std::vector<long double>* exact) {
  const long double az = v.azimuth_mdeg * kPi / 180000.0L, el = v.elevation_mdeg * kPi / 180000.0L;
  struct R {
    long double x, y, d;
  };
  std::vector<R> r;
  for (const Point3& p : w) {
    const long double xs = p.x * std::cos(az) - p.y * std::sin(az);
    const long double y1 = p.x * std::sin(az) + p.y * std::cos(az);
    long double x = xs, y = p.z * std::cos(el) + y1 * std::sin(el);
    long double d = p.z * std::sin(el) - y1 * std::cos(el);
    if (v.perspective > 0) {  // the README's perspective: scale by D / (D - d), depth too
      const long double k = v.perspective / (v.perspective - d);
      x *= k, y *= k, d *= k;
    }
    r.push_back({x, y, d});
  }
  long double xl = 1e30L, xh = -1e30L, yl = 1e30L, yh = -1e30L, dl = 1e30L, dh = -1e30L;
  for (const R& q : r) {
    xl = std::min(xl, q.x), xh = std::max(xh, q.x), yl = std::min(yl, q.y), yh = std::max(yh, q.y);
    dl = std::min(dl, q.d), dh = std::max(dh, q.d);
  }
  const long double scale = std::min(v.width / (xh - xl), v.height / (yh - yl));
  std::vector<Point3> out;
  for (const R& q : r) {
    const long double x = v.margin + (q.x - xl) * scale, y = v.margin + (q.y - yl) * scale;
    const long double d = (q.d - dl) / (dh - dl) * kCoordMax;
    exact->insert(exact->end(), {x, y, d});
    out.push_back(
        Point3{int32_t(std::lround(x)), int32_t(std::lround(y)), int32_t(std::lround(d))});
  }
  return out;
}

// Projects w with the core and returns the largest distance of a coordinate from the
// long-double projection (depth included when with_depth); every output must be in range.
long double depth_slack(const View& v, const std::vector<Point3>& w) {
  if (v.perspective == 0) return 0;
  std::vector<long double> exact;
  reference_depths(v, w, &exact);
  const auto [lo, hi] = std::minmax_element(exact.begin(), exact.end());
  return *hi > *lo ? kCoordMax / ((*hi - *lo) * 65536.0L) : 0;
}

long double worst_error(const View& v, const std::vector<Point3>& w, bool with_depth) {
  std::vector<Point3> got(w.size());
  CHECK(ok(project_points(v, w.data(), uint32_t(w.size()), got.data())));
  std::vector<long double> exact;
  reference(v, w, &exact);
  long double worst = 0;
  for (size_t i = 0; i < w.size(); ++i) {
    worst = std::max(worst, std::fabs(got[i].x - exact[3 * i]));
    worst = std::max(worst, std::fabs(got[i].y - exact[3 * i + 1]));
    // Under perspective the depth is divided to Q16 world units like x and y, and the depth
    // fit then magnifies that rounding (2^-17 unit, on the point and on the range's low end)
    // by its steps per unit: 1/2 + 2^-9 + 2^-16 * kCoordMax / (depth range in units).
    if (with_depth)
      worst = std::max(worst, std::fabs(got[i].z - exact[3 * i + 2]) - depth_slack(v, w));
    CHECK(in_range(got[i].x) && in_range(got[i].y) && in_range(got[i].z));
  }
  return worst;
}

void check_projection() {
  std::mt19937_64 rng(11);
  long double worst = 0;
  int scenes = 0;
  for (int k = 0; k < 400; ++k) {
    View v;
    v.azimuth_mdeg = int32_t(rng() % 720001) - 360000;
    v.elevation_mdeg = int32_t(rng() % 180001) - 90000;
    if (k % 2) v.perspective = int32_t(3 * kWorldLimit / 2 + rng() % 1000);  // beyond every point
    // World extents from tiny to the full 2^20: the fit magnifies small worlds the most.
    const int32_t extent = int32_t(1) << (8 + rng() % 13);
    std::vector<Point3> w;
    for (int i = 0; i < 50; ++i) {
      auto c = [&] { return int32_t(rng() % (2 * uint64_t(extent) + 1)) - extent; };
      w.push_back(Point3{c(), c(), c()});
    }
    worst = std::max(worst, worst_error(v, w, true));
    ++scenes;
  }
  CHECK_MSG(worst <= 0.5L + 1.0L / 512, "projection error " + std::to_string((double)worst));
  std::printf("projection: %d scenes, worst error %.6f steps\n", scenes, (double)worst);
  // In place: out may alias world.
  View v;
  std::vector<Point3> w = {{0, 0, 0}, {100, 0, 0}, {0, 100, 0}, {0, 0, 100}}, copy(4);
  CHECK(ok(project_points(v, w.data(), 4, copy.data())));
  CHECK(ok(project_points(v, w.data(), 4, w.data())));
  for (int i = 0; i < 4; ++i)
    CHECK(w[i].x == copy[i].x && w[i].y == copy[i].y && w[i].z == copy[i].z);
}

// Perspective near the eye plane: with azimuth and elevation 0 the depth is exactly -y, so
// the eye plane is exact. Points down to 1 world unit from it (a magnification of D) land
// within the same bound of the long-double projection; on or behind it they are refused.
void check_near_eye_plane() {
  View v;
  v.azimuth_mdeg = 0;
  v.elevation_mdeg = 0;
  long double worst = 0;
  for (int32_t eye : {1000, 65536, 1 << 20}) {
    v.perspective = eye;
    for (int32_t gap : {1, 2, 3, 7, 100}) {
      std::vector<Point3> w = {{0, 0, 0},
                               {5000, 0, 3000},
                               {-7000, 2000, -1000},
                               {300, -(eye - gap), 200},
                               {-300, -(eye - gap - 1), -250},
                               {kWorldLimit, kWorldLimit, kWorldLimit}};
      worst = std::max(worst, worst_error(v, w, false));
    }
    // On the eye plane, and behind it: refused by name, nothing written.
    for (int32_t y : {-eye, -eye - 1, -(kWorldLimit)}) {
      if (y > -eye) continue;
      Point3 p[2] = {{0, 0, 0}, {10, y, 10}}, out[2] = {{7, 7, 7}, {7, 7, 7}};
      CHECK(project_points(v, p, 2, out) == Status::kCoordinateOutOfRange);
      CHECK(out[0].x == 7);
    }
  }
  CHECK_MSG(worst <= 0.5L + 1.0L / 512, "near-eye error " + std::to_string((double)worst));
  std::printf("near the eye plane: worst error %.6f steps\n", (double)worst);
}

void check_errors() {
  View v;
  Point3 p[2] = {{0, 0, 0}, {kWorldLimit + 1, 0, 0}};
  CHECK(project_points(v, p, 2, p) == Status::kCoordinateOutOfRange);
  View bad;
  bad.width = kCoordMax;
  CHECK(project_points(bad, p, 1, p) == Status::kBadParameter);
  const uint32_t pairs[4] = {0, 1, 1, 2};
  Edge3 e[2];
  CHECK(edges_from_indices(p, 2, pairs, 2, e) == Status::kBadParameter);
  CHECK(ok(edges_from_indices(p, 2, pairs, 1, e)));
  CHECK(e[0].b.x == p[1].x);
  // One point, and a scene seen exactly edge-on, land on the margin, never divide by zero.
  Point3 one{5, 5, 5};
  CHECK(ok(project_points(v, &one, 1, &one)));
  CHECK(one.x == v.margin && one.y == v.margin);
}

}  // namespace

// view/facing.h: each triangle's facing from its world normal, against long double (the exact
// sine and cosine; where the long-double dot product is within its own error of zero the
// case is skipped), orthographic and in perspective; and against the sign of the projected
// area on triangles large enough that rounding their corners cannot flip it.
void check_model_facing() {
  std::mt19937_64 rng(20261202);
  std::uniform_int_distribution<int32_t> coord(-kWorldLimit, kWorldLimit), small(-3000, 3000);
  std::uniform_int_distribution<int32_t> angle(-360000, 360000);
  size_t compared = 0, wrong = 0, projected = 0, projected_wrong = 0;
  for (int round = 0; round < 200; ++round) {
    View v;
    v.azimuth_mdeg = angle(rng);
    v.elevation_mdeg = angle(rng) / 4;
    v.perspective = round % 2 ? 0 : 2 * kWorldLimit - int32_t(rng() % 1000);
    std::vector<Point3> world;
    std::vector<Triangle> tris;
    for (uint32_t t = 0; t < 100; ++t) {
      const Point3 a{coord(rng) / 2, coord(rng) / 2, coord(rng) / 2};
      // Half of them thin: two corners near a line through the first.
      const bool thin = t % 2 == 0;
      const Point3 b{a.x + coord(rng) / 2, a.y + coord(rng) / 2, a.z + coord(rng) / 2};
      const Point3 c =
          thin ? Point3{a.x + (b.x - a.x) / 2 + small(rng), a.y + (b.y - a.y) / 2 + small(rng),
                        a.z + (b.z - a.z) / 2 + small(rng)}
               : Point3{a.x + coord(rng) / 2, a.y + coord(rng) / 2, a.z + coord(rng) / 2};
      world.insert(world.end(), {a, b, c});
      tris.push_back(Triangle{{3 * t, 3 * t + 1, 3 * t + 2}, t});
    }
    std::vector<uint8_t> facing(tris.size());
    CHECK(ok(model_facing(v, world.data(), uint32_t(world.size()), tris.data(),
                          uint32_t(tris.size()), facing.data())));
    const long double pi = 3.14159265358979323846264338327950288L;
    const long double az = v.azimuth_mdeg * pi / 180000, el = v.elevation_mdeg * pi / 180000;
    const long double w[3] = {-std::sin(az) * std::cos(el), -std::cos(az) * std::cos(el),
                              std::sin(el)};
    std::vector<Point3> screen(world.size());
    CHECK(ok(project_points(v, world.data(), uint32_t(world.size()), screen.data())));
    for (size_t t = 0; t < tris.size(); ++t) {
      const Point3 &a = world[3 * t], &b = world[3 * t + 1], &c = world[3 * t + 2];
      const long double u[3] = {(long double)b.x - a.x, (long double)b.y - a.y,
                                (long double)b.z - a.z};
      const long double q[3] = {(long double)c.x - a.x, (long double)c.y - a.y,
                                (long double)c.z - a.z};
      const long double n[3] = {u[1] * q[2] - u[2] * q[1], u[2] * q[0] - u[0] * q[2],
                                u[0] * q[1] - u[1] * q[0]};
      const long double p[3] = {(long double)a.x, (long double)a.y, (long double)a.z};
      long double dot = 0, scale = 0;
      for (int k = 0; k < 3; ++k) {
        const long double to = v.perspective > 0 ? v.perspective * w[k] - p[k] : w[k];
        dot += n[k] * to;
        scale += std::fabs(n[k]) * (v.perspective > 0 ? 4.0L * kWorldLimit : 1.0L);
      }
      // The core rounds w to Q2.30: a relative 2^-29 of the terms, and long double's own 2^-60.
      if (std::fabs(dot) > scale * std::ldexp(1.0L, -28)) {
        ++compared;
        if ((dot > 0) != (facing[t] != 0)) ++wrong;
      }
      const Point3 &sa = screen[3 * t], &sb = screen[3 * t + 1], &sc = screen[3 * t + 2];
      const int64_t area =
          int64_t{sb.x - sa.x} * (sc.y - sa.y) - int64_t{sb.y - sa.y} * (sc.x - sa.x);
      // Rounding each corner by half a step moves the doubled area by at most about the sum of
      // the two edges' lengths in x and y (under 4 x 20,400 steps here): twice that decides.
      if (std::llabs(area) > 8 * 20400) {
        ++projected;
        if ((area > 0) != (facing[t] != 0)) ++projected_wrong;
      }
    }
  }
  std::printf(
      "model facing: %zu decided cases, %zu wrong; %zu against the projected area, %zu "
      "differ\n",
      compared, wrong, projected, projected_wrong);
  CHECK(compared > 15000 && wrong == 0);
  CHECK(projected > 5000 && projected_wrong == 0);
  // A corner outside the world, and an index beyond the vertices, are refused by name.
  View v;
  const Point3 far[3] = {{0, 0, 0}, {kWorldLimit + 1, 0, 0}, {0, 1, 0}};
  const Triangle t{{0, 1, 2}, 0};
  uint8_t f = 0;
  CHECK(model_facing(v, far, 3, &t, 1, &f) == Status::kCoordinateOutOfRange);
  const Triangle beyond{{0, 1, 3}, 0};
  CHECK(model_facing(v, far, 3, &beyond, 1, &f) == Status::kBadParameter);
}

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "near_eye_plane") {  // the stability family alone
    check_near_eye_plane();
    return check::finish("stability_near_eye_plane");
  }
  check_trig();
  check_projection();
  check_near_eye_plane();
  check_errors();
  check_model_facing();
  return check::finish("view");
}
