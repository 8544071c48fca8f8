#include "pipeline/triangulate.h"

#include <algorithm>

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

bool same(const P2& a, const P2& b) { return a.x == b.x && a.y == b.y; }

// Do two edges of the boundary cross at a point inside both (not where they touch or overlap,
// as a keyhole bridge's two sides do)? O(n^2) exact orientation tests.
bool crosses_itself(const std::vector<P2>& p) {
  const std::size_t n = p.size();
  auto sign = [](int64_t v) { return (v > 0) - (v < 0); };
  for (std::size_t i = 0; i < n; ++i) {
    const P2 &a = p[i], &b = p[(i + 1) % n];
    for (std::size_t j = i + 2; j < n; ++j) {
      if ((j + 1) % n == i) continue;  // adjacent through the closing edge
      const P2 &c = p[j], &d = p[(j + 1) % n];
      if (sign(orient(a, b, c)) * sign(orient(a, b, d)) < 0 &&
          sign(orient(c, d, a)) * sign(orient(c, d, b)) < 0)
        return true;
    }
  }
  return false;
}

// A loop given twice or more (`f 1 2 3 4 1 2 3 4`, or cut off part way round as in assimp's
// box_longline.obj): the loop once.
void drop_repeated_loop(std::vector<uint32_t>* v) {
  const std::size_t n = v->size();
  for (std::size_t period = 3; period < n; ++period) {
    bool repeats = true;
    for (std::size_t i = period; i < n && repeats; ++i) repeats = (*v)[i] == (*v)[i - period];
    if (repeats) {
      v->resize(period);
      return;
    }
  }
}

// Ear clipping on a weakly simple ring: a boundary may touch itself where a keyhole bridge
// runs to an inner boundary and back, so a corner can stand at the same point twice. A point
// that coincides with a corner of the ear does not block it (it is that corner again), and a
// spike (there and straight back along the bridge) is cut off as it appears. Emits the ears,
// then the last triangle; false when no ear is left (the boundary crosses itself).
bool clip_ears(const std::vector<P2>& p, const std::vector<uint32_t>& v, uint32_t face,
               std::vector<Triangle>* out) {
  std::vector<std::size_t> ring(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) ring[i] = i;
  auto at = [&](std::size_t k) { return ring[k % ring.size()]; };
  while (ring.size() > 3) {
    bool cut = false;
    for (std::size_t k = 0; k < ring.size() && !cut; ++k) {
      const std::size_t a = at(k + ring.size() - 1), b = at(k), c = at(k + 1);
      if (same(p[b], p[c])) {  // the same point twice in a row (a bridge's two ends meeting)
        ring.erase(ring.begin() + long((k + 1) % ring.size()));
        cut = true;
        continue;
      }
      if (same(p[a], p[c])) {  // a spike a -> b -> a: no area, drop b and the second a
        const std::size_t second = (k + 1) % ring.size();
        ring.erase(ring.begin() + long(std::max(k, second)));
        ring.erase(ring.begin() + long(std::min(k, second)));
        cut = true;
        continue;
      }
      if (orient(p[a], p[b], p[c]) <= 0) continue;  // reflex or flat: not an ear
      bool empty = true;
      for (std::size_t m : ring) {
        if (same(p[m], p[a]) || same(p[m], p[b]) || same(p[m], p[c])) continue;
        if (in_closed(p[a], p[b], p[c], p[m])) empty = false;
      }
      if (!empty) continue;
      out->push_back(Triangle{{v[a], v[b], v[c]}, face});
      ring.erase(ring.begin() + long(k));
      cut = true;
    }
    if (!cut) return false;
  }
  if (ring.size() == 3 && orient(p[ring[0]], p[ring[1]], p[ring[2]]) > 0)
    out->push_back(Triangle{{v[ring[0]], v[ring[1]], v[ring[2]]}, face});
  return true;
}

}  // namespace

std::vector<Triangle> triangulate(const std::vector<Point3>& world,
                                  const std::vector<std::vector<uint32_t>>& faces,
                                  const std::vector<uint32_t>& regions, TriangulateStats* stats) {
  std::vector<Triangle> out;
  out.reserve(2 * faces.size());  // a quad mesh's count; more only grows it
  TriangulateStats st;
  // Each face's corners and their 2-D points, kept across faces (no allocation per face).
  std::vector<uint32_t> v;
  std::vector<P2> p, sorted;
  for (uint32_t f = 0; f < faces.size(); ++f) {
    ++st.polygons;
    v.clear();
    for (uint32_t i : faces[f])
      if (v.empty() || v.back() != i) v.push_back(i);
    while (v.size() > 1 && v.front() == v.back()) v.pop_back();
    drop_repeated_loop(&v);
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
    if (ax == 0 && ay == 0 && az == 0) {  // no area: all corners on one line
      ++st.degenerate;
      continue;
    }
    // Drop the largest axis; flip so the polygon's winding is counter-clockwise in 2-D.
    p.resize(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Point3& w = world[v[i]];
      if (az >= ax && az >= ay)
        p[i] = {w.x, nz >= 0 ? w.y : -int64_t(w.y)};
      else if (ax >= ay)
        p[i] = {w.y, nx >= 0 ? w.z : -int64_t(w.z)};
      else
        p[i] = {w.z, ny >= 0 ? w.x : -int64_t(w.x)};
    }
    if (v.size() > 3 && crosses_itself(p)) {  // a bow tie or a star: no triangulation is right
      ++st.not_simple;
      if (st.first_not_simple < 0) st.first_not_simple = int64_t(f);
      continue;
    }
    bool reflex = false, flat = false;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const int64_t o = orient(p[i], p[(i + 1) % v.size()], p[(i + 2) % v.size()]);
      reflex = reflex || o < 0;
      flat = flat || o == 0;
    }
    // A corner met twice (a keyhole, or a boundary that wraps round) is no convex polygon even
    // when every corner turns left: the fan would reuse it in one triangle.
    sorted = p;
    std::sort(sorted.begin(), sorted.end(),
              [](const P2& a, const P2& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
    for (std::size_t i = 1; i < sorted.size() && !flat; ++i) flat = same(sorted[i - 1], sorted[i]);
    if (!reflex && !flat) {  // strictly convex: the fan from the first corner
      for (std::size_t k = 1; k + 1 < v.size(); ++k)
        out.push_back(Triangle{{v[0], v[k], v[k + 1]}, f});
      continue;
    }
    if (reflex) ++st.concave;
    if (!clip_ears(p, v, f, &out)) {
      ++st.not_simple;
      if (st.first_not_simple < 0) st.first_not_simple = int64_t(f);
    }
  }
  st.triangles = uint32_t(out.size());
  if (stats != nullptr) *stats = st;
  if (!regions.empty()) {
    // A region's triangles one run with its id, the runs in the order of their first faces:
    // the region's id is its first face, and triangles came out in face order.
    for (Triangle& t : out) t.polygon = regions[t.polygon];
    std::stable_sort(out.begin(), out.end(),
                     [](const Triangle& a, const Triangle& b) { return a.polygon < b.polygon; });
  }
  return out;
}

}  // namespace haloplot::host
