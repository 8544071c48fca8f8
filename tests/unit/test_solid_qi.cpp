// Appel/Heger QI propagation against the topology-free fallback (Franklin's midpoint tests),
// on every manifold test scene the issue names: cube arrays, spheres and tori at several
// resolutions, concave solids with holes (a frame, an L-block, a stair), under many rotations
// and in perspective. The two methods share only CUT's crossings and the exact cover
// predicate; one carries counts along the mesh, the other asks every face in a grid cell.
//
// The propagation in parts (qi.h's QiSplit) must give the QI of one part exactly: with every
// vertex a part of its own, each vertex is seeded by its own ray cast and every walk checked
// against the cast at its far end (no conflict allowed); with parts of 7 vertices run on three
// threads, the pieces and outlines of one part, byte for byte.
//
// They must agree exactly: at the middle of every piece the fallback tests, the QI the
// propagation gave that point equals the count the fallback found (both in halves). The
// visible length per edge then agrees to far better than the 1 step the issue allows; that is
// checked too. The Kira shortcuts (classes, V.C.) must not change any visibility.
#include <cstdio>
#include <random>
#include <string>

#include "check.h"
#include "pipeline/surface_pipeline.h"
#include "pipeline/thread_parts.h"
#include "solid/cover.h"
#include "support/solid_refs.h"
#include "support/solid_scenes.h"

using namespace haloplot;
using namespace haloplot::host;
using namespace solid_scenes;

namespace {

// The QI the propagation gave edge e at position m (Q0.32), from its pieces.
int32_t qi_at(const std::vector<SolidPiece>& pieces, const std::vector<size_t>& first, uint32_t e,
              int64_t m) {
  for (size_t k = first[e]; k < first[e + 1]; ++k)
    if (pieces[k].t0 <= m && m < pieces[k].t1) return pieces[k].q;
  return kQiUnknown;
}

std::vector<size_t> index_by_edge(const std::vector<SolidPiece>& p, size_t n_edges) {
  std::vector<size_t> first(n_edges + 1, 0);
  for (const auto& x : p) ++first[x.edge + 1];
  for (size_t e = 0; e < n_edges; ++e) first[e + 1] += first[e];
  return first;
}

struct Totals {
  uint64_t scenes = 0, pieces = 0, edges = 0;
  QiStats qi;
  uint64_t vc_saved = 0, tests_with = 0, tests_without = 0, class_saved = 0;
  uint64_t split_ray_casts = 0;  // with every vertex a part: a cast each, checked by the walks
  uint64_t outline_tests = 0, outline_segments = 0, circuits = 0, one_by_one = 0;
  uint64_t franklin_deleted_faces = 0, franklin_culled = 0;
} totals;

// Visible length of edge e in steps (pieces with hidden == false), from positions.
double visible_length(const std::vector<SolidPiece>& p, const std::vector<size_t>& first,
                      uint32_t e, const Edge3& ed) {
  const double len = std::hypot(double(ed.b.x - ed.a.x), double(ed.b.y - ed.a.y));
  double sum = 0;
  for (size_t k = first[e]; k < first[e + 1]; ++k)
    if (!p[k].hidden) sum += double(p[k].t1 - p[k].t0) / 4294967296.0 * len;
  return sum;
}

// Kira's outlines against their definition, by brute force: a point is on an outline exactly
// when the picture's faces (any facing, any depth) lie on one side of it and not on the other.
// Every face is asked on both sides of: the middle of every traced outline segment (none may
// be wrong), and 4 points of every edge (each on the boundary must lie on a traced segment,
// of whichever edge: collinear edges share one outline).
using solid_refs::on_boundary;

void check_outlines(const SolidScene& scene, const SolidRun& qi, const std::string& label) {
  int wrong = 0;
  for (const auto& o : qi.outline) {
    if (o.t1 - o.t0 < 2) continue;
    if (!on_boundary(scene, qi.edges[o.edge], o.t0 + (o.t1 - o.t0) / 2) && ++wrong <= 3)
      CHECK_MSG(false, label + ": traced outline on edge " + std::to_string(o.edge) + " [" +
                           std::to_string(o.t0) + ", " + std::to_string(o.t1) +
                           ") is not on the picture's boundary");
  }
  for (uint32_t e = 0; e < qi.edges.size(); ++e) {
    const Edge3& ed = qi.edges[e];
    if (ed.a.x == ed.b.x && ed.a.y == ed.b.y) continue;
    for (int k = 0; k < 4; ++k) {
      const int64_t m = (int64_t(2 * k + 1) << 32) / 8 + 12345;
      if (!on_boundary(scene, ed, m)) continue;
      const double px = ed.a.x + (ed.b.x - ed.a.x) * std::ldexp(double(m), -32);
      const double py = ed.a.y + (ed.b.y - ed.a.y) * std::ldexp(double(m), -32);
      bool found = false;
      for (const auto& o : qi.outline) {
        const Edge3& oe = qi.edges[o.edge];
        const double ox = oe.b.x - oe.a.x, oy = oe.b.y - oe.a.y, l2 = ox * ox + oy * oy;
        const double t = ((px - oe.a.x) * ox + (py - oe.a.y) * oy) / l2;
        const double dist = std::fabs((px - oe.a.x) * oy - (py - oe.a.y) * ox) / std::sqrt(l2);
        if (dist < 1e-3 && t >= std::ldexp(double(o.t0), -32) - 1e-9 &&
            t <= std::ldexp(double(o.t1), -32) + 1e-9)
          found = true;
      }
      if (!found && ++wrong <= 3)
        CHECK_MSG(false, label + ": edge " + std::to_string(e) + " at t=" + std::to_string(m) +
                             " is on the picture's boundary but on no traced outline");
    }
  }
  CHECK_MSG(wrong == 0, label + ": " + std::to_string(wrong) + " outline samples wrong");
  totals.outline_tests += qi.outline_stats.condition_tests;
  totals.outline_segments += qi.outline_stats.unit_segments;
  totals.circuits += qi.outline_stats.circuits;
  totals.one_by_one += qi.outline_stats.one_by_one;
}

bool same_pieces(const std::vector<SolidPiece>& a, const std::vector<SolidPiece>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].edge != b[i].edge || a[i].t0 != b[i].t0 || a[i].t1 != b[i].t1 || a[i].q != b[i].q ||
        a[i].hidden != b[i].hidden)
      return false;
  return true;
}

