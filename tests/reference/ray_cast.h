// Independent reference for hidden lines: the true 3-D scene, ray cast from the eye in long
// double. It starts from the world vertices (integers, before the view's rounding), turns them
// with the view's rotation in double precision, and decides a point of an edge hidden exactly when
// the open segment from it to the eye (orthographic: the ray towards the viewer) passes
// through the inside of a triangle. It shares no code with core/: the camera is written here
// from the formulas in core/include/haloplot/view/projection.h's header comment, and nothing is
// rounded to steps. Host-only.
//
// Visible length: an edge is sampled at every half step of its exact screen image (screen
// parameter s, mapped to the world segment by the projective inverse, so the samples are
// uniform on paper under perspective too), and each change of visibility between two samples
// is located by bisection to 2^-40 of the edge. An occluder narrower than half a step that
// falls between two samples is missed: the error that leaves is under half a step per gap.
//
// Faces that contain both ends of the edge (by vertex id) are the edge's own and are skipped;
// any other face counts, also one that touches the edge at a vertex or lies along it without
// sharing its ids (it blocks only where the segment to the eye passes through its inside).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <vector>

#include "haloplot/geometry/contract.h"  // Point3
#include "haloplot/solid/mesh.h"         // Triangle (vertex ids)
#include "haloplot/view/projection.h"    // View (the parameters only)

namespace ray_cast {

using LD = double;  // double precision: the reference the issue names, and fast enough to cast per
                    // half step
constexpr LD kPi = 3.14159265358979323846;

struct V3 {
  LD x, y, d;  // view space: x right, y up on paper, d towards the eye
};

inline V3 sub(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.d - b.d}; }
inline V3 cross(V3 a, V3 b) {
  return {a.y * b.d - a.d * b.y, a.d * b.x - a.x * b.d, a.x * b.y - a.y * b.x};
}
inline LD dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.d * b.d; }

// The view as exact real arithmetic: rotation, perspective D / (D - d), then the uniform fit of
// the screen bounds of all the scene's vertices into the plot area (the core's fit).
struct Camera {
  haloplot::View view;
  LD D = 0;  // 0: orthographic
  LD xl = 0, yl = 0, scale = 1;
  bool identity = false;  // the points are already on paper: (x, y, depth) in steps

  V3 rotate(const haloplot::Point3& p) const {
    if (identity) return {LD(p.x), LD(p.y), LD(p.z)};
    const LD az = view.azimuth_mdeg * kPi / 180000.0, el = view.elevation_mdeg * kPi / 180000.0;
    const LD xs = p.x * std::cos(az) - p.y * std::sin(az);
    const LD y1 = p.x * std::sin(az) + p.y * std::cos(az);
    return {xs, p.z * std::cos(el) + y1 * std::sin(el), p.z * std::sin(el) - y1 * std::cos(el)};
  }
  LD magnify(const V3& p) const { return D > 0 ? D / (D - p.d) : 1.0; }
  void screen(const V3& p, LD* sx, LD* sy) const {
    const LD k = magnify(p);
    *sx = view.margin + (p.x * k - xl) * scale;
    *sy = view.margin + (p.y * k - yl) * scale;
  }
};

inline Camera camera(const haloplot::View& v, const std::vector<haloplot::Point3>& world) {
  Camera c;
  c.view = v;
  c.D = v.perspective;
  LD xl = 1e30, xh = -1e30, yl = 1e30, yh = -1e30;
  for (const haloplot::Point3& w : world) {
    const V3 p = c.rotate(w);
    const LD k = c.magnify(p);
    xl = std::min(xl, p.x * k), xh = std::max(xh, p.x * k);
    yl = std::min(yl, p.y * k), yh = std::max(yh, p.y * k);
  }
  c.xl = xl, c.yl = yl;
  c.scale = std::min(v.width / (xh - xl), v.height / (yh - yl));
  return c;
}

