// Hatching against its two promises, checked by brute force in long double (independent of the
// core's exact predicates): every hatch stroke lies on the face that is nearest the viewer at
// its points (so each hatched region is inside exactly one visible face), and no stroke crosses
// a visible edge. Scenes: the pair of cubes, linked tori, spheres, concave frames, random views,
// depth-dependent angles. Points within a step of any projected edge are skipped (the strokes'
// ends are rounded to steps, within 1/2 step of the face's side).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <set>
#include <string>

#include "check.h"
#include "haloplot/cut/grid.h"
#include "pipeline/surface_pipeline.h"
#include "support/solid_scenes.h"

using namespace haloplot;
using namespace haloplot::host;
using namespace solid_scenes;

namespace {

using LD = long double;

// Distance from p to segment ab, on paper.
LD seg_dist(LD px, LD py, const Point3& a, const Point3& b) {
  const LD dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
  LD t = l2 > 0 ? ((px - a.x) * dx + (py - a.y) * dy) / l2 : 0;
  t = std::max<LD>(0, std::min<LD>(1, t));
  const LD ex = px - (a.x + t * dx), ey = py - (a.y + t * dy);
  return std::sqrt(ex * ex + ey * ey);
}

// The nearest face at (px, py) by brute force, or -1; `near_edge` when the point is within a
// step of a side of any face that holds it (ambiguous at the step scale: skipped).
int nearest(const SolidScene& s, LD px, LD py, bool* near_edge) {
  int best = -1;
  LD best_z = -1e300L;
  *near_edge = false;
  for (size_t t = 0; t < s.triangles.size(); ++t) {
    const Point3 a = s.vertices[s.triangles[t].v[0]], b = s.vertices[s.triangles[t].v[1]],
                 c = s.vertices[s.triangles[t].v[2]];
    const LD area = LD(b.x - a.x) * (c.y - a.y) - LD(b.y - a.y) * (c.x - a.x);
    if (area == 0) continue;
    if (px < std::min({a.x, b.x, c.x}) - 1 || px > std::max({a.x, b.x, c.x}) + 1 ||
        py < std::min({a.y, b.y, c.y}) - 1 || py > std::max({a.y, b.y, c.y}) + 1)
      continue;  // neither inside nor within a step of a side
    const LD l1 = (LD(b.x - px) * (c.y - py) - LD(b.y - py) * (c.x - px)) / area;
    const LD l2 = (LD(c.x - px) * (a.y - py) - LD(c.y - py) * (a.x - px)) / area;
    const LD l3 = 1 - l1 - l2;
    const bool inside = l1 >= 0 && l2 >= 0 && l3 >= 0;
    const LD d = std::min({seg_dist(px, py, a, b), seg_dist(px, py, b, c), seg_dist(px, py, c, a)});
    if ((inside || d < 1.0L) && d < 1.0L) *near_edge = true;
    if (!inside) continue;
    const LD z = l1 * a.z + l2 * b.z + l3 * c.z;
    if (z > best_z) best_z = z, best = int(t);
  }
  return best;
}

bool proper_cross(LD ax, LD ay, LD bx, LD by, LD cx, LD cy, LD dx, LD dy, LD margin_ab,
                  LD margin_cd) {
  const LD rx = bx - ax, ry = by - ay, sx = dx - cx, sy = dy - cy;
  const LD den = rx * sy - ry * sx;
  if (den == 0) return false;
  const LD t = ((cx - ax) * sy - (cy - ay) * sx) / den, u = ((cx - ax) * ry - (cy - ay) * rx) / den;
  return t > margin_ab && t < 1 - margin_ab && u > margin_cd && u < 1 - margin_cd;
}

void check_strokes(const SolidScene& s, const HatchRun& hr, const std::string& label);

// Franklin's steps 10-11 against brute force: the cycles against Euler's relation (nodes -
// segments + bounded cycles = connected pieces = hole cycles, pieces counted by union-find), and
// the face each cycle names against the nearest face a quarter step to the left of the middle of
// every segment of the cycle at least 8 steps long (skipped within 0.2 step of any face side).
void check_regions(const SolidScene& s, const std::string& label) {
  RegionsRun rr;
  const Status st = run_regions(s, FranklinParams{}, &rr);
  CHECK_MSG(st == Status::kOk, label + ": regions " + status_name(st));
  if (st != Status::kOk) return;
  CHECK_MSG(rr.stats.overlaps == 0, label + ": no overlapping half-edges");
  std::vector<uint32_t> parent(rr.n_nodes);
  for (uint32_t v = 0; v < rr.n_nodes; ++v) parent[v] = v;
  auto find = [&](uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  std::set<uint32_t> used;
  int64_t edges = 0;
  for (size_t g = 0; g < rr.segments.size(); ++g) {
    if (!rr.kept[g]) continue;
    ++edges;
    used.insert(rr.node[2 * g]);
    used.insert(rr.node[2 * g + 1]);
    parent[find(rr.node[2 * g])] = find(rr.node[2 * g + 1]);
  }
  std::set<uint32_t> roots;
  for (uint32_t v : used) roots.insert(find(v));
  const int64_t pieces = int64_t(roots.size());
  const int64_t bounded = rr.stats.bounded, holes = rr.stats.holes;
  CHECK_MSG(holes == pieces, label + ": " + std::to_string(holes) + " hole cycles for " +
                                 std::to_string(pieces) + " connected pieces");
  CHECK_MSG(int64_t(used.size()) - edges + bounded == pieces,
            label + ": Euler V - E + bounded = pieces (" + std::to_string(used.size()) + " - " +
                std::to_string(edges) + " + " + std::to_string(bounded) +
                " != " + std::to_string(pieces) + ")");
  int checked = 0, wrong = 0;
  for (size_t g = 0; g < rr.segments.size(); ++g) {
    if (!rr.kept[g]) continue;
    const RegionSegment& seg = rr.segments[g];
    const Point3 a = s.vertices[s.edge_pairs[2 * seg.edge]],
                 b = s.vertices[s.edge_pairs[2 * seg.edge + 1]];
    const LD t0 = std::ldexp(LD(seg.t0), -32), t1 = std::ldexp(LD(seg.t1), -32);
    const LD dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
    if ((t1 - t0) * len < 8) continue;
    const LD mx = a.x + (t0 + t1) / 2 * dx, my = a.y + (t0 + t1) / 2 * dy;
    for (int side = 0; side < 2; ++side) {
      const uint32_t face = rr.cycle_face[rr.cycle[2 * g + size_t(side)]];
      if (face == kRegionUnnamed) continue;
      const LD sgn = side == 0 ? 1 : -1;  // half-edge 2g runs along the edge: left is (-dy, dx)
      const LD px = mx - sgn * dy / len * 0.25L, py = my + sgn * dx / len * 0.25L;
      LD closest = 1e30L;
      for (const Triangle& t : s.triangles) {
        LD x0 = 1e30L, x1 = -1e30L, y0 = 1e30L, y1 = -1e30L;
        for (uint32_t v : t.v) {
          x0 = std::min<LD>(x0, s.vertices[v].x), x1 = std::max<LD>(x1, s.vertices[v].x);
          y0 = std::min<LD>(y0, s.vertices[v].y), y1 = std::max<LD>(y1, s.vertices[v].y);
        }
        if (px < x0 - 1 || px > x1 + 1 || py < y0 - 1 || py > y1 + 1) continue;  // > 0.2 away
        for (int k = 0; k < 3; ++k) {
          const Point3 u = s.vertices[t.v[k]], w = s.vertices[t.v[(k + 1) % 3]];
          closest = std::min(closest, seg_dist(px, py, u, w));
        }
      }
      if (closest < 0.2L) continue;
      bool near_edge = false;
      const int want = nearest(s, px, py, &near_edge);
      ++checked;
      const bool same =
          face == kRegionBackground
              ? want < 0
              : want >= 0 && s.triangles[size_t(want)].polygon == s.triangles[face].polygon;
      if (!same && ++wrong <= 2)
        std::fprintf(stderr, "  segment %zu side %d: face %u, brute force %d\n", g, side, face,
                     want);
    }
  }
  CHECK_MSG(checked > 0, label + ": region faces checked");
  CHECK_MSG(wrong == 0, label + ": " + std::to_string(wrong) + " of " + std::to_string(checked) +
                            " region faces differ from the nearest face");
}

// Total stroke length per polygon: the two hatching methods fill the same visible areas, so
// they agree to within the rounding of their ends. An end is within 1/2 step of the boundary
// across it, which along a line meeting the boundary at a shallow angle is several steps: the
// slack is 4 steps a stroke, both methods' strokes counted.
void compare_methods(const HatchRun& regions, const HatchRun& faces, const std::string& label) {
  std::map<uint32_t, LD> len;
  std::map<uint32_t, LD> slack;
  for (const auto* run : {&regions, &faces})
    for (const HatchStroke& h : run->strokes) {
      const LD l = std::hypot(LD(h.line.b.x - h.line.a.x), LD(h.line.b.y - h.line.a.y));
      len[h.polygon] += run == &regions ? l : -l;
      slack[h.polygon] += 4;
    }
  int off = 0;
  for (const auto& [poly, d] : len)
    if (std::fabs(d) > slack[poly] + 2) {
      if (++off <= 2)
        std::fprintf(stderr, "  polygon %u: regions - faces = %.1Lf steps (slack %.0Lf)\n", poly, d,
                     slack[poly]);
    }
  CHECK_MSG(off == 0, label + ": " + std::to_string(off) +
                          " polygons hatched differently by the two methods");
}

void check_scene(const SolidScene& s, const HatchParams& hp, const std::string& label) {
  check_regions(s, label);
  HatchRun faces;
  CHECK(run_hatch(s, hp, &faces, HatchMethod::kLines) == Status::kOk);
  check_strokes(s, faces, label + " (lines)");
  // No dots: with lines shorter than a step not laid, a visible piece is a step or more long,
  // except where a nearer face leaves less of it (a piece ending at another face's side).
  HatchParams steps = hp;
  steps.min_length = 1;
  HatchRun laid;
  CHECK(run_hatch(s, steps, &laid, HatchMethod::kLines) == Status::kOk);
  size_t dots = 0;
  for (const HatchStroke& h : laid.strokes)
    dots += h.line.a.x == h.line.b.x && h.line.a.y == h.line.b.y ? 1 : 0;
  CHECK_MSG(dots * 1000 <= laid.strokes.size(), label + ": " + std::to_string(dots) + " of " +
                                                    std::to_string(laid.strokes.size()) +
                                                    " hatch strokes are dots");
  HatchRun hr;
  const Status st = run_hatch(s, hp, &hr);
  CHECK_MSG(st == Status::kOk, label + ": " + status_name(st));
  check_strokes(s, hr, label + " (regions)");
  compare_methods(hr, faces, label);
}

void check_strokes(const SolidScene& s, const HatchRun& hr, const std::string& label) {
  CHECK_MSG(!hr.strokes.empty(), label + ": some strokes");
  SolidRun qi;
  CHECK(run_hidden_lines(s, HiddenMethod::kAuto, FallbackParams{}, &qi) == Status::kOk);
  std::map<uint32_t, std::set<uint32_t>> poly_vertices;
  for (const Triangle& t : s.triangles)
    for (uint32_t v : t.v) poly_vertices[t.polygon].insert(v);
  int wrong_face = 0, crossing = 0, checked = 0;
  for (const HatchStroke& h : hr.strokes) {
    const LD len = std::hypot(LD(h.line.b.x - h.line.a.x), LD(h.line.b.y - h.line.a.y));
    if (len < 4) continue;
    for (LD f : {0.3L, 0.5L, 0.7L}) {
      const LD px = h.line.a.x + f * (h.line.b.x - h.line.a.x),
               py = h.line.a.y + f * (h.line.b.y - h.line.a.y);
      bool near_edge = false;
      const int t = nearest(s, px, py, &near_edge);
      if (near_edge) continue;
      ++checked;
      if (t < 0 || s.triangles[size_t(t)].polygon != h.polygon) ++wrong_face;
    }
    // No visible edge of another face crosses it (a step of slack at both ends of both). Its
    // own polygon's sides are where its ends were rounded to: near them it may overshoot by
    // half a step, which along a line almost parallel to the side is more than a step.
    for (const SolidPiece& p : qi.pieces) {
      if (p.hidden) continue;
      const uint32_t ea = s.edge_pairs[2 * p.edge], eb = s.edge_pairs[2 * p.edge + 1];
      if (poly_vertices[h.polygon].count(ea) && poly_vertices[h.polygon].count(eb)) continue;
      const Edge3& e = qi.edges[p.edge];
      const LD t0 = std::ldexp(LD(p.t0), -32), t1 = std::ldexp(LD(p.t1), -32);
      const LD ax = e.a.x + t0 * (e.b.x - e.a.x), ay = e.a.y + t0 * (e.b.y - e.a.y);
      const LD bx = e.a.x + t1 * (e.b.x - e.a.x), by = e.a.y + t1 * (e.b.y - e.a.y);
      const LD plen = std::hypot(bx - ax, by - ay);
      if (plen < 3) continue;
      // A stroke's ends are rounded to steps: one that reaches an edge may poke through it by
      // half a step. A crossing counts only when both ends are over a step from the edge's line.
      const LD da = ((h.line.a.x - ax) * (by - ay) - (h.line.a.y - ay) * (bx - ax)) / plen;
      const LD db = ((h.line.b.x - ax) * (by - ay) - (h.line.b.y - ay) * (bx - ax)) / plen;
      if (std::min(std::fabs(da), std::fabs(db)) > 1.0L &&
          proper_cross(h.line.a.x, h.line.a.y, h.line.b.x, h.line.b.y, ax, ay, bx, by, 0,
                       1.5L / plen)) {
        if (++crossing <= 2)
          std::fprintf(stderr,
                       "  stroke poly %u (%d,%d)-(%d,%d) crosses edge %u (%d,%d,%d)-(%d,%d,%d) "
                       "piece %.4Lf..%.4Lf\n",
                       h.polygon, h.line.a.x, h.line.a.y, h.line.b.x, h.line.b.y, p.edge, e.a.x,
                       e.a.y, e.a.z, e.b.x, e.b.y, e.b.z, t0, t1);
      }
    }
  }
  CHECK_MSG(checked > 0, label + ": points checked");
  CHECK_MSG(wrong_face == 0, label + ": " + std::to_string(wrong_face) + " of " +
                                 std::to_string(checked) + " points not on the nearest face");
  CHECK_MSG(crossing == 0,
            label + ": " + std::to_string(crossing) + " strokes cross a visible edge");
}

// Two squares on paper, each one polygon of two triangles, both facing the viewer.
void square(SolidScene* s, int32_t x0, int32_t y0, int32_t x1, int32_t y1, int32_t z,
            uint32_t polygon) {
  const uint32_t b = uint32_t(s->vertices.size());
  s->vertices.push_back({x0, y0, z});
  s->vertices.push_back({x1, y0, z});
  s->vertices.push_back({x1, y1, z});
  s->vertices.push_back({x0, y1, z});
  s->triangles.push_back(Triangle{{b, b + 1, b + 2}, polygon});
  s->triangles.push_back(Triangle{{b, b + 2, b + 3}, polygon});
  for (uint32_t k = 0; k < 4; ++k) {
    s->edge_pairs.push_back(b + k);
    s->edge_pairs.push_back(b + (k + 1) % 4);
  }
}

// A face that exactly covers grid cells (its corners on cell corners): it blocks the cell it
// holds strictly (the centre of 3 x 3; the four-corner test is strict, so a cell whose border
// lies on the face's side is not blocked and keeps the cuts on that border), the face behind it
// inside that cell is deleted, and the regions and hatching stay right. The grid depends on the
// scene, so the front square is moved until it sits on the grid the run chose.
void exact_cell_cover() {
  int32_t cell = 1000;
  SolidScene s;
  FranklinRun fr;
  FranklinParams fine;
  fine.c_q8 = 4 * 256;  // c = 4: enough cells for a 3 x 3 block inside the background
  for (int i = 0; i < 6; ++i) {
    s = SolidScene{};
    square(&s, 0, 0, 8000, 8000, 100, 0);                // background
    square(&s, cell, cell, 4 * cell, 4 * cell, 900, 1);  // exactly on the grid
    square(&s, 2 * cell + cell / 4, 2 * cell + cell / 4, 3 * cell - 7, 3 * cell - 7, 500,
           2);                                   // behind, inside the centre cell
    square(&s, 5000, 5000, 7000, 6000, 600, 3);  // a fourth, elsewhere
    CHECK(run_franklin(s, fine, &fr) == Status::kOk);
    const int32_t next = (8000 + 1 + int32_t(fr.stats.b) - 1) / int32_t(fr.stats.b);
    if (next == cell) break;
    cell = next;
  }
  const Grid g = grid_over(s.vertices.data(), uint32_t(s.vertices.size()), fr.stats.b);
  CHECK_MSG(g.cell == cell && g.ox == 0 && g.oy == 0, "the front square sits on the grid");
  CHECK_MSG(fr.stats.blocking_cells >= 1,
            "the strictly covered cell is blocked: " + std::to_string(fr.stats.blocking_cells));
  CHECK_MSG(fr.stats.faces_deleted >= 2, "the square behind it is deleted (both halves): " +
                                             std::to_string(fr.stats.faces_deleted));
  for (const FranklinPiece& p : fr.pieces)
    if (p.edge >= 8 && p.edge < 12) CHECK_MSG(p.hidden, "the deleted square's edges are hidden");
  HatchParams hp;
  hp.spacing = 97;
  hp.mdeg_per_depth = 0;
  // Not 45 degrees: a line lying exactly on a square's diagonal is lost by the per-face method
  // (the regions method draws it), and the comparison of the two would fail on that alone.
  hp.angle_mdeg = 30000;
  check_scene(s, hp, "face exactly covering cells");
}

}  // namespace

int main() {
  exact_cell_cover();
  {
    // Straight on: the boxes' sides are edge-on, the touching boxes share coplanar faces and
    // meet along cell borders.
    Mesh m;
    box(&m, 0, 0, 0, 4000, 4000, 4000);
    box(&m, 4000, 0, 0, 8000, 4000, 4000);         // touching face to face
    box(&m, 2000, 4000, -2000, 6000, 8000, 2000);  // coplanar front with the others' tops
    box(&m, 1000, 1000, 5000, 3000, 3000, 7000);   // in front
    for (const auto& [a, e] :
         std::vector<std::pair<int32_t, int32_t>>{{0, 0}, {90000, 0}, {0, 90000}, {45000, 0}}) {
      SolidScene s;
      if (!project(m, view(a, e), &s)) continue;
      HatchParams hp;
      hp.spacing = 110;
      check_scene(s, hp, "straight-on boxes view " + std::to_string(a) + "," + std::to_string(e));
    }
  }

  std::mt19937 rng(11);
  std::uniform_int_distribution<int32_t> az(-180000, 180000), el(-80000, 80000);
  std::vector<std::pair<std::string, Mesh>> meshes;
  {
    Mesh m;
    box(&m, 0, 0, 0, 2000, 2000, 2000);
    box(&m, 1000, -3000, 1000, 3000, -1000, 3000);
    meshes.push_back({"pair of cubes", m});
  }
  {
    Mesh m;
    torus(&m, 0, 0, 0, 20000, 7000, 24, 12);
    torus(&m, 20000, 0, 0, 20000, 7000, 24, 12, true);
    meshes.push_back({"linked tori", m});
  }
  {
    Mesh m;
    sphere(&m, 0, 0, 0, 20000, 8, 16);
    sphere(&m, 30000, 10000, 12000, 9000, 8, 16);
    meshes.push_back({"spheres", m});
  }
  {
    Mesh m;
    frame(&m, 0, 0, 10000, 4000, 0, 3000);
    frame(&m, 3000, 3000, 9000, 5000, 6000, 8000);
    meshes.push_back({"frames", m});
  }
  for (const auto& [name, m] : meshes)
    for (int i = 0; i < 4; ++i) {
      const View v = i == 0 ? view(30000, 25000) : view(az(rng), el(rng));
      SolidScene s;
      if (!project(m, v, &s)) continue;
      HatchParams hp;
      hp.spacing = 150;
      hp.angle_mdeg = 20000 * i;
      hp.mdeg_per_depth = 180000;
      check_scene(s, hp,
                  name + " view " + std::to_string(v.azimuth_mdeg) + "," +
                      std::to_string(v.elevation_mdeg));
    }
  return check::finish("hatch");
}
