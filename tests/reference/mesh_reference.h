// An independent reference for the hidden-line drawing of any mesh (issue 45): brute force in
// float64, written from the docs only (docs/formats.md, docs/cli.md, docs/design.md's view
// convention). It includes nothing from core/ or host_sim/ and links neither: the plot is
// judged by its SVG, the reference is built from the OBJ file itself.
//
// What it draws (Blender Line Art / Freestyle's defaults as the guide). The OBJ's corners are
// welded where they fall on the same integer world position (the model centred and scaled to
// span 2^19 units, as the tool's --weld 0 does), polygons are fanned into triangles, and an
// edge (a pair of welded corners that some triangle has as a side) is drawn when it is
//  - a boundary edge: one triangle;
//  - a non-manifold edge: three or more triangles;
//  - a crease: two triangles, not of one polygon, whose planes fold by more than the crease
//    angle. The fold is measured with the two triangles oriented consistently across the
//    edge: where their windings disagree (a non-orientable shell's seam, a file's inverted
//    face) one normal is turned over first. That is the angle the surface bends through, the
//    same for either orientation of the shell (an unsigned min(angle, 180 - angle) would call
//    a fold of 150 degrees a bend of 30);
//  - a contour: two triangles (of one polygon or not) whose far corners lie on the same side of
//    the edge on paper: the eye sees one from the front and the other from the back, whatever
//    the orientation.
// A point of a drawn edge is visible when the ray from it to the viewer (orthographic, towards
// +depth) passes through the inside of no triangle but the edge's own (those holding both its
// corners); both sides of a triangle hide. Edges are sampled every half step on paper, a
// change of visibility located by bisection.
//
// Ink is compared both ways: the share of one drawing's length lying within a tolerance (2
// steps) of the other's lines.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace mesh_reference {

constexpr double kPi = 3.14159265358979323846;

struct Vec3 {
  double x = 0, y = 0, z = 0;
};
inline Vec3 sub(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }

struct Tri {
  uint32_t v[3];
  uint32_t polygon;  // the f statement it comes from
};

struct Mesh {
  std::vector<Vec3> file;    // every v of the file, as written
  std::vector<uint32_t> id;  // file vertex -> welded vertex (the first at its world position)
  std::vector<Tri> tris;     // welded ids
  std::string error;
};

// Reads v and f statements (v, v/vt, v//vn, v/vt/vn; negative indices from the last v so far);
// everything else is skipped. Polygons lose repeated corners and are fanned from their first.
inline Mesh read_obj(const std::string& path) {
  Mesh m;
  std::ifstream in(path);
  if (!in) {
    m.error = "cannot open " + path;
    return m;
  }
  std::vector<std::vector<long>> faces;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string key;
    if (!(ls >> key)) continue;
    if (key == "v") {
      Vec3 p;
      ls >> p.x >> p.y >> p.z;
      m.file.push_back(p);
    } else if (key == "f") {
      std::vector<long> f;
      std::string c;
      while (ls >> c) {
        long i = std::stol(c.substr(0, c.find('/')));
        f.push_back(i < 0 ? long(m.file.size()) + i : i - 1);
      }
      faces.push_back(f);
    }
  }
  // Weld: the tool's world position (docs/formats.md: centred on the bounding box, the largest
  // extent scaled to 2^19, rounded to integers).
  Vec3 lo = m.file.empty() ? Vec3{} : m.file[0], hi = lo;
  for (const Vec3& p : m.file) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  const double s = extent > 0 ? 524288.0 / extent : 1.0;
  std::map<std::tuple<long, long, long>, uint32_t> at;
  for (uint32_t i = 0; i < m.file.size(); ++i) {
    const Vec3& p = m.file[i];
    auto key = std::make_tuple(std::lround((p.x - (lo.x + hi.x) / 2) * s),
                               std::lround((p.y - (lo.y + hi.y) / 2) * s),
                               std::lround((p.z - (lo.z + hi.z) / 2) * s));
    m.id.push_back(at.emplace(key, i).first->second);
  }
  for (uint32_t fi = 0; fi < faces.size(); ++fi) {
    std::vector<uint32_t> c;
    for (long i : faces[fi]) {
      if (i < 0 || size_t(i) >= m.file.size()) {
        m.error = path + ": face " + std::to_string(fi) + " has a bad index";
        return m;
      }
      const uint32_t w = m.id[size_t(i)];
      if (c.empty() || c.back() != w) c.push_back(w);
    }
    while (c.size() > 1 && c.back() == c.front()) c.pop_back();
    if (c.size() < 3) continue;
    for (size_t k = 1; k + 1 < c.size(); ++k) m.tris.push_back({{c[0], c[k], c[k + 1]}, fi});
  }
  return m;
}

