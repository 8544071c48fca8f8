// Solid test scenes in world coordinates: boxes, frames with a hole, L-blocks, UV spheres and
// tori, as polygons (counter-clockwise seen from outside, the OBJ convention), and the way
// from there to the core's projected SolidScene (core/view and the host's triangulation).
// Generators only: no visibility is decided here.
#pragma once
#include <cmath>
#include <cstdint>
#include <vector>

#include "cli/scene_input.h"
#include "haloplot/view/projection.h"
#include "pipeline/solid_pipeline.h"
#include "pipeline/triangulate.h"

namespace solid_scenes {

using haloplot::Point3;

struct Mesh {
  std::vector<Point3> v;
  std::vector<std::vector<uint32_t>> faces;

  uint32_t add(int32_t x, int32_t y, int32_t z) {
    v.push_back(Point3{x, y, z});
    return uint32_t(v.size() - 1);
  }
  void face(std::vector<uint32_t> f) { faces.push_back(std::move(f)); }
};

// An axis-aligned box, six quads.
inline void box(Mesh* m, int32_t x0, int32_t y0, int32_t z0, int32_t x1, int32_t y1, int32_t z1) {
  uint32_t c[8];
  for (int i = 0; i < 8; ++i) c[i] = m->add(i & 1 ? x1 : x0, i & 2 ? y1 : y0, i & 4 ? z1 : z0);
  m->face({c[0], c[2], c[3], c[1]});  // z0, normal -z
  m->face({c[4], c[5], c[7], c[6]});  // z1, +z
  m->face({c[0], c[1], c[5], c[4]});  // y0, -y
  m->face({c[2], c[6], c[7], c[3]});  // y1, +y
  m->face({c[0], c[4], c[6], c[2]});  // x0, -x
  m->face({c[1], c[3], c[7], c[5]});  // x1, +x
}

// A prism over a counter-clockwise polygon in the xy plane (may be concave), from z0 to z1.
inline void prism(Mesh* m, const std::vector<std::pair<int32_t, int32_t>>& poly, int32_t z0,
                  int32_t z1) {
  const size_t n = poly.size();
  std::vector<uint32_t> lo(n), hi(n);
  for (size_t i = 0; i < n; ++i) {
    lo[i] = m->add(poly[i].first, poly[i].second, z0);
    hi[i] = m->add(poly[i].first, poly[i].second, z1);
  }
  m->face(std::vector<uint32_t>(hi.begin(), hi.end()));
  m->face(std::vector<uint32_t>(lo.rbegin(), lo.rend()));
  for (size_t i = 0; i < n; ++i) {
    const size_t j = (i + 1) % n;
    m->face({lo[i], lo[j], hi[j], hi[i]});
  }
}

// A square frame (a box with a square hole through it along z): genus one, concave.
inline void frame(Mesh* m, int32_t x0, int32_t y0, int32_t size, int32_t hole, int32_t z0,
                  int32_t z1) {
  const int32_t a = (size - hole) / 2;
  // Outer ring o[k] and inner ring h[k] at both depths, counter-clockwise.
  const int32_t ox[4] = {x0, x0 + size, x0 + size, x0};
  const int32_t oy[4] = {y0, y0, y0 + size, y0 + size};
  const int32_t hx[4] = {x0 + a, x0 + a + hole, x0 + a + hole, x0 + a};
  const int32_t hy[4] = {y0 + a, y0 + a, y0 + a + hole, y0 + a + hole};
  uint32_t o0[4], o1[4], h0[4], h1[4];
  for (int k = 0; k < 4; ++k) {
    o0[k] = m->add(ox[k], oy[k], z0);
    o1[k] = m->add(ox[k], oy[k], z1);
    h0[k] = m->add(hx[k], hy[k], z0);
    h1[k] = m->add(hx[k], hy[k], z1);
  }
  for (int k = 0; k < 4; ++k) {
    const int j = (k + 1) % 4;
    m->face({o1[k], o1[j], h1[j], h1[k]});  // top trapezoids (+z)
    m->face({o0[j], o0[k], h0[k], h0[j]});  // bottom (-z)
    m->face({o0[k], o0[j], o1[j], o1[k]});  // outer walls
    m->face({h0[j], h0[k], h1[k], h1[j]});  // hole walls, facing the hole
  }
}

// A UV sphere: `stacks` bands of `slices` quads, triangles at the poles.
inline void sphere(Mesh* m, int32_t cx, int32_t cy, int32_t cz, int32_t r, int stacks, int slices) {
  const double pi = std::acos(-1.0);
  const uint32_t south = m->add(cx, cy, cz - r);
  std::vector<uint32_t> ring_start;
  for (int i = 1; i < stacks; ++i) {
    const double phi = -pi / 2 + pi * i / stacks;
    ring_start.push_back(uint32_t(m->v.size()));
    for (int j = 0; j < slices; ++j) {
      const double th = 2 * pi * j / slices;
      m->add(cx + int32_t(std::lround(r * std::cos(phi) * std::cos(th))),
             cy + int32_t(std::lround(r * std::cos(phi) * std::sin(th))),
             cz + int32_t(std::lround(r * std::sin(phi))));
    }
  }
  const uint32_t north = m->add(cx, cy, cz + r);
  auto at = [&](int ring, int j) { return ring_start[size_t(ring)] + uint32_t(j % slices); };
  for (int j = 0; j < slices; ++j) m->face({south, at(0, j + 1), at(0, j)});
  for (int i = 0; i + 1 < stacks - 1; ++i)
    for (int j = 0; j < slices; ++j)
      m->face({at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)});
  for (int j = 0; j < slices; ++j) m->face({north, at(stacks - 2, j), at(stacks - 2, j + 1)});
}

