// Independent reference for the curve stages (core/curve/): each projected cubic (or segment)
// evaluated in long double, crossings found by dense sampling of the chords and refined by
// Newton's method on the curves themselves, with their depths and angles there. Shares no code
// with core/curve/ (the BezierEdge3 and Edge3 structs only). Used by the `curves` and
// `curve_draw` tests.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "demo/curve_scenes.h"
#include "haloplot/curve/bezier.h"  // the BezierEdge3 struct only

namespace curve_reference {

using haloplot::BezierEdge3;
using haloplot::Edge3;
using haloplot::Point3;
using haloplot::host::CurveScene;
using LD = long double;

struct RefCurve {
  LD p[4][3];
  bool straight = false;
};

struct LP {
  LD x, y, z;
};

inline RefCurve ref_of(const BezierEdge3& e) {
  RefCurve r;
  for (int i = 0; i < 4; ++i) r.p[i][0] = e.p[i].x, r.p[i][1] = e.p[i].y, r.p[i][2] = e.p[i].z;
  return r;
}
inline RefCurve ref_of(const Edge3& e) {
  RefCurve r;
  const Point3 q[4] = {e.a, e.a, e.b, e.b};
  for (int i = 0; i < 4; ++i) r.p[i][0] = q[i].x, r.p[i][1] = q[i].y, r.p[i][2] = q[i].z;
  r.straight = true;
  return r;
}

inline LP eval(const RefCurve& c, LD t) {
  LD w[4];
  if (c.straight) {
    w[0] = 1 - t, w[1] = 0, w[2] = 0, w[3] = t;
  } else {
    const LD s = 1 - t;
    w[0] = s * s * s, w[1] = 3 * s * s * t, w[2] = 3 * s * t * t, w[3] = t * t * t;
  }
  LP out{0, 0, 0};
  for (int i = 0; i < 4; ++i) {
    out.x += w[i] * c.p[i][0];
    out.y += w[i] * c.p[i][1];
    out.z += w[i] * c.p[i][2];
  }
  return out;
}
inline LP deriv(const RefCurve& c, LD t) {
  if (c.straight) return LP{c.p[3][0] - c.p[0][0], c.p[3][1] - c.p[0][1], 0};
  const LD s = 1 - t;
  const LD w[3] = {3 * s * s, 6 * s * t, 3 * t * t};
  LP out{0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    out.x += w[i] * (c.p[i + 1][0] - c.p[i][0]);
    out.y += w[i] * (c.p[i + 1][1] - c.p[i][1]);
  }
  return out;
}

struct RefCrossing {
  uint32_t i, j;        // i <= j
  LD s, u;              // parameters on i and j
  LD dz;                // depth of i minus depth of j there (units; larger is nearer)
  LD sin_angle;         // |sin| of the angle between the curves there
  int sense;            // sign of cross(tangent of i, tangent of j) there
  bool at_end = false;  // at an end of i or j (kept only when asked for joints)
};

// Newton's method on B_i(s) - B_j(u) = 0 from (s, u); false if it does not converge.
inline bool newton(const RefCurve& a, const RefCurve& b, LD* s, LD* u) {
  for (int k = 0; k < 60; ++k) {
    const LP pa = eval(a, *s), pb = eval(b, *u), da = deriv(a, *s), db = deriv(b, *u);
    const LD fx = pa.x - pb.x, fy = pa.y - pb.y;
    const LD det = da.x * -db.y - da.y * -db.x;
    if (det == 0) return false;
    const LD ds = (fx * -db.y - fy * -db.x) / det, du = (da.x * fy - da.y * fx) / det;
    *s -= ds;
    *u -= du;
    if (std::fabs(ds) < 1e-17L && std::fabs(du) < 1e-17L) break;
  }
  const LP pa = eval(a, *s), pb = eval(b, *u);
  return std::hypot(pa.x - pb.x, pa.y - pb.y) < 1e-9L;
}

// Crossings of curves i <= j by dense sampling (m chords each), refined by Newton.
// With `joints`, a crossing at an edge's end is kept when the two curves are at different
// depths there (a chain passing a joint of another); ends at one 3-D point are a meeting.
inline void ref_pair(const std::vector<RefCurve>& cs, uint32_t i, uint32_t j, int m,
                     std::vector<RefCrossing>* out, bool joints = false) {
  const RefCurve &a = cs[i], &b = cs[j];
  std::vector<LP> pa(m + 1), pb(m + 1);
  for (int k = 0; k <= m; ++k) pa[k] = eval(a, LD(k) / m), pb[k] = eval(b, LD(k) / m);
  const size_t before = out->size();
  for (int k = 0; k < m; ++k) {
    for (int l = (i == j ? k + 2 : 0); l < m; ++l) {
      const LP &p0 = pa[k], &p1 = pa[k + 1], &q0 = pb[l], &q1 = pb[l + 1];
      if (std::max(p0.x, p1.x) < std::min(q0.x, q1.x) ||
          std::max(q0.x, q1.x) < std::min(p0.x, p1.x) ||
          std::max(p0.y, p1.y) < std::min(q0.y, q1.y) ||
          std::max(q0.y, q1.y) < std::min(p0.y, p1.y))
        continue;
      const LD dx = p1.x - p0.x, dy = p1.y - p0.y, ex = q1.x - q0.x, ey = q1.y - q0.y;
      const LD den = dx * ey - dy * ex;
      if (den == 0) continue;
      const LD al = ((q0.x - p0.x) * ey - (q0.y - p0.y) * ex) / den;
      const LD be = ((q0.x - p0.x) * dy - (q0.y - p0.y) * dx) / den;
      // A little past the chords' ends: a chord is off its curve by the curve's flatness, so a
      // crossing near a chord's end (an edge's end among them) may show on the neighbouring chord
      // only.
      if (al < -0.01L || al > 1.01L || be < -0.01L || be > 1.01L) continue;
      LD s = (k + al) / m, u = (l + be) / m;
      if (!newton(a, b, &s, &u)) continue;
      const auto outside = [](LD v) { return v < -1e-9L || v > 1 + 1e-9L; };
      const auto end = [](LD v) { return v <= 1e-9L || v >= 1 - 1e-9L; };
      if (outside(s) || outside(u)) continue;
      const bool at_end = end(s) || end(u);
      if (at_end && !(joints && std::fabs(eval(a, s).z - eval(b, u).z) > 1e-6L)) continue;
      if (i == j && std::fabs(s - u) < 1e-6L) continue;
      if (i == j && u < s) std::swap(s, u);
      bool seen = false;
      for (size_t n = before; n < out->size(); ++n)
        if (std::fabs((*out)[n].s - s) < 1e-9L && std::fabs((*out)[n].u - u) < 1e-9L) seen = true;
      const LP da = deriv(a, s), db = deriv(b, u);
      const LD cr = da.x * db.y - da.y * db.x;
      const LD sin_angle = std::fabs(cr) / (std::hypot(da.x, da.y) * std::hypot(db.x, db.y));
      if (!seen)
        out->push_back(RefCrossing{i, j, s, u, eval(a, s).z - eval(b, u).z, sin_angle,
                                   cr > 0 ? 1 : -1, at_end});
    }
  }
}

// With `joints`, crossings at edge ends too: one per projected point (the edges on either
// side of a joint all see it).
inline std::vector<RefCrossing> reference(const CurveScene& scene, int m, bool joints = false) {
  std::vector<RefCurve> cs;
  for (const auto& c : scene.curves) cs.push_back(ref_of(c));
  for (const auto& s : scene.segments) cs.push_back(ref_of(s));
  std::vector<RefCrossing> all;
  for (uint32_t i = 0; i < cs.size(); ++i)
    for (uint32_t j = i; j < cs.size(); ++j)
      if (!(cs[i].straight && cs[j].straight) && !(i == j && cs[i].straight))
        ref_pair(cs, i, j, m, &all, joints);
  std::vector<RefCrossing> out;
  for (const RefCrossing& r : all) {
    bool seen = false;
    const LP p = eval(cs[r.i], r.s);
    for (const RefCrossing& o : out) {
      const LP q = eval(cs[o.i], o.s);
      if (r.at_end && o.at_end && std::hypot(p.x - q.x, p.y - q.y) < 1e-6L) seen = true;
    }
    if (!seen) out.push_back(r);
  }
  return out;
}

}  // namespace curve_reference