void split_agrees(const SolidScene& scene, const SolidRun& whole, const std::string& label) {
  for (const uint32_t part_vertices : {1u, 7u}) {
    SolidRun split;
    const Parts* parts = part_vertices == 7 ? thread_parts(3) : nullptr;
    const Status s = run_hidden_lines(scene, HiddenMethod::kQi, FallbackParams{}, &split, true,
                                      false, nullptr, parts, part_vertices);
    const std::string what = label + ", parts of " + std::to_string(part_vertices) + " vertices";
    CHECK_MSG(s == Status::kOk, what + ": " + status_name(s));
    if (s != Status::kOk) continue;
    CHECK_MSG(split.qi.conflicts == 0,
              what + ": " + std::to_string(split.qi.conflicts) + " conflicts");
    CHECK_MSG(split.qi.edges_walked == whole.qi.edges_walked,
              what + ": walked " + std::to_string(split.qi.edges_walked) + " edges, one part " +
                  std::to_string(whole.qi.edges_walked));
    CHECK_MSG(same_pieces(split.pieces, whole.pieces) &&
                  same_pieces(split.contour_diagonals, whole.contour_diagonals),
              what + ": pieces differ from one part's");
    bool outline_same = split.outline.size() == whole.outline.size();
    for (size_t i = 0; outline_same && i < split.outline.size(); ++i)
      outline_same = split.outline[i].edge == whole.outline[i].edge &&
                     split.outline[i].t0 == whole.outline[i].t0 &&
                     split.outline[i].t1 == whole.outline[i].t1;
    CHECK_MSG(outline_same, what + ": outlines differ from one part's");
    if (part_vertices == 1) totals.split_ray_casts += split.qi.ray_casts;
  }
}