// The camera of docs/design.md (world Z-up; the OBJ read Y-up: file (x, y, z) is world
// (x, -z, y)), fitted uniformly into the page's drawable area with its lower-left corner at
// the margin, in steps. Depth is scaled by the same factor (so lengths in steps everywhere).
struct View {
  double az_deg = 30, el_deg = 25;
  double per_mm = 80, page_w_mm = 297, page_h_mm = 210, margin_mm = 10;
};

struct Projected {
  std::vector<Vec3> p;  // x, y on paper in steps (before the page's centring offset), z depth
};

inline Projected project(const Mesh& m, const View& v) {
  const double az = v.az_deg * kPi / 180, el = v.el_deg * kPi / 180;
  std::vector<Vec3> r;
  for (const Vec3& f : m.file) {
    const double x = f.x, y = -f.z, z = f.y;
    const double xs = x * std::cos(az) - y * std::sin(az);
    const double y1 = x * std::sin(az) + y * std::cos(az);
    r.push_back({xs, z * std::cos(el) + y1 * std::sin(el), z * std::sin(el) - y1 * std::cos(el)});
  }
  double xl = 1e300, xh = -1e300, yl = 1e300, yh = -1e300;
  for (const Vec3& q : r)
    xl = std::min(xl, q.x), xh = std::max(xh, q.x), yl = std::min(yl, q.y), yh = std::max(yh, q.y);
  const double margin = std::ceil(v.margin_mm * v.per_mm);
  const double w = std::floor((v.page_w_mm - v.margin_mm) * v.per_mm) - margin;
  const double h = std::floor((v.page_h_mm - v.margin_mm) * v.per_mm) - margin;
  const double k = std::min(w / (xh - xl), h / (yh - yl));
  Projected out;
  for (const Vec3& q : r)
    out.p.push_back({margin + (q.x - xl) * k, margin + (q.y - yl) * k, q.z * k});
  return out;
}

enum Kind { kSmooth = 0, kBoundary, kNonManifold, kCrease, kContour };
inline const char* kind_name(int k) {
  static const char* names[] = {"smooth", "boundary", "non-manifold", "crease", "contour"};
  return names[k];
}

struct Seg {
  double x0, y0, x1, y1;
};

struct Edge {
  uint32_t a, b;
  std::vector<uint32_t> tris;
  int kind = kSmooth;
};

// Every side of every triangle, once, with the triangles that have it.
inline std::vector<Edge> edges_of(const Mesh& m) {
  std::unordered_map<uint64_t, uint32_t> index;
  std::vector<Edge> edges;
  for (uint32_t t = 0; t < m.tris.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      uint32_t a = m.tris[t].v[i], b = m.tris[t].v[(i + 1) % 3];
      if (a > b) std::swap(a, b);
      const uint64_t key = (uint64_t(a) << 32) | b;
      auto it = index.emplace(key, uint32_t(edges.size())).first;
      if (it->second == edges.size()) edges.push_back({a, b, {}});
      edges[it->second].tris.push_back(t);
    }
  return edges;
}

inline uint32_t far_corner(const Tri& t, uint32_t a, uint32_t b) {
  for (uint32_t c : t.v)
    if (c != a && c != b) return c;
  return t.v[0];
}
// +1 when the triangle runs a -> b, -1 when b -> a.
inline int direction(const Tri& t, uint32_t a, uint32_t b) {
  for (int i = 0; i < 3; ++i) {
    if (t.v[i] == a && t.v[(i + 1) % 3] == b) return 1;
    if (t.v[i] == b && t.v[(i + 1) % 3] == a) return -1;
  }
  return 0;
}

inline void classify(const Mesh& m, const Projected& P, double crease_deg,
                     std::vector<Edge>* edges) {
  const double cos_crease = std::cos(crease_deg * kPi / 180);
  for (Edge& e : *edges) {
    if (e.tris.size() == 1) {
      e.kind = kBoundary;
      continue;
    }
    if (e.tris.size() >= 3) {
      e.kind = kNonManifold;
      continue;
    }
    const Tri &t1 = m.tris[e.tris[0]], &t2 = m.tris[e.tris[1]];
    const uint32_t c1 = far_corner(t1, e.a, e.b), c2 = far_corner(t2, e.a, e.b);
    // Contour: the far corners on the same side of the edge on paper.
    const Vec3 &A = P.p[e.a], &B = P.p[e.b], &C1 = P.p[c1], &C2 = P.p[c2];
    const double ex = B.x - A.x, ey = B.y - A.y;
    const double s1 = ex * (C1.y - A.y) - ey * (C1.x - A.x);
    const double s2 = ex * (C2.y - A.y) - ey * (C2.x - A.x);
    if ((s1 > 0 && s2 > 0) || (s1 < 0 && s2 < 0)) {
      e.kind = kContour;
      continue;
    }
    if (t1.polygon == t2.polygon) continue;  // a polygon's own diagonal: smooth
    // Crease: the fold between the planes, the two oriented consistently across the edge.
    auto normal = [&](const Tri& t) {
      const Vec3 &p0 = m.file[t.v[0]], &p1 = m.file[t.v[1]], &p2 = m.file[t.v[2]];
      return cross(sub(p1, p0), sub(p2, p0));
    };
    Vec3 n1 = normal(t1), n2 = normal(t2);
    const double l1 = norm(n1), l2 = norm(n2);
    if (l1 == 0 || l2 == 0) {
      e.kind = kCrease;  // a triangle with no area: its plane is any, so treated as a fold
      continue;
    }
    double c = dot(n1, n2) / (l1 * l2);
    if (direction(t1, e.a, e.b) == direction(t2, e.a, e.b)) c = -c;  // windings disagree
    if (c < cos_crease) e.kind = kCrease;
  }
}

