#include "pipeline/open_sides.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <tuple>

#include "pipeline/mesh_repair.h"

namespace haloplot::host {
namespace {

double distance(const Point3& p, const Point3& q) {
  const double dx = double(p.x) - q.x, dy = double(p.y) - q.y, dz = double(p.z) - q.z;
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// Every face side as (lesser vertex, greater vertex), sorted: a side's faces are its repeats.
std::vector<std::pair<uint32_t, uint32_t>> sorted_sides(const ObjModel& m) {
  std::vector<std::pair<uint32_t, uint32_t>> s;
  for (const std::vector<uint32_t>& c : m.faces)
    for (size_t i = 0; i < c.size(); ++i) {
      const uint32_t a = c[i], b = c[(i + 1) % c.size()];
      if (a != b) s.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(s.begin(), s.end());
  return s;
}

// The median length of the faces' sides, from at most some 65,000 faces spread over the model.
double median_side(const ObjModel& m) {
  std::vector<double> len;
  const size_t stride = std::max<size_t>(1, m.faces.size() / 65536);
  for (size_t f = 0; f < m.faces.size(); f += stride) {
    const std::vector<uint32_t>& c = m.faces[f];
    for (size_t i = 0; i < c.size(); ++i)
      len.push_back(distance(m.vertices[c[i]], m.vertices[c[(i + 1) % c.size()]]));
  }
  if (len.empty()) return 0;
  std::nth_element(len.begin(), len.begin() + std::ptrdiff_t(len.size() / 2), len.end());
  return len[len.size() / 2];
}

// Each vertex's faces: [first[v], first[v + 1]) of face.
struct FacesByVertex {
  std::vector<uint32_t> first, face;
  explicit FacesByVertex(const ObjModel& m) : first(m.vertices.size() + 1, 0) {
    for (const std::vector<uint32_t>& c : m.faces)
      for (uint32_t v : c) ++first[v + 1];
    for (size_t v = 0; v + 1 < first.size(); ++v) first[v + 1] += first[v];
    face.resize(first.back());
    std::vector<uint32_t> fill(first.begin(), first.end() - 1);
    for (uint32_t f = 0; f < m.faces.size(); ++f)
      for (uint32_t v : m.faces[f]) face[fill[v]++] = f;
  }
  bool share_a_face(const ObjModel& m, uint32_t v, uint32_t w) const {
    for (uint32_t k = first[v]; k < first[v + 1]; ++k) {
      const std::vector<uint32_t>& c = m.faces[face[k]];
      if (std::find(c.begin(), c.end(), w) != c.end()) return true;
    }
    return false;
  }
};

using Cell = std::array<int64_t, 3>;

Cell cell_of(const Point3& p, double side) {
  return {int64_t(std::floor(p.x / side)), int64_t(std::floor(p.y / side)),
          int64_t(std::floor(p.z / side))};
}

// The smallest number of one significant digit (1 to 9 times a power of ten) whose "%g" text,
// read back as --weld reads it, times `scale` is at least `world` > 0: the round EPS to print.
double round_eps(double world, double scale) {
  double p = std::pow(10.0, std::floor(std::log10(world / scale)) - 1);
  for (int d = 1;; ++d) {
    if (d == 10) d = 1, p *= 10;
    char text[32];
    std::snprintf(text, sizeof text, "%g", d * p);
    const double eps = std::strtod(text, nullptr);
    if (eps * scale >= world) return eps;
  }
}

}  // namespace

OpenSides measure_open_sides(const ObjModel& m) {
  OpenSides out;
  const std::vector<std::pair<uint32_t, uint32_t>> s = sorted_sides(m);
  std::vector<uint8_t> open(m.vertices.size(), 0);
  for (size_t i = 0, j = 0; i < s.size(); i = j) {
    while (j < s.size() && s[j] == s[i]) ++j;
    if (j - i == 1) {
      ++out.sides;
      open[s[i].first] = open[s[i].second] = 1;
    }
    if (j - i > 2) ++out.nonmanifold_sides;
  }
  out.typical_side = median_side(m);
  std::vector<std::pair<Cell, uint32_t>> corners;
  const double reach = std::max(1.0, out.typical_side / 2);
  for (uint32_t v = 0; v < open.size(); ++v)
    if (open[v]) corners.emplace_back(cell_of(m.vertices[v], reach), v);
  out.corners = uint32_t(corners.size());
  if (corners.empty()) return out;
  std::sort(corners.begin(), corners.end());
  const FacesByVertex faces(m);
  for (const auto& [cell, v] : corners) {
    double best = reach;
    bool found = false;
    for (int64_t dx = -1; dx <= 1; ++dx)
      for (int64_t dy = -1; dy <= 1; ++dy)
        for (int64_t dz = -1; dz <= 1; ++dz) {
          const Cell want = {cell[0] + dx, cell[1] + dy, cell[2] + dz};
          auto it = std::lower_bound(corners.begin(), corners.end(), std::make_pair(want, 0u));
          for (; it != corners.end() && it->first == want; ++it) {
            const uint32_t w = it->second;
            if (w == v) continue;
            const double d = distance(m.vertices[v], m.vertices[w]);
            if (d > best || (found && d == best) || faces.share_a_face(m, v, w)) continue;
            best = d;
            found = true;
          }
        }
    if (found) out.gaps.push_back(best);
  }
  std::sort(out.gaps.begin(), out.gaps.end());
  return out;
}

WeldTrial try_weld(ObjModel model, double tolerance) {
  RepairReport r;
  weld_vertices(&model, tolerance, &r);
  orient_shells(&model, &r);
  const std::vector<std::pair<uint32_t, uint32_t>> s = sorted_sides(model);
  WeldTrial t;
  for (size_t i = 0, j = 0; i < s.size(); i = j) {
    while (j < s.size() && s[j] == s[i]) ++j;
    t.open_sides += j - i == 1;
    t.nonmanifold_sides += j - i > 2;
  }
  t.shells = r.shells;
  t.closed_shells = r.closed_shells;
  t.unorientable_shells = r.unorientable_shells;
  t.dropped_faces = r.dropped_faces;
  return t;
}

WeldHint weld_hint(const ObjModel& model, const OpenSides& open) {
  WeldHint h;
  const std::vector<double>& g = open.gaps;
  const double limit = open.typical_side / kGapBelowSide;
  const uint32_t least = std::max(kMinGapCorners, open.corners / 10);
  while (h.near < g.size() && g[h.near] <= limit) ++h.near;
  if (h.near == 0) return h;
  h.nearest = g.front() / model.scale;
  h.farthest = g[h.near - 1] / model.scale;
  // The places the gaps jump by kGapJump or more (to the next gap, or the search's reach),
  // the widest first; then the median near gap.
  std::vector<std::pair<double, size_t>> jumps;
  for (size_t i = 0; i < h.near; ++i) {
    const double next = i + 1 < g.size() ? g[i + 1] : std::max(1.0, open.typical_side / 2);
    if (i + 1 >= least && next >= kGapJump * g[i]) jumps.emplace_back(next / g[i], i);
  }
  h.gaps = !jumps.empty();
  std::sort(jumps.begin(), jumps.end(), [](const auto& a, const auto& b) { return a > b; });
  // At a jump, twice its gap first: copies of one point strung out in a row (a, b, c) are
  // each nearest the next, but c joins a only within twice that.
  std::vector<double> tries;
  for (size_t k = 0; k < jumps.size() && k < 2; ++k) {
    const size_t i = jumps[k].second;
    if (jumps[k].first >= 2 * kGapJump) tries.push_back(2 * g[i]);
    tries.push_back(g[i]);
  }
  tries.push_back(g[h.near / 2]);
  h.before = try_weld(model, 0);
  for (double gap : tries) {
    const double eps = round_eps(gap, model.scale);
    if (h.tried && eps == h.eps) continue;  // the same weld again
    const WeldTrial after = try_weld(model, eps * model.scale);
    const bool better = after.open_sides < h.before.open_sides &&
                        after.nonmanifold_sides <= h.before.nonmanifold_sides &&
                        after.unorientable_shells <= h.before.unorientable_shells;
    if (!h.tried || better) {
      h.eps = eps;
      h.after = after;
      h.within = uint32_t(std::upper_bound(g.begin(), g.end(), eps * model.scale) - g.begin());
    }
    h.tried = true;
    if (better) {
      h.suggest = true;
      break;
    }
  }
  return h;
}

}  // namespace haloplot::host