void agree(const SolidScene& scene, const std::string& label) {
  SolidRun qi, fb, kira;
  const Status s1 = run_hidden_lines(scene, HiddenMethod::kQi, FallbackParams{}, &qi, true);
  const Status s2 = run_hidden_lines(scene, HiddenMethod::kFallback, FallbackParams{}, &fb);
  FallbackParams k;
  k.use_classes = k.use_vc = true;
  const Status s3 = run_hidden_lines(scene, HiddenMethod::kFallback, k, &kira);
  CHECK_MSG(s1 == Status::kOk && s2 == Status::kOk && s3 == Status::kOk,
            label + ": " + status_name(s1) + " " + status_name(s2) + " " + status_name(s3));
  if (s1 != Status::kOk || s2 != Status::kOk || s3 != Status::kOk) return;
  CHECK_MSG(qi.check.manifold(), label + ": test scenes are closed manifolds");
  CHECK_MSG(qi.qi.conflicts == 0, label + ": " + std::to_string(qi.qi.conflicts) + " conflicts");
  split_agrees(scene, qi, label);
  const size_t n = scene.edge_pairs.size() / 2;
  const auto fq = index_by_edge(qi.pieces, n);
  const auto ff = index_by_edge(fb.pieces, n);
  const auto fk = index_by_edge(kira.pieces, n);
  int mismatches = 0;
  for (const auto& p : fb.pieces) {
    if (p.t1 - p.t0 < 2) continue;  // no Q0.32 position strictly inside (see fallback.h)
    const int64_t m = p.t0 + (p.t1 - p.t0) / 2;
    const int32_t q = qi_at(qi.pieces, fq, p.edge, m);
    if (q != p.q && ++mismatches <= 5)
      CHECK_MSG(false, label + ": edge " + std::to_string(p.edge) + " at t=" + std::to_string(m) +
                           ": QI " + std::to_string(q) + " halves, fallback " +
                           std::to_string(p.q));
    // The Kira shortcuts decide visibility only; it must match.
    bool kh = false;
    for (size_t x = fk[p.edge]; x < fk[p.edge + 1]; ++x)
      if (kira.pieces[x].t0 <= m && m < kira.pieces[x].t1) kh = kira.pieces[x].hidden;
    if (kh != (p.q != 0) && ++mismatches <= 5)
      CHECK_MSG(false, label + ": Kira shortcuts changed edge " + std::to_string(p.edge));
  }
  // Franklin 1980 (steps 2-9, blocking faces, any face hides) must see the same visibility.
  FranklinRun fr;
  const Status s4 = run_franklin(scene, FranklinParams{}, &fr);
  CHECK_MSG(s4 == Status::kOk, label + ": Franklin " + status_name(s4));
  for (const auto& p : fb.pieces) {
    if (p.t1 - p.t0 < 2) continue;
    const int64_t m = p.t0 + (p.t1 - p.t0) / 2;
    bool hidden = false, found = false;
    for (const auto& x : fr.pieces)
      if (x.edge == p.edge && x.t0 <= m && m < x.t1) hidden = x.hidden, found = true;
    if ((!found || hidden != (p.q != 0)) && ++mismatches <= 5)
      CHECK_MSG(false, label + ": Franklin differs on edge " + std::to_string(p.edge) +
                           " at t=" + std::to_string(m) + (found ? "" : " (no piece)"));
  }
  totals.franklin_deleted_faces += fr.stats.faces_deleted;
  totals.franklin_culled += fr.stats.face_cells_culled;
  CHECK_MSG(mismatches == 0, label + ": " + std::to_string(mismatches) + " disagreements");
  double worst = 0;
  for (uint32_t e = 0; e < n; ++e) {
    const double a = visible_length(qi.pieces, fq, e, qi.edges[e]);
    const double b = visible_length(fb.pieces, ff, e, qi.edges[e]);
    worst = std::max(worst, std::fabs(a - b));
  }
  CHECK_MSG(worst <= 1.0, label + ": visible length differs by " + std::to_string(worst));
  if (scene.triangles.size() <= 800) check_outlines(scene, qi, label);
  ++totals.scenes;
  totals.pieces += fb.pieces.size();
  totals.edges += n;
  totals.qi.crossings += qi.qi.crossings;
  totals.qi.wedge += qi.qi.wedge;
  totals.qi.delta += qi.qi.delta;
  totals.qi.quarter += qi.qi.quarter;
  totals.qi.half += qi.qi.half;
  totals.qi.occluded += qi.qi.occluded;
  totals.qi.degenerate += qi.qi.degenerate;
  totals.qi.ray_casts += qi.qi.ray_casts;
  totals.vc_saved += kira.fallback.vc_saved;
  totals.class_saved += kira.fallback.class_saved;
  totals.tests_with += kira.fallback.tests;
  totals.tests_without += fb.fallback.tests;
}

