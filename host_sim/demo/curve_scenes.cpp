#include "demo/curve_scenes.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace haloplot::host {

namespace {

struct V3 {
  double x, y, z;
};
V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
V3 operator*(double k, V3 a) { return {k * a.x, k * a.y, k * a.z}; }

using Fn = std::function<V3(double)>;

// The view's rotation: about x by tilt, then about y by turn; (x, y) on paper, z the depth.
V3 rotate(V3 p, const CurveView& v) {
  const double c = std::cos(v.tilt), s = std::sin(v.tilt);
  const V3 a{p.x, c * p.y - s * p.z, s * p.y + c * p.z};
  const double c2 = std::cos(v.turn), s2 = std::sin(v.turn);
  return {c2 * a.x + s2 * a.z, a.y, -s2 * a.x + c2 * a.z};
}

// Hermite control points of `edges` equal steps of f over [t0, t1], in 3-D, rotated.
std::vector<V3> fit(const Fn& f, const Fn& df, double t0, double t1, int edges, bool closed,
                    const CurveView& view) {
  const double h = (t1 - t0) / edges;
  std::vector<V3> cp;
  for (int i = 0; i < edges; ++i) {
    const double a = t0 + i * h, b = (closed && i + 1 == edges) ? t0 : a + h;
    cp.push_back(rotate(f(a), view));
    cp.push_back(rotate(f(a) + (h / 3) * df(a), view));
    cp.push_back(rotate(f(b) + (-h / 3) * df(b), view));
    cp.push_back(rotate(f(b), view));
  }
  return cp;
}

// ---- perspective ----

// The rotated curve's centre and the factor that makes its largest extent 2^19 world units.
struct World {
  V3 centre;
  double scale;
};
World world_of(const Fn& f, double t0, double t1, const CurveView& view) {
  V3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (int i = 0; i <= 4096; ++i) {
    const V3 p = rotate(f(t0 + (t1 - t0) * i / 4096), view);
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  return World{0.5 * (lo + hi), double(1 << 19) / extent};
}

// The curve seen from the eye at (0, 0, D) (world units, about the centre): (x, y) scaled by
// D / (D - z), z kept as the depth (along a ray through the eye, larger z is nearer).
struct Perspective {
  World w;
  double d;
  V3 at(const Fn& f, double t, const CurveView& v) const {
    const V3 p = w.scale * (rotate(f(t), v) + (-1.0) * w.centre);
    const double k = d / (d - p.z);
    return V3{k * p.x, k * p.y, p.z};
  }
  V3 deriv(const Fn& f, const Fn& df, double t, const CurveView& v) const {
    const V3 p = w.scale * (rotate(f(t), v) + (-1.0) * w.centre), dp = w.scale * rotate(df(t), v);
    const double k = d / (d - p.z), dk = d * dp.z / ((d - p.z) * (d - p.z));
    return V3{k * dp.x + dk * p.x, k * dp.y + dk * p.y, dp.z};
  }
};

V3 hermite(const V3 c[4], double s) {
  const double u = 1 - s, w[4] = {u * u * u, 3 * u * u * s, 3 * u * s * s, s * s * s};
  return V3{w[0] * c[0].x + w[1] * c[1].x + w[2] * c[2].x + w[3] * c[3].x,
            w[0] * c[0].y + w[1] * c[1].y + w[2] * c[2].y + w[3] * c[3].y,
            w[0] * c[0].z + w[1] * c[1].z + w[2] * c[2].z + w[3] * c[3].z};
}

// The perspective image of f over `edges` equal steps, each step's Hermite cubic halved until
// it is within tol (in the image's units) of the image at 64 points, in x and y; the depth is
// fitted alongside.
std::vector<V3> fit_perspective(const Fn& f, const Fn& df, double t0, double t1, int edges,
                                bool closed, const CurveView& view, const Perspective& pv,
                                double tol) {
  std::vector<V3> cp;
  const std::function<void(double, double, int)> step = [&](double a, double b, int depth) {
    const V3 pa = pv.at(f, a, view), pb = pv.at(f, b, view);
    const double h = b - a;
    const V3 c[4] = {pa, pa + (h / 3) * pv.deriv(f, df, a, view),
                     pb + (-h / 3) * pv.deriv(f, df, b, view), pb};
    double err = 0;
    for (int i = 1; i < 64; ++i) {
      const V3 q = hermite(c, i / 64.0), g = pv.at(f, a + h * i / 64.0, view);
      err = std::max(err, std::hypot(q.x - g.x, q.y - g.y));
    }
    if (err > tol && depth < 12) {
      step(a, a + h / 2, depth + 1);
      step(a + h / 2, b, depth + 1);
      return;
    }
    cp.insert(cp.end(), c, c + 4);
  };
  const double h = (t1 - t0) / edges;
  for (int i = 0; i < edges; ++i) step(t0 + i * h, t0 + (i + 1) * h, 0);
  if (closed && !cp.empty()) cp.back() = cp.front();  // the same point, rounded once
  return cp;
}

// The control points of f over [t0, t1] as the view sees it: the 3-D Hermite fit rotated
// (orthographic), or the perspective image fitted to within kPerspectiveFitSteps of the view's
// scale (the scale from the image's own extent; the control points' is a little larger, so
// the bound holds).
std::vector<V3> view_fit(const Fn& f, const Fn& df, double t0, double t1, int edges, bool closed,
                         const CurveView& view) {
  if (view.perspective <= 0) return fit(f, df, t0, t1, edges, closed, view);
  const Perspective pv{world_of(f, t0, t1, view), view.perspective};
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (int i = 0; i <= 4096; ++i) {
    const V3 p = pv.at(f, t0 + (t1 - t0) * i / 4096, view);
    x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
  }
  const double k = (view.size - 2.0 * view.margin) / std::max(x1 - x0, y1 - y0);
  return fit_perspective(f, df, t0, t1, edges, closed, view, pv, kPerspectiveFitSteps / k);
}

// Scale into the view's square and round; equal 3-D points round to equal integer points, so
// shared ends stay shared.
struct Fit {
  double x0, y0, z0, k, kz;
  int32_t margin;
  Point3 operator()(V3 p) const {
    return Point3{margin + int32_t(std::lround((p.x - x0) * k)),
                  margin + int32_t(std::lround((p.y - y0) * k)),
                  margin + int32_t(std::lround((p.z - z0) * kz))};
  }
};

Fit fit_of(const std::vector<V3>& pts, const CurveView& v) {
  double x0 = 1e300, y0 = 1e300, z0 = 1e300, x1 = -1e300, y1 = -1e300, z1 = -1e300;
  for (const V3& p : pts) {
    x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), z0 = std::min(z0, p.z);
    x1 = std::max(x1, p.x), y1 = std::max(y1, p.y), z1 = std::max(z1, p.z);
  }
  const double span = v.size - 2.0 * v.margin;
  return Fit{x0,      y0, z0, span / std::max(x1 - x0, y1 - y0), span / std::max(z1 - z0, 1e-9),
             v.margin};
}

CurveScene to_scene(const std::vector<V3>& cp, const Fit& fit) {
  CurveScene s;
  for (size_t i = 0; i + 3 < cp.size(); i += 4)
    s.curves.push_back(BezierEdge3{{fit(cp[i]), fit(cp[i + 1]), fit(cp[i + 2]), fit(cp[i + 3])}});
  return s;
}

}  // namespace