// Ray casting on paper: triangles bucketed by their screen bounding boxes.
class Caster {
 public:
  Caster(const Mesh& m, const Projected& P) : m_(m), P_(P) {
    xl_ = yl_ = 1e300;
    double xh = -1e300, yh = -1e300;
    for (const Vec3& q : P.p)
      xl_ = std::min(xl_, q.x), xh = std::max(xh, q.x), yl_ = std::min(yl_, q.y),
      yh = std::max(yh, q.y);
    n_ = 128;
    cw_ = std::max(1e-9, (xh - xl_) / n_) * 1.0000001;
    ch_ = std::max(1e-9, (yh - yl_) / n_) * 1.0000001;
    cells_.assign(size_t(n_ * n_), {});
    for (uint32_t t = 0; t < m.tris.size(); ++t) {
      double bx0 = 1e300, bx1 = -1e300, by0 = 1e300, by1 = -1e300;
      for (uint32_t c : m.tris[t].v)
        bx0 = std::min(bx0, P.p[c].x), bx1 = std::max(bx1, P.p[c].x), by0 = std::min(by0, P.p[c].y),
        by1 = std::max(by1, P.p[c].y);
      for (int cy = cell_y(by0); cy <= cell_y(by1); ++cy)
        for (int cx = cell_x(bx0); cx <= cell_x(bx1); ++cx)
          cells_[size_t(cy * n_ + cx)].push_back(t);
    }
  }

  // Is the point q (paper x, y, depth) hidden by a triangle that does not hold both a and b?
  bool hidden(const Vec3& q, uint32_t a, uint32_t b) const {
    const int cx = cell_x(q.x), cy = cell_y(q.y);
    for (uint32_t t : cells_[size_t(cy * n_ + cx)]) {
      const Tri& tr = m_.tris[t];
      const bool ha = tr.v[0] == a || tr.v[1] == a || tr.v[2] == a;
      const bool hb = tr.v[0] == b || tr.v[1] == b || tr.v[2] == b;
      if (ha && hb) continue;
      if (blocks(tr, q)) return true;
    }
    return false;
  }

  // The visible pieces of edge a b on paper.
  void visible_pieces(uint32_t a, uint32_t b, std::vector<Seg>* out) const {
    const Vec3 &A = P_.p[a], &B = P_.p[b];
    const double L = std::hypot(B.x - A.x, B.y - A.y);
    auto at = [&](double s) {
      return Vec3{A.x + s * (B.x - A.x), A.y + s * (B.y - A.y), A.z + s * (B.z - A.z)};
    };
    auto visible = [&](double s) { return !hidden(at(s), a, b); };
    const int64_t n = std::max<int64_t>(2, int64_t(std::ceil(L / 0.5)));
    auto sample = [&](int64_t i) { return (double(i) + 0.5) / double(n); };
    bool prev = visible(sample(0));
    double start = 0;
    auto emit = [&](double s0, double s1) {
      const Vec3 p = at(s0), q = at(s1);
      out->push_back({p.x, p.y, q.x, q.y});
    };
    for (int64_t i = 1; i < n; ++i) {
      const bool v = visible(sample(i));
      if (v == prev) continue;
      double lo = sample(i - 1), hi = sample(i);
      for (int k = 0; k < 30; ++k) {
        const double mid = (lo + hi) / 2;
        (visible(mid) == prev ? lo : hi) = mid;
      }
      if (prev) emit(start, (lo + hi) / 2);
      start = (lo + hi) / 2;
      prev = v;
    }
    if (prev) emit(start, 1.0);
  }

 private:
  int cell_x(double x) const { return std::clamp(int((x - xl_) / cw_), 0, n_ - 1); }
  int cell_y(double y) const { return std::clamp(int((y - yl_) / ch_), 0, n_ - 1); }