// The camera for points already projected by the core (x, y in steps, the projective depth):
// ray casting them orthographically decides the visibility of the rounded scene exactly as
// the core sees it, so the two references split a difference into the core's own error and
// what rounding the vertices to steps changed.
// substep_bits: the points are in units of 2^-s steps (View::substep_bits); lengths come out in
// steps.
inline Camera on_paper(int substep_bits = 0) {
  Camera c;
  c.identity = true;
  c.view.margin = 0;
  c.scale = std::ldexp(1.0, -substep_bits);
  return c;
}

class Scene {
 public:
  Scene(const Camera& cam, const std::vector<haloplot::Point3>& world,
        const std::vector<haloplot::Triangle>& triangles)
      : cam_(cam), tris_(triangles) {
    vp_.reserve(world.size());
    sx_.reserve(world.size());
    sy_.reserve(world.size());
    for (const haloplot::Point3& w : world) {
      vp_.push_back(cam.rotate(w));
      LD x, y;
      cam.screen(vp_.back(), &x, &y);
      sx_.push_back(x), sy_.push_back(y);
    }
    find_diagonals();
    build_grid();
  }

  // Is the point p (view space) hidden by a face other than those holding vertices a and b?
  bool hidden(const V3& p, uint32_t a, uint32_t b) const {
    return hidden_but(p, [&](uint32_t, const haloplot::Triangle& t) {
      const bool has_a = t.v[0] == a || t.v[1] == a || t.v[2] == a;
      const bool has_b = t.v[0] == b || t.v[1] == b || t.v[2] == b;
      return has_a && has_b;
    });
  }

  // Is p hidden by a face that own(index, triangle) does not claim?
  template <typename Own>
  bool hidden_but(const V3& p, Own own) const {
    LD x, y;
    cam_.screen(p, &x, &y);
    const int64_t cx = cell_x(x), cy = cell_y(y);
    if (cx < 0 || cy < 0 || cx >= gx_ || cy >= gy_) return false;
    const size_t c = size_t(cy * gx_ + cx);
    for (size_t k = start_[c]; k < start_[c + 1]; ++k) {
      const haloplot::Triangle& t = tris_[items_[k]];
      if (own(items_[k], t)) continue;
      if (blocks(t, p)) return true;
    }
    return false;
  }

  // The visible length, in plot steps on the exact screen image, of the segment between
  // vertices a and b; *length gets the image's whole length, *changes how often visibility
  // changed between samples (many: the edge runs along a face's side on paper, where a cast
  // ray grazes and the answer flickers).
  LD visible_length(uint32_t a, uint32_t b, LD* length = nullptr,
                    int64_t* changes = nullptr) const {
    return segment_visible_length(
        vp_[a], vp_[b],
        [&](uint32_t, const haloplot::Triangle& t) {
          const bool has_a = t.v[0] == a || t.v[1] == a || t.v[2] == a;
          const bool has_b = t.v[0] == b || t.v[1] == b || t.v[2] == b;
          return has_a && has_b;
        },
        length, changes);
  }

