#include "pipeline/triangulate.h"

namespace haloplot::host {
namespace {

struct P2 {
  int64_t x, y;
};

int64_t orient(const P2& a, const P2& b, const P2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Inside or on the triangle a, b, c (counter-clockwise).
bool in_closed(const P2& a, const P2& b, const P2& c, const P2& p) {
  return orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, a, p) >= 0;
}

}  // namespace

std::vector<Triangle> triangulate(const std::vector<Point3>& world,
                                  const std::vector<std::vector<uint32_t>>& faces,
                                  TriangulateStats* stats) {
  std::vector<Triangle> out;
  TriangulateStats st;
  for (uint32_t f = 0; f < faces.size(); ++f) {
    ++st.polygons;
    std::vector<uint32_t> v;
    for (uint32_t i : faces[f])
      if (v.empty() || v.back() != i) v.push_back(i);
    while (v.size() > 1 && v.front() == v.back()) v.pop_back();
    if (v.size() < 3) {
      ++st.degenerate;
      continue;
    }
    // Newell's normal: each component below n * 2^41 for |coordinates| <= 2^20.
    int64_t nx = 0, ny = 0, nz = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Point3& a = world[v[i]];
      const Point3& b = world[v[(i + 1) % v.size()]];
      nx += int64_t(a.y - b.y) * (a.z + b.z);
      ny += int64_t(a.z - b.z) * (a.x + b.x);
      nz += int64_t(a.x - b.x) * (a.y + b.y);
    }
    const int64_t ax = nx < 0 ? -nx : nx, ay = ny < 0 ? -ny : ny, az = nz < 0 ? -nz : nz;
    // Drop the largest axis; flip so the polygon's winding is counter-clockwise in 2-D.
    std::vector<P2> p(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Point3& w = world[v[i]];
      if (az >= ax && az >= ay)
        p[i] = {w.x, nz >= 0 ? w.y : -int64_t(w.y)};
      else if (ax >= ay)
        p[i] = {w.y, nx >= 0 ? w.z : -int64_t(w.z)};
      else
        p[i] = {w.z, ny >= 0 ? w.x : -int64_t(w.x)};
    }
    std::vector<std::size_t> ring(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) ring[i] = i;
    bool convex = true;
    for (std::size_t i = 0; i < v.size(); ++i)
      if (orient(p[i], p[(i + 1) % v.size()], p[(i + 2) % v.size()]) < 0) convex = false;
    if (!convex) ++st.concave;
    bool stuck = false;
    while (ring.size() > 3 && !convex) {
      bool cut = false;
      for (std::size_t k = 0; k < ring.size() && !cut; ++k) {
        const std::size_t a = ring[(k + ring.size() - 1) % ring.size()], b = ring[k],
                          c = ring[(k + 1) % ring.size()];
        if (orient(p[a], p[b], p[c]) <= 0) continue;  // reflex or flat: not an ear
        bool empty = true;
        for (std::size_t m : ring)
          if (m != a && m != b && m != c && in_closed(p[a], p[b], p[c], p[m])) empty = false;
        if (!empty) continue;
        out.push_back(Triangle{{v[a], v[b], v[c]}, f});
        ring.erase(ring.begin() + long(k));
        cut = true;
      }
      if (!cut) {
        stuck = true;
        break;
      }
    }
    if (stuck) ++st.not_simple;
    // What is left (the whole polygon when convex) as a fan from its first corner.
    for (std::size_t k = 1; k + 1 < ring.size(); ++k)
      out.push_back(Triangle{{v[ring[0]], v[ring[k]], v[ring[k + 1]]}, f});
  }
  st.triangles = uint32_t(out.size());
  if (stats != nullptr) *stats = st;
  return out;
}

}  // namespace haloplot::host