CurveScene trefoil_knot(int edges, const CurveView& view) {
  const Fn f = [](double t) {
    return V3{std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t),
              -std::sin(3 * t)};
  };
  const Fn df = [](double t) {
    return V3{std::cos(t) + 4 * std::cos(2 * t), -std::sin(t) + 4 * std::sin(2 * t),
              -3 * std::cos(3 * t)};
  };
  const std::vector<V3> cp = view_fit(f, df, 0, 2 * M_PI, edges, true, view);
  return to_scene(cp, fit_of(cp, view));
}

CurveScene torus_knot(int p, int q, int edges, const CurveView& view) {
  const Fn f = [p, q](double t) {
    const double r = 2 + std::cos(q * t);
    return V3{r * std::cos(p * t), r * std::sin(p * t), -std::sin(q * t)};
  };
  const Fn df = [p, q](double t) {
    const double r = 2 + std::cos(q * t), dr = -q * std::sin(q * t);
    return V3{dr * std::cos(p * t) - r * p * std::sin(p * t),
              dr * std::sin(p * t) + r * p * std::cos(p * t), -q * std::cos(q * t)};
  };
  const std::vector<V3> cp = view_fit(f, df, 0, 2 * M_PI, edges, true, view);
  return to_scene(cp, fit_of(cp, view));
}

CurveScene helix(double turns, double pitch, int edges, bool with_axis, const CurveView& view) {
  const double rise = pitch / (2 * M_PI);
  const Fn f = [rise](double t) { return V3{std::cos(t), std::sin(t), rise * t}; };
  const Fn df = [rise](double t) { return V3{-std::sin(t), std::cos(t), rise}; };
  const double t1 = 2 * M_PI * turns;
  std::vector<V3> cp = fit(f, df, 0, t1, edges, false, view);
  // The axis reaches a little beyond both ends of the helix.
  const V3 a0 = rotate(V3{0, 0, -0.5 * pitch}, view),
           a1 = rotate(f(t1) + V3{0, 0, 0.5 * pitch} + V3{-std::cos(t1), -std::sin(t1), 0}, view);
  std::vector<V3> all = cp;
  if (with_axis) all.insert(all.end(), {a0, a1});
  const Fit fitted = fit_of(all, view);
  CurveScene s = to_scene(cp, fitted);
  if (with_axis) s.segments.push_back(Edge3{fitted(a0), fitted(a1)});
  return s;
}

}  // namespace haloplot::host