  // Does the ray from q towards the viewer pass through the inside of triangle t?
  bool blocks(const Tri& t, const Vec3& q) const {
    const Vec3 &p0 = P_.p[t.v[0]], &p1 = P_.p[t.v[1]], &p2 = P_.p[t.v[2]];
    const double d = (p1.x - p0.x) * (p2.y - p0.y) - (p1.y - p0.y) * (p2.x - p0.x);
    if (std::fabs(d) < 1e-12) return false;  // edge-on: covers no area
    const double w1 = ((q.x - p0.x) * (p2.y - p0.y) - (q.y - p0.y) * (p2.x - p0.x)) / d;
    const double w2 = ((p1.x - p0.x) * (q.y - p0.y) - (p1.y - p0.y) * (q.x - p0.x)) / d;
    const double w0 = 1 - w1 - w2;
    const double eps = 1e-9;
    if (w0 <= eps || w1 <= eps || w2 <= eps) return false;
    const double depth = w0 * p0.z + w1 * p1.z + w2 * p2.z;
    return depth > q.z + 1e-6;
  }

  const Mesh& m_;
  const Projected& P_;
  double xl_, yl_, cw_, ch_;
  int n_;
  std::vector<std::vector<uint32_t>> cells_;
};

// The share of ink a (by length) within tol of some line of b.
class SegIndex {
 public:
  SegIndex(const std::vector<Seg>& segs, double cell) : segs_(segs), cell_(cell) {
    for (uint32_t i = 0; i < segs.size(); ++i) {
      const Seg& s = segs[i];
      const double L = std::hypot(s.x1 - s.x0, s.y1 - s.y0);
      const int n = int(std::ceil(L / (cell / 4))) + 1;
      int64_t last = -1;
      for (int k = 0; k <= n; ++k) {
        const double u = double(k) / n;
        const int64_t key = key_of(s.x0 + u * (s.x1 - s.x0), s.y0 + u * (s.y1 - s.y0));
        if (key == last) continue;
        last = key;
        auto& v = cells_[key];
        if (v.empty() || v.back() != i) v.push_back(i);
      }
    }
  }
  bool near(double x, double y, double tol) const {
    const int64_t cx = int64_t(std::floor(x / cell_)), cy = int64_t(std::floor(y / cell_));
    for (int64_t dy = -2; dy <= 2; ++dy)
      for (int64_t dx = -2; dx <= 2; ++dx) {
        auto it = cells_.find(pack(cx + dx, cy + dy));
        if (it == cells_.end()) continue;
        for (uint32_t i : it->second)
          if (distance(segs_[i], x, y) <= tol) return true;
      }
    return false;
  }

 private:
  static int64_t pack(int64_t cx, int64_t cy) {
    return (cx + (1 << 20)) * (int64_t(1) << 22) + (cy + (1 << 20));
  }
  int64_t key_of(double x, double y) const {
    return pack(int64_t(std::floor(x / cell_)), int64_t(std::floor(y / cell_)));
  }
  static double distance(const Seg& s, double x, double y) {
    const double ex = s.x1 - s.x0, ey = s.y1 - s.y0, l2 = ex * ex + ey * ey;
    double u = l2 > 0 ? ((x - s.x0) * ex + (y - s.y0) * ey) / l2 : 0;
    u = std::clamp(u, 0.0, 1.0);
    return std::hypot(s.x0 + u * ex - x, s.y0 + u * ey - y);
  }
  const std::vector<Seg>& segs_;
  double cell_;
  std::unordered_map<int64_t, std::vector<uint32_t>> cells_;
};

struct Share {
  double near = 0, total = 0;
  double fraction() const { return total > 0 ? near / total : 1.0; }
};

// The length of a lying within tol of b, sampled every quarter step; the pieces of a that are
// not (for pictures) go to *misses.
inline Share ink_within(const std::vector<Seg>& a, const std::vector<Seg>& b, double tol,
                        std::vector<Seg>* misses = nullptr) {
  SegIndex index(b, 2 * tol);
  Share sh;
  for (const Seg& s : a) {
    const double L = std::hypot(s.x1 - s.x0, s.y1 - s.y0);
    const int n = std::max(1, int(std::ceil(L / 0.25)));
    for (int k = 0; k < n; ++k) {
      const double u0 = double(k) / n, u1 = double(k + 1) / n, u = (u0 + u1) / 2;
      const bool ok = index.near(s.x0 + u * (s.x1 - s.x0), s.y0 + u * (s.y1 - s.y0), tol);
      sh.total += L / n;
      if (ok)
        sh.near += L / n;
      else if (misses)
        misses->push_back({s.x0 + u0 * (s.x1 - s.x0), s.y0 + u0 * (s.y1 - s.y0),
                           s.x0 + u1 * (s.x1 - s.x0), s.y0 + u1 * (s.y1 - s.y0)});
    }
  }
  return sh;
}

}  // namespace mesh_reference