// A torus around the z axis (or, upright, around the y axis: turned 90 degrees about x, a
// rotation, so faces keep their winding): major radius R, minor r, n x k quads.
inline void torus(Mesh* m, int32_t cx, int32_t cy, int32_t cz, int32_t R, int32_t r, int n, int k,
                  bool upright = false) {
  const double pi = std::acos(-1.0);
  const uint32_t base = uint32_t(m->v.size());
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < k; ++j) {
      const double u = 2 * pi * i / n, w = 2 * pi * j / k;
      const double rr = R + r * std::cos(w);
      const int32_t x = int32_t(std::lround(rr * std::cos(u)));
      const int32_t y = int32_t(std::lround(rr * std::sin(u)));
      const int32_t z = int32_t(std::lround(r * std::sin(w)));
      if (upright)
        m->add(cx + x, cy - z, cz + y);
      else
        m->add(cx + x, cy + y, cz + z);
    }
  auto at = [&](int i, int j) { return base + uint32_t((i % n) * k + (j % k)); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < k; ++j) m->face({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
}

// Drawn edges: the polygon sides, in first-seen order (what the OBJ reader does).
inline std::vector<uint32_t> polygon_edges(const Mesh& m) {
  std::vector<uint32_t> pairs;
  std::vector<std::pair<uint32_t, uint32_t>> seen;
  std::vector<std::vector<uint32_t>> adj(m.v.size());
  for (const auto& f : m.faces)
    for (size_t i = 0; i < f.size(); ++i) {
      uint32_t a = f[i], b = f[(i + 1) % f.size()];
      if (a == b) continue;
      const uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
      bool dup = false;
      for (uint32_t x : adj[lo]) dup = dup || x == hi;
      if (dup) continue;
      adj[lo].push_back(hi);
      pairs.push_back(a);
      pairs.push_back(b);
    }
  return pairs;
}

// Projects and triangulates: the scene the core sees.
inline bool project(const Mesh& m, const haloplot::View& view, haloplot::host::SolidScene* out) {
  out->vertices.resize(m.v.size());
  if (haloplot::project_points(view, m.v.data(), uint32_t(m.v.size()), out->vertices.data()) !=
      haloplot::Status::kOk)
    return false;
  out->edge_pairs = polygon_edges(m);
  out->triangles = haloplot::host::triangulate(m.v, m.faces, nullptr);
  out->substep_bits = view.substep_bits;
  std::string error;
  return haloplot::host::model_facing_of(view, m.v, out, &error);
}

inline haloplot::View view(int32_t az_mdeg, int32_t el_mdeg) {
  haloplot::View v;
  v.azimuth_mdeg = az_mdeg;
  v.elevation_mdeg = el_mdeg;
  return v;
}

}  // namespace solid_scenes