  // The same for any segment A B of view space (an intersection line), faces own() claims
  // left out.
  template <typename Own>
  LD segment_visible_length(const V3& A, const V3& B, Own own, LD* length = nullptr,
                            int64_t* changes = nullptr) const {
    LD ax, ay, bx, by;
    cam_.screen(A, &ax, &ay);
    cam_.screen(B, &bx, &by);
    const LD L = std::hypot(bx - ax, by - ay);
    if (length) *length = L;
    // Screen parameter s to the world point: under perspective the homogeneous weights
    // h = D - d make s = u hB / ((1 - u) hA + u hB), so u = s hA / (s hA + (1 - s) hB).
    const LD hA = cam_.D > 0 ? cam_.D - A.d : 1.0, hB = cam_.D > 0 ? cam_.D - B.d : 1.0;
    auto at = [&](LD s) {
      const LD u = s * hA / (s * hA + (1 - s) * hB);
      return V3{A.x + u * (B.x - A.x), A.y + u * (B.y - A.y), A.d + u * (B.d - A.d)};
    };
    auto visible = [&](LD s) { return !hidden_but(at(s), own); };
    // Samples at the middles of n equal parts; the ends take the visibility of the nearest.
    const int64_t n = std::max<int64_t>(4, int64_t(std::ceil(L / 0.5)));
    auto sample = [&](int64_t i) { return (LD(i) + 0.5) / LD(n); };
    bool prev = visible(sample(0));
    if (changes) *changes = 0;
    LD seen = 0, run_start = 0;
    for (int64_t i = 1; i < n; ++i) {
      const bool v = visible(sample(i));
      if (v == prev) continue;
      LD lo = sample(i - 1), hi = sample(i);  // visible(lo) == prev, visible(hi) == v
      for (int k = 0; k < 40; ++k) {
        const LD mid = (lo + hi) / 2;
        (visible(mid) == prev ? lo : hi) = mid;
      }
      if (changes) ++*changes;
      if (prev) seen += (lo + hi) / 2 - run_start;
      run_start = (lo + hi) / 2;
      prev = v;
    }
    if (prev) seen += 1.0 - run_start;
    return seen * L;
  }

  const V3& vertex(uint32_t i) const { return vp_[i]; }
  // Vertex i on the exact screen, in steps.
  void screen_of(uint32_t i, LD* x, LD* y) const { *x = sx_[i], *y = sy_[i]; }

 private:
  // Does triangle t cross the open segment from p to the eye (Moller-Trumbore)? Points of the
  // triangle nearer p than 1e-9 of the way (perspective) or of 1e-9 of the depth range
  // (orthographic) do not count: p lies on its own faces.
  bool blocks(const haloplot::Triangle& t, const V3& p) const {
    const V3 A = vp_[t.v[0]], B = vp_[t.v[1]], C = vp_[t.v[2]];
    const V3 dir = cam_.D > 0 ? V3{-p.x, -p.y, cam_.D - p.d} : V3{0, 0, 1};
    const V3 e1 = sub(B, A), e2 = sub(C, A);
    const V3 pv = cross(dir, e2);
    const LD det = dot(e1, pv);
    if (det == 0) return false;  // the segment runs in the triangle's plane: it grazes
    const LD inv = 1 / det;
    const V3 tv = sub(p, A);
    const LD u = dot(tv, pv) * inv;
    const V3 qv = cross(tv, e1);
    const LD v = dot(dir, qv) * inv;
    // Inside, or on a side shared with another triangle of the same polygon: the polygon's
    // inside includes its diagonals, and a ray along one (a symmetric scene makes them) must
    // not slip between the two halves. Bit k of the mask: the side opposite vertex k.
    const uint8_t diag = diagonal_[size_t(&t - tris_.data())];
    auto inside = [&](LD w, int k) { return w > 0 || ((diag >> k) & 1 && w > -1e-9); };
    if (!(inside(1 - u - v, 0) && inside(u, 1) && inside(v, 2))) return false;
    const LD s = dot(e2, qv) * inv;
    return cam_.D > 0 ? (s > 1e-9 && s < 1) : s > 1e-9 * depth_range_;
  }

  // The sides each triangle shares with another triangle of its polygon.
  void find_diagonals() {
    std::vector<std::tuple<uint32_t, uint32_t, uint32_t, uint32_t>> sides;  // lo, hi, polygon, 3t+k
    for (uint32_t i = 0; i < tris_.size(); ++i)
      for (uint32_t k = 0; k < 3; ++k) {
        const uint32_t a = tris_[i].v[(k + 1) % 3], b = tris_[i].v[(k + 2) % 3];
        sides.emplace_back(std::min(a, b), std::max(a, b), tris_[i].polygon, 3 * i + k);
      }
    std::sort(sides.begin(), sides.end());
    diagonal_.assign(tris_.size(), 0);
    for (size_t i = 0; i + 1 < sides.size(); ++i) {
      const auto &x = sides[i], &y = sides[i + 1];
      if (std::get<0>(x) != std::get<0>(y) || std::get<1>(x) != std::get<1>(y) ||
          std::get<2>(x) != std::get<2>(y))
        continue;
      for (uint32_t id : {std::get<3>(x), std::get<3>(y)})
        diagonal_[id / 3] = uint8_t(diagonal_[id / 3] | (1u << (id % 3)));
    }
  }

