// Solids that pass through each other (issue 18): an edge's visibility changes where it passes
// through a face, which nothing on paper marks. Checked two ways:
//   - pierce_q32 (core/solid/pierce.h) against the same question in __int128 on random
//     segments and triangles, every position exact;
//   - face_crossing (core/solid/face_crossing.h) against a triangle-triangle intersection in
//     double on random pairs: each end within a unit (the rounding), none missing where the
//     reference's segment is over two units long on paper (touching pairs of the small range
//     aside; a segment that rounds to a point on paper is not drawn);
//   - two overlapping boxes (closed, and one of them open), a sphere through a torus, plotted
//     hidden-line, every drawn edge's visible length against ray casts
//     (tests/reference/ray_cast.h) of the 3-D model
//     and of the core's own rounded scene: on paper within 0.1 step on every edge (where the
//     edge lies exactly along an occluder's side on paper the cast grazes, and the 3-D model
//     decides alone), against the model within one step on every edge (the scenes fitted in
//     the default sub-step units; in whole steps a few grazing edges of the torus missed).
//     The QI settles them (it stops where edges pass through faces:
//     core/include/haloplot/solid/qi.h), and so does the fallback; the control, QI from what paper
//     alone shows, must fail the comparison.
//   - the intersection lines (core/include/haloplot/solid/intersection_lines.h) against the same
//   scenes' lines
//     found here in double precision: every pair of triangles without a shared vertex id
//     crossed in view space (a triangle-triangle intersection written out below), and each
//     segment's visible length ray cast with its two faces left out. Per pair of faces, the
//     visible length on paper within one step; no line the reference sees for over a step is
//     missing. The controls: with the lines switched off they are missing, and a plot that drew
//     every crossing whole (the reference's whole lengths as its drawing) fails the per-pair
//     comparison.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "../check.h"
#include "haloplot/view/projection.h"
#include "reference/ray_cast.h"
#include "solid/face_crossing.h"
#include "solid/pierce.h"
#include "support/solid_scenes.h"

using namespace haloplot;
using namespace haloplot::host;
using namespace solid_scenes;