void run_views(const Mesh& m, const std::string& name, std::mt19937* rng, int n_random) {
  // Fixed views, including the axis-aligned ones where faces are edge-on and edges end-on.
  const int32_t fixed[][2] = {{30000, 25000}, {0, 0},     {45000, 35264},
                              {90000, 0},     {0, 90000}, {-60000, -30000}};
  for (const auto& f : fixed) {
    SolidScene s;
    CHECK(project(m, view(f[0], f[1]), &s));
    agree(s, name + " view " + std::to_string(f[0]) + "," + std::to_string(f[1]));
  }
  std::uniform_int_distribution<int32_t> az(-180000, 180000), el(-90000, 90000);
  for (int i = 0; i < n_random; ++i) {
    View v = view(az(*rng), el(*rng));
    if (i % 3 == 2) v.perspective = 3 * 524288;  // after the scale below the model spans ~2^19
    SolidScene s;
    if (!project(m, v, &s)) continue;
    agree(s, name + " random view " + std::to_string(v.azimuth_mdeg) + "," +
                 std::to_string(v.elevation_mdeg) + (v.perspective ? " perspective" : ""));
  }
}

// corner_cover_halves, the QI walk's shortcut for a vertex asked about its own star, against
// cover_halves asked the same question with the triangle started at each of its corners: small
// coordinates, where nudges run along sides and faces stand edge-on or level with the nudge,
// and coordinates near the contract's bound.
void corner_cover_agrees(std::mt19937* rng) {
  uint64_t covered = 0;
  for (int32_t span : {3, 1 << 18}) {
    std::uniform_int_distribution<int32_t> coord(-span, span);
    for (int i = 0; i < 200000; ++i) {
      const Point3 a{coord(*rng), coord(*rng), coord(*rng)};
      const Point3 b{coord(*rng), coord(*rng), coord(*rng)};
      const Point3 c{coord(*rng), coord(*rng), coord(*rng)};
      const int pick = i % 4;  // toward b, toward c, toward a point on b's side, anywhere
      Point3 to = pick == 0 ? b : (pick == 1 ? c : Point3{coord(*rng), coord(*rng), coord(*rng)});
      if (pick == 2) to = Point3{a.x + 2 * (b.x - a.x), a.y + 2 * (b.y - a.y), coord(*rng)};
      if (to.x == a.x && to.y == a.y) continue;  // no nudge on paper: never asked
      const CoverPoint p = vertex_toward(a, to);
      const int fast = corner_cover_halves(a, b, c, p);
      covered += fast != 0;
      CHECK_EQ(fast, cover_halves(a, b, c, p));
      CHECK_EQ(fast, cover_halves(b, c, a, p));
      CHECK_EQ(fast, cover_halves(c, a, b, p));
      if (pick < 2) CHECK_EQ(fast, 0);  // a face never covers a nudge toward its own corner
    }
  }
  CHECK(covered > 1000);  // the cases that cover were asked too
  std::printf("corner cover: %llu of 400000 nudged corners covered\n", (unsigned long long)covered);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string only = argc > 1 ? argv[1] : "";
  std::mt19937 rng(20261122);
  const int n_random = 12;
  if (only.empty() || only == "corner") corner_cover_agrees(&rng);
  if (only.empty() || only == "cubes") {
    for (int n : {1, 2, 4}) {
      Mesh m;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          box(&m, i * 3000, j * 3000, 0, i * 3000 + 2000, j * 3000 + 2000, 2000);
      run_views(m, std::to_string(n) + "x" + std::to_string(n) + " cubes", &rng, n_random);
    }
    Mesh pair;  // the HALO paper's pair of cubes: one partly behind the other
    box(&pair, 0, 0, 0, 2000, 2000, 2000);
    box(&pair, 1000, 1000, 3000, 3000, 3000, 5000);
    run_views(pair, "pair of cubes", &rng, n_random);
  }
  if (only.empty() || only == "spheres") {
    for (int res : {4, 8, 16}) {
      Mesh m;
      sphere(&m, 0, 0, 0, 20000, res, 2 * res);
      sphere(&m, 30000, 10000, 12000, 9000, res, 2 * res);  // apart: QI assumes no piercing
      run_views(m, "spheres " + std::to_string(res), &rng, n_random);
    }
  }
  if (only.empty() || only == "tori") {
    for (int res : {6, 12, 24}) {
      Mesh m;
      torus(&m, 0, 0, 0, 20000, 7000, 2 * res, res);
      torus(&m, 20000, 0, 0, 20000, 7000, 2 * res, res, true);  // linked, never touching
      run_views(m, "tori " + std::to_string(res), &rng, n_random);
    }
  }
  if (only.empty() || only == "concave") {
    Mesh m;
    frame(&m, 0, 0, 10000, 4000, 0, 3000);
    prism(&m, {{12000, 0}, {20000, 0}, {20000, 3000}, {15000, 3000}, {15000, 9000}, {12000, 9000}},
          0, 4000);  // an L-block
    prism(&m,
          {{0, 12000},
           {9000, 12000},
           {9000, 15000},
           {6000, 15000},
           {6000, 18000},
           {3000, 18000},
           {3000, 21000},
           {0, 21000}},
          -2000, 2000);                               // a stair
    frame(&m, 12000, 12000, 9000, 5000, 6000, 8000);  // a frame floating above
    run_views(m, "concave solids", &rng, 3 * n_random);
  }
  std::printf(
      "scenes=%llu edges=%llu pieces=%llu rules: crossings=%llu wedge=%llu delta=%llu "
      "quarter=%llu half=%llu occluded=%llu degenerate=%llu ray_casts=%llu; fallback tests "
      "%llu without Kira, %llu with (V.C. saved %llu, classes %llu pieces)\n",
      (unsigned long long)totals.scenes, (unsigned long long)totals.edges,
      (unsigned long long)totals.pieces, (unsigned long long)totals.qi.crossings,
      (unsigned long long)totals.qi.wedge, (unsigned long long)totals.qi.delta,
      (unsigned long long)totals.qi.quarter, (unsigned long long)totals.qi.half,
      (unsigned long long)totals.qi.occluded, (unsigned long long)totals.qi.degenerate,
      (unsigned long long)totals.qi.ray_casts, (unsigned long long)totals.tests_without,
      (unsigned long long)totals.tests_with, (unsigned long long)totals.vc_saved,
      (unsigned long long)totals.class_saved);
  std::printf(
      "outlines: %llu contour unit segments, %llu circuits, %llu condition tests, "
      "%llu segments asked one by one\n",
      (unsigned long long)totals.outline_segments, (unsigned long long)totals.circuits,
      (unsigned long long)totals.outline_tests, (unsigned long long)totals.one_by_one);
  std::printf("in parts of one vertex: %llu ray casts, each checked against the walks\n",
              (unsigned long long)totals.split_ray_casts);
  std::printf("Franklin: %llu faces deleted by blocking faces, %llu (face, cell) pairs culled\n",
              (unsigned long long)totals.franklin_deleted_faces,
              (unsigned long long)totals.franklin_culled);
  return check::finish("solid_qi");
}