  int64_t cell_x(LD x) const { return int64_t(std::floor((x - x0_) / cell_)); }
  int64_t cell_y(LD y) const { return int64_t(std::floor((y - y0_) / cell_)); }

  // A uniform screen grid of the triangles' bounding boxes: a face that hides a point covers
  // the point's screen position.
  void build_grid() {
    LD xl = 1e30, xh = -1e30, yl = 1e30, yh = -1e30, dl = 1e30, dh = -1e30, sum = 0;
    for (size_t i = 0; i < sx_.size(); ++i) {
      xl = std::min(xl, sx_[i]), xh = std::max(xh, sx_[i]);
      yl = std::min(yl, sy_[i]), yh = std::max(yh, sy_[i]);
      dl = std::min(dl, vp_[i].d), dh = std::max(dh, vp_[i].d);
    }
    depth_range_ = std::max<LD>(dh - dl, 1);
    for (const haloplot::Triangle& t : tris_) {
      LD bx0, bx1, by0, by1;
      box(t, &bx0, &bx1, &by0, &by1);
      sum += std::max(bx1 - bx0, by1 - by0);
    }
    cell_ = std::max<LD>(4, tris_.empty() ? 1 : sum / LD(tris_.size()));
    x0_ = xl - 1, y0_ = yl - 1;
    gx_ = int64_t((xh - x0_) / cell_) + 2, gy_ = int64_t((yh - y0_) / cell_) + 2;
    start_.assign(size_t(gx_ * gy_) + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
      for (size_t i = 0; i < tris_.size(); ++i) {
        LD bx0, bx1, by0, by1;
        box(tris_[i], &bx0, &bx1, &by0, &by1);
        for (int64_t cy = cell_y(by0); cy <= cell_y(by1); ++cy)
          for (int64_t cx = cell_x(bx0); cx <= cell_x(bx1); ++cx) {
            const size_t c = size_t(cy * gx_ + cx);
            if (pass == 0)
              ++start_[c + 1];
            else
              items_[fill_[c]++] = uint32_t(i);
          }
      }
      if (pass == 0) {
        for (size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
        items_.resize(start_.back());
        fill_.assign(start_.begin(), start_.end() - 1);
      }
    }
  }
  void box(const haloplot::Triangle& t, LD* x0, LD* x1, LD* y0, LD* y1) const {
    *x0 = std::min({sx_[t.v[0]], sx_[t.v[1]], sx_[t.v[2]]}) - 0.01;
    *x1 = std::max({sx_[t.v[0]], sx_[t.v[1]], sx_[t.v[2]]}) + 0.01;
    *y0 = std::min({sy_[t.v[0]], sy_[t.v[1]], sy_[t.v[2]]}) - 0.01;
    *y1 = std::max({sy_[t.v[0]], sy_[t.v[1]], sy_[t.v[2]]}) + 0.01;
  }

  Camera cam_;
  std::vector<haloplot::Triangle> tris_;
  std::vector<uint8_t> diagonal_;
  std::vector<V3> vp_;
  std::vector<LD> sx_, sy_;
  LD x0_ = 0, y0_ = 0, cell_ = 1, depth_range_ = 1;
  int64_t gx_ = 0, gy_ = 0;
  std::vector<size_t> start_, fill_;
  std::vector<uint32_t> items_;
};

}  // namespace ray_cast