namespace {

int g_cases = 200000;  // random cases per coordinate range

using i128 = __int128;

// The reference: the same definition, written out in __int128 with a plain division.
int64_t pierce_reference(const Point3& a, const Point3& b, const Point3& A, const Point3& B,
                         const Point3& C) {
  const i128 ux = B.x - A.x, uy = B.y - A.y, uz = B.z - A.z;
  const i128 vx = C.x - A.x, vy = C.y - A.y, vz = C.z - A.z;
  const i128 nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  if (nz == 0) return -1;
  auto g = [&](const Point3& p) { return nx * (p.x - A.x) + ny * (p.y - A.y) + nz * (p.z - A.z); };
  const i128 ga = g(a), gb = g(b);
  if (ga == 0 || gb == 0 || (ga > 0) == (gb > 0)) return -1;
  const i128 n = ga > 0 ? ga : -ga, d = n + (gb > 0 ? gb : -gb);
  // Inside on paper: the point (a d + (b - a) n) / d against each side.
  const Point3* c[3] = {&A, &B, &C};
  for (int s = 0; s < 3; ++s) {
    const Point3 &p0 = *c[s], &p1 = *c[(s + 1) % 3];
    const i128 px = i128(a.x) * d + i128(b.x - a.x) * n, py = i128(a.y) * d + i128(b.y - a.y) * n;
    const i128 o =
        i128(p1.x - p0.x) * (py - i128(p0.y) * d) - i128(p1.y - p0.y) * (px - i128(p0.x) * d);
    if (o != 0 && (o > 0) != (nz > 0)) return -1;
  }
  return int64_t((n << 32) / d);
}

void random_pierces() {
  std::mt19937_64 rng(1818);
  size_t hits = 0, total = 0;
  for (int range : {16, 1000, kCoordMax}) {
    std::uniform_int_distribution<int32_t> c(0, range);
    for (int i = 0; i < g_cases; ++i) {
      const Point3 p[5] = {{c(rng), c(rng), c(rng)},
                           {c(rng), c(rng), c(rng)},
                           {c(rng), c(rng), c(rng)},
                           {c(rng), c(rng), c(rng)},
                           {c(rng), c(rng), c(rng)}};
      const int64_t ours = pierce_q32(p[0], p[1], p[2], p[3], p[4]);
      const int64_t theirs = pierce_reference(p[0], p[1], p[2], p[3], p[4]);
      ++total;
      if (theirs >= 0) ++hits;
      if (ours != theirs) {
        CHECK_MSG(false, "pierce at range " + std::to_string(range) + ": " + std::to_string(ours) +
                             " vs " + std::to_string(theirs));
        return;
      }
    }
  }
  std::printf("pierce_q32: %zu random cases, %zu pierce, all equal to __int128\n", total, hits);
  CHECK(hits * 20 > total);  // about 9 % pierce
}

// More changes of visibility than this along one edge: the on-paper cast grazes a face's side.
constexpr int64_t kFlicker = 16;

struct Model {
  std::string name;
  Mesh mesh;
  bool open = false;
};

std::vector<Model> models() {
  std::vector<Model> out;
  {
    Model m{"overlapping boxes", {}};
    box(&m.mesh, -200000, -200000, -200000, 60000, 60000, 60000);
    box(&m.mesh, -60000, -90000, -30000, 200000, 170000, 230000);
    out.push_back(m);
  }
  {
    Model m{"sphere through a torus", {}};
    torus(&m.mesh, 0, 0, 0, 150000, 50000, 32, 12);
    sphere(&m.mesh, 150000, 0, 20000, 80000, 12, 24);
    out.push_back(m);
  }
  {  // open: both sides of every face show, so crossings on faces turned away are asked too
    Model m{"an open box through a box", {}};
    box(&m.mesh, -200000, -200000, -200000, 60000, 60000, 60000);
    box(&m.mesh, -60000, -90000, -30000, 200000, 170000, 230000);
    m.mesh.faces.erase(m.mesh.faces.begin() + 9);  // the second box's y1 side
    m.open = true;
    out.push_back(m);
  }
  return out;
}

struct Result {
  size_t edges = 0, over = 0, paper_over = 0, flicker = 0;
  double worst = 0, paper_worst = 0;
  bool used_qi = false;
  std::string method;
  uint64_t pierces = 0;
};

// The reference's intersection line of two triangles in view space: each triangle's part in
// the other's plane, as an interval along the line where the planes meet; their overlap.
using ray_cast::V3;
bool triangle_crossing(const V3 p[3], const V3 q[3], V3* s0, V3* s1) {
  auto part_in_plane = [](const V3 t[3], const V3 o[3], V3 pts[3]) {
    const V3 n = ray_cast::cross(ray_cast::sub(o[1], o[0]), ray_cast::sub(o[2], o[0]));
    double d[3];
    for (int k = 0; k < 3; ++k) d[k] = ray_cast::dot(n, ray_cast::sub(t[k], o[0]));
    if ((d[0] > 0 && d[1] > 0 && d[2] > 0) || (d[0] < 0 && d[1] < 0 && d[2] < 0)) return 0;
    if (d[0] == 0 && d[1] == 0 && d[2] == 0) return 0;  // coplanar: no line
    int m = 0;
    for (int k = 0; k < 3 && m < 3; ++k) {
      const int j = (k + 1) % 3;
      if (d[k] == 0) pts[m++] = t[k];
      if ((d[k] < 0 && d[j] > 0) || (d[k] > 0 && d[j] < 0)) {
        const double u = d[k] / (d[k] - d[j]);
        pts[m++] = V3{t[k].x + u * (t[j].x - t[k].x), t[k].y + u * (t[j].y - t[k].y),
                      t[k].d + u * (t[j].d - t[k].d)};
      }
    }
    return m;
  };
  V3 a[3], b[3];
  const int na = part_in_plane(p, q, a), nb = part_in_plane(q, p, b);
  if (na < 2 || nb < 2) return false;
  const V3 dir =
      ray_cast::cross(ray_cast::cross(ray_cast::sub(p[1], p[0]), ray_cast::sub(p[2], p[0])),
                      ray_cast::cross(ray_cast::sub(q[1], q[0]), ray_cast::sub(q[2], q[0])));
  auto s = [&](const V3& x) { return ray_cast::dot(dir, x); };
  auto lo_hi = [&](const V3* pts, int n, V3* lo, V3* hi) {
    *lo = *hi = pts[0];
    for (int k = 1; k < n; ++k) {
      if (s(pts[k]) < s(*lo)) *lo = pts[k];
      if (s(pts[k]) > s(*hi)) *hi = pts[k];
    }
  };
  V3 alo, ahi, blo, bhi;
  lo_hi(a, na, &alo, &ahi);
  lo_hi(b, nb, &blo, &bhi);
  *s0 = s(alo) > s(blo) ? alo : blo;
  *s1 = s(ahi) < s(bhi) ? ahi : bhi;
  return s(*s0) <= s(*s1);  // a point too: a segment shorter than a unit may round to one
}

// face_crossing against triangle_crossing on random pairs (z as the depth).
void random_crossings() {
  std::mt19937_64 rng(2718);
  size_t found = 0, compared = 0;
  auto v3 = [](const Point3& p) { return V3{double(p.x), double(p.y), double(p.z)}; };
  auto near = [](const Point3& a, const V3& b) {
    return std::fabs(a.x - b.x) <= 1.0 && std::fabs(a.y - b.y) <= 1.0 &&
           std::fabs(a.z - b.d) <= 1.0;
  };
  for (int range : {16, 1000, kCoordMax}) {
    std::uniform_int_distribution<int32_t> c(0, range);
    for (int i = 0; i < g_cases; ++i) {
      Point3 p[3], q[3];
      for (Point3& x : p) x = Point3{c(rng), c(rng), c(rng)};
      for (Point3& x : q) x = Point3{c(rng), c(rng), c(rng)};
      Edge3 ours;
      const bool hit = face_crossing(p, q, &ours);
      const V3 vp[3] = {v3(p[0]), v3(p[1]), v3(p[2])}, vq[3] = {v3(q[0]), v3(q[1]), v3(q[2])};
      V3 a, b;
      const bool ref = triangle_crossing(vp, vq, &a, &b);
      const double len = ref ? std::hypot(b.x - a.x, b.y - a.y) : 0;  // on paper
      found += hit;
      if (!hit) {
        // The small range has pairs that only touch along a side: no line, by definition.
        if (ref && len > 2.0 && range > 16) {
          CHECK_MSG(false, "face_crossing missed a segment " + std::to_string(len) + " long");
          return;
        }
        continue;
      }
      ++compared;
      const bool same =
          ref && ((near(ours.a, a) && near(ours.b, b)) || (near(ours.a, b) && near(ours.b, a)));
      if (!same) {
        CHECK_MSG(false, "face_crossing at range " + std::to_string(range) +
                             " is not the reference's segment");
        return;
      }
    }
  }
  std::printf("face_crossing: %zu random pairs crossed, every end within a unit of double\n",
              compared);
  CHECK(found * 10 > size_t(3) * size_t(g_cases));  // about a quarter cross
}

struct LineResult {
  size_t reference = 0, ours = 0, missing = 0, over = 0;
  size_t whole_over = 0;  // the control: pairs a plot drawing every crossing whole would fail
  double worst = 0, reference_visible = 0, ours_visible = 0;
};

// Our intersection lines against the reference's, per pair of faces.
LineResult compare_lines(const SolidScene& scene, const SolidRun& run,
                         const ray_cast::Scene& truth) {
  using Key = std::pair<uint32_t, uint32_t>;
  std::map<Key, double> ours, theirs;
  const double unit = std::ldexp(1.0, -scene.substep_bits);
  for (size_t i = 0; i < run.intersections.size(); ++i) {
    const SolidPiece& p = run.intersections[i];
    const auto& f = run.intersection_faces[i];
    const Edge3& e = run.edges[p.edge];
    const double len = std::hypot(double(e.b.x - e.a.x), double(e.b.y - e.a.y)) * unit;
    double& seen = ours[Key(std::min(f[0], f[1]), std::max(f[0], f[1]))];
    if (!p.hidden) seen += double(p.t1 - p.t0) / 4294967296.0 * len;
  }
  LineResult r;
  r.ours = ours.size();
  const std::vector<Triangle>& tris = scene.triangles;
  auto corner = [&](uint32_t t, int k) { return truth.vertex(tris[t].v[k]); };
  for (uint32_t i = 0; i < tris.size(); ++i) {
    const V3 p[3] = {corner(i, 0), corner(i, 1), corner(i, 2)};
    for (uint32_t j = i + 1; j < tris.size(); ++j) {
      bool shared = false;
      for (uint32_t u : tris[i].v)
        for (uint32_t w : tris[j].v) shared = shared || u == w;
      if (shared) continue;
      const V3 q[3] = {corner(j, 0), corner(j, 1), corner(j, 2)};
      V3 a, b;
      if (!triangle_crossing(p, q, &a, &b)) continue;
      double length = 0;
      const double seen = truth.segment_visible_length(
          a, b, [&](uint32_t k, const Triangle&) { return k == i || k == j; }, &length);
      if (length < 1e-9) continue;
      ++r.reference;
      theirs[Key(i, j)] = seen;
      if (length - seen > 1.0) ++r.whole_over;
    }
  }
  std::map<Key, double> all = ours;
  for (const auto& t : theirs) all.emplace(t.first, 0.0);
  for (const auto& k : all) {
    const double a = ours.count(k.first) ? ours[k.first] : 0.0;
    const double b = theirs.count(k.first) ? theirs[k.first] : 0.0;
    r.ours_visible += a;
    r.reference_visible += b;
    if (b > 1.0 && !ours.count(k.first)) ++r.missing;
    const double diff = std::fabs(a - b);
    if (diff > 1.0) ++r.over;
    r.worst = std::max(r.worst, diff);
  }
  return r;
}

Result compare(const Model& m, const View& v, HiddenMethod method = HiddenMethod::kAuto,
               LineResult* lines = nullptr) {
  Result r;
  SolidScene scene;
  CHECK(project(m.mesh, v, &scene));
  SolidRun run;
  CHECK(run_hidden_lines(scene, method, FallbackParams{}, &run, false, lines != nullptr) ==
        Status::kOk);
  // The lines come in the order of their two faces, numbered so, whatever grid's cells found
  // them (the face grid's cells change with the faces' sizes; the lines do not).
  size_t out_of_order = 0;
  for (size_t i = 1; i < run.intersections.size(); ++i) {
    const auto &f = run.intersection_faces[i - 1], &g = run.intersection_faces[i];
    const uint32_t e = run.intersections[i - 1].edge, d = run.intersections[i].edge;
    if (!(f < g ? e < d : f == g && e == d)) ++out_of_order;
  }
  CHECK_MSG(out_of_order == 0, m.name + ": " + std::to_string(out_of_order) +
                                   " intersection pieces out of their faces' order");
  r.used_qi = run.used_qi;
  r.method = run.used_qi ? "QI" : "fallback (" + run.fallback_reason + ")";
  r.pierces = run.used_qi ? run.qi.pierces : run.fallback.pierces;
  std::vector<double> share(scene.edge_pairs.size() / 2, 0.0);
  for (const SolidPiece& p : run.pieces)
    if (!p.hidden && p.edge < share.size()) share[p.edge] += double(p.t1 - p.t0) / 4294967296.0;
  const ray_cast::Scene truth(ray_cast::camera(v, m.mesh.v), m.mesh.v, scene.triangles);
  if (lines != nullptr) *lines = compare_lines(scene, run, truth);
  const ray_cast::Scene paper(ray_cast::on_paper(v.substep_bits), scene.vertices, scene.triangles);
  for (uint32_t e = 0; e < share.size(); ++e) {
    const uint32_t i = scene.edge_pairs[2 * e], j = scene.edge_pairs[2 * e + 1];
    double length = 0, paper_length = 0;
    const double theirs = truth.visible_length(i, j, &length);
    int64_t changes = 0;
    const double on_paper = paper.visible_length(i, j, &paper_length, &changes);
    const double diff = std::fabs(share[e] * length - theirs);
    const double paper_diff = std::fabs(share[e] * paper_length - on_paper);
    ++r.edges;
    if (diff > 1.0) ++r.over;
    r.worst = std::max(r.worst, diff);
    if (changes > kFlicker) {  // on paper it runs along another face's side: undecided there
      ++r.flicker;
      continue;
    }
    // An edge exactly along an occluder's side on paper (rounding can make them collinear)
    // grazes every cast ray: there the 3-D model decides alone.
    if (paper_diff > 0.1 && diff > 1.0) ++r.paper_over;
    r.paper_worst = std::max(r.paper_worst, paper_diff);
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  // `small` (the sanitizer build): a tenth of the random cases and the first two views.
  const bool small = argc > 1 && std::string(argv[1]) == "small";
  if (small) g_cases = 20000;
  random_pierces();
  random_crossings();
  const int32_t views[][3] = {{30000, 25000, 0},
                              {-50000, 40000, 0},
                              {200000, -15000, 0},
                              {30000, 25000, 700000},
                              {120000, 60000, 900000}};
  for (const Model& m : models()) {
    for (const auto& a : views) {
      if (small && &a - views >= 2) break;
      View v = view(a[0], a[1]);
      v.perspective = a[2];
      v.substep_bits = kDefaultSubstepBits;
      LineResult lines;
      const Result r = compare(m, v, HiddenMethod::kAuto, &lines);
      std::printf(
          "%s at %d,%d%s: %s, %llu pierces; %zu edges, against 3-D worst %.3f steps, %zu over 1 "
          "step; on paper worst %.4f (%zu edges along a face's side left out)\n",
          m.name.c_str(), a[0] / 1000, a[1] / 1000, a[2] ? " perspective" : "", r.method.c_str(),
          (unsigned long long)r.pierces, r.edges, r.worst, r.over, r.paper_worst, r.flicker);
      const std::string where = m.name + " at " + std::to_string(a[0] / 1000) + "," +
                                std::to_string(a[1] / 1000) + (a[2] ? " perspective: " : ": ");
      CHECK_MSG(r.used_qi && r.pierces > 0, where + "the QI should stop where edges pierce");
      CHECK_MSG(r.paper_over == 0, where + std::to_string(r.paper_over) +
                                       " edges differ from the ray cast of the rounded scene");
      CHECK_MSG(r.flicker * 50 <= r.edges, where + "too many edges left out on paper");
      // In the default sub-step units every edge, the curved surfaces' grazing ones too,
      // agrees with the 3-D model within a step (in whole steps a few of the torus's did not).
      CHECK_MSG(r.over == 0,
                where + std::to_string(r.over) + " edges differ from the 3-D model by over a step");
      std::printf(
          "  intersection lines: %zu pairs of faces cross (reference), %zu drawn; visible %.1f "
          "steps (reference %.1f); per pair worst %.3f steps, %zu over 1, %zu missing; every "
          "crossing drawn whole (the control): %zu over 1\n",
          lines.reference, lines.ours, lines.ours_visible, lines.reference_visible, lines.worst,
          lines.over, lines.missing, lines.whole_over);
      CHECK_MSG(lines.reference > 0, where + "the scene should have intersection lines");
      CHECK_MSG(lines.missing == 0, where + std::to_string(lines.missing) + " lines missing");
      CHECK_MSG(lines.over == 0,
                where + std::to_string(lines.over) +
                    " intersection lines differ from the reference by over a step");
      CHECK_MSG(lines.whole_over > 0, where + "drawing every crossing whole went unnoticed");
    }
    {  // and a missing line: the same scene with the lines switched off.
      View v = view(views[0][0], views[0][1]);
      v.substep_bits = kDefaultSubstepBits;
      SolidScene scene;
      CHECK(project(m.mesh, v, &scene));
      SolidRun off;
      CHECK(run_hidden_lines(scene, HiddenMethod::kAuto, FallbackParams{}, &off) == Status::kOk);
      const ray_cast::Scene truth(ray_cast::camera(v, m.mesh.v), m.mesh.v, scene.triangles);
      const LineResult c = compare_lines(scene, off, truth);
      std::printf("%s with the lines off (the control): %zu missing\n", m.name.c_str(), c.missing);
      CHECK_MSG(c.missing > 0, m.name + ": missing intersection lines went unnoticed");
    }
    // The control: QI propagation alone knows nothing of faces passing through each other.
    View v = view(views[0][0], views[0][1]);
    const Result c = compare(m, v, HiddenMethod::kQiPaperOnly);
    std::printf("%s at 30,25, QI from paper alone (the control): %s, %zu edges over 1 step\n",
                m.name.c_str(), c.method.c_str(), c.over);
    // And the topology-free method agrees too (in sub-steps, as above).
    v.substep_bits = kDefaultSubstepBits;
    const Result f = compare(m, v, HiddenMethod::kFallback);
    CHECK_MSG(f.over == 0 && f.pierces > 0,
              m.name + ": the fallback: " + std::to_string(f.over) + " edges over 1 step");
    CHECK_MSG(c.over > 0, m.name + ": the comparison does not see edges through faces");
  }
  return check::finish("intersecting");
}
