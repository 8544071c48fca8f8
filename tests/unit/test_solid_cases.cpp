// Hidden lines worked by hand. Every scene is built directly in plot coordinates (x, y on
// paper, z = depth, larger nearer) and seen straight on, which is the hardest view there is:
// side faces are edge-on, depth edges are points, and every back edge lies exactly behind a
// front edge. The expected QI of each edge piece was worked out on paper from the figures in
// the comments; both the QI propagation and the fallback must produce it.
//
// Unit: QI in halves (2 = one front face in front; 1 = lying along a face's side: occluded).
#include <cstdio>
#include <string>
#include <vector>

#include "check.h"
#include "pipeline/drawing_modes.h"
#include "pipeline/surface_pipeline.h"
#include "support/solid_scenes.h"

using namespace haloplot;
using namespace haloplot::host;
using namespace solid_scenes;

namespace {

constexpr int64_t kOne = int64_t{1} << 32;

struct Piece {
  double t0, t1;  // fractions of the edge, from the first point given
  int32_t q;      // halves
};

// Builds the scene the core sees from a mesh already in plot coordinates.
SolidScene plot_scene(const Mesh& m) {
  SolidScene s;
  s.vertices = m.v;
  s.edge_pairs = polygon_edges(m);
  s.triangles = triangulate(m.v, m.faces, nullptr);
  return s;
}

// Checks the pieces of the drawn edge from a to b (x, y, depth) against the hand-worked list,
// at the middle of each expected piece and a quarter of the way into it.
void expect(const SolidScene& s, const SolidRun& r, const std::string& what, Point3 a, Point3 b,
            const std::vector<Piece>& want) {
  const size_t n = s.edge_pairs.size() / 2;
  for (size_t e = 0; e < n; ++e) {
    const Point3 p = s.vertices[s.edge_pairs[2 * e]], q = s.vertices[s.edge_pairs[2 * e + 1]];
    const bool same =
        p.x == a.x && p.y == a.y && p.z == a.z && q.x == b.x && q.y == b.y && q.z == b.z;
    const bool flip =
        p.x == b.x && p.y == b.y && p.z == b.z && q.x == a.x && q.y == a.y && q.z == a.z;
    if (!same && !flip) continue;
    for (const Piece& w : want)
      for (double f : {0.25, 0.5, 0.75}) {
        const double t = w.t0 + (w.t1 - w.t0) * f;
        const int64_t m = int64_t((flip ? 1 - t : t) * double(kOne));
        int32_t got = kQiUnknown;
        for (const SolidPiece& x : r.pieces)
          if (x.edge == e && x.t0 <= m && m < x.t1) got = x.q;
        CHECK_MSG(got == w.q, what + ": edge (" + std::to_string(a.x) + "," + std::to_string(a.y) +
                                  ")-(" + std::to_string(b.x) + "," + std::to_string(b.y) +
                                  ") at " + std::to_string(t) + ": QI " + std::to_string(got) +
                                  " halves, by hand " + std::to_string(w.q));
      }
    return;
  }
  CHECK_MSG(false, what + ": no such edge");
}

// Both methods, each checked by `body`.
template <typename Body>
void both(const SolidScene& s, const std::string& what, Body body) {
  for (HiddenMethod m : {HiddenMethod::kQi, HiddenMethod::kFallback}) {
    SolidRun r;
    const Status st = run_hidden_lines(s, m, FallbackParams{}, &r, true);
    CHECK_MSG(st == Status::kOk, what + ": " + status_name(st));
    CHECK_MSG(r.qi.conflicts == 0, what + ": conflicts");
    body(r, what + (m == HiddenMethod::kQi ? " (QI)" : " (fallback)"));
  }
  // Franklin 1980 (blocking faces, at several grid finenesses) sees the same: hidden exactly
  // where the hand-worked QI is not 0, on these edge-on, end-on and coincident cases.
  SolidRun qi;
  CHECK(run_hidden_lines(s, HiddenMethod::kQi, FallbackParams{}, &qi) == Status::kOk);
  for (uint32_t c : {256u, 512u, 1024u, 2048u}) {
    FranklinParams fp;
    fp.c_q8 = c;
    FranklinRun fr;
    CHECK(run_franklin(s, fp, &fr) == Status::kOk);
    int wrong = 0;
    for (const SolidPiece& p : qi.pieces) {
      if (p.t1 - p.t0 < 2) continue;
      const int64_t m = p.t0 + (p.t1 - p.t0) / 2;
      for (const FranklinPiece& x : fr.pieces)
        if (x.edge == p.edge && x.t0 <= m && m < x.t1 && x.hidden != (p.q != 0)) ++wrong;
    }
    CHECK_MSG(wrong == 0, what + ": Franklin with c = " + std::to_string(c / 256.0) +
                              " differs on " + std::to_string(wrong) + " pieces");
  }
}

Point3 P(int32_t x, int32_t y, int32_t z) { return Point3{x, y, z}; }

// B: the front box, x, y in [1500, 2500], depth 3000..4000 (nearest).
void front_box(Mesh* m) { box(m, 1500, 1500, 3000, 2500, 2500, 4000); }

// A triangular prism: the triangle on paper, depth 0..1000 (behind B).
void rear_prism(Mesh* m, std::vector<std::pair<int32_t, int32_t>> tri) { prism(m, tri, 0, 1000); }

}  // namespace

int main() {
  // The HALO paper's pair of cubes, straight on: A behind, B in front overlapping its corner.
  //
  //        +---------+            B: [1500, 2500]^2, depth 3000..4000
  //   +----|----+    |            A: [1000, 2000]^2, depth 1000..2000
  //   |    +----|----+            A's top edge is hidden from x = 1500 on, its right edge
  //   |         |                 from y = 1500 on; every back edge lies exactly behind its
  //   +---------+                 front edge (occluded: half a face), so it is hidden too.
  {
    Mesh m;
    box(&m, 1000, 1000, 1000, 2000, 2000, 2000);
    front_box(&m);
    const SolidScene s = plot_scene(m);
    both(s, "pair of cubes", [&](const SolidRun& r, const std::string& w) {
      expect(s, r, w, P(1000, 2000, 2000), P(2000, 2000, 2000), {{0, 0.5, 0}, {0.5, 1, 2}});
      expect(s, r, w, P(2000, 1000, 2000), P(2000, 2000, 2000), {{0, 0.5, 0}, {0.5, 1, 2}});
      expect(s, r, w, P(1000, 1000, 2000), P(2000, 1000, 2000), {{0, 1, 0}});
      expect(s, r, w, P(1000, 1000, 2000), P(1000, 2000, 2000), {{0, 1, 0}});
      // A's back face edges: half of A's front face, and B's front face where B covers them.
      expect(s, r, w, P(1000, 2000, 1000), P(2000, 2000, 1000), {{0, 0.5, 1}, {0.5, 1, 3}});
      expect(s, r, w, P(1000, 1000, 1000), P(2000, 1000, 1000), {{0, 1, 1}});
      // B's front edges are all visible; its back edges lie behind them.
      expect(s, r, w, P(1500, 1500, 4000), P(2500, 1500, 4000), {{0, 1, 0}});
      expect(s, r, w, P(1500, 1500, 3000), P(2500, 1500, 3000), {{0, 1, 1}});
      CHECK_MSG(r.pieces.size() > 0, w);

      // The four drawing modes, from these pieces.
      ModeSpec all{SolidMode::kAll, 100, 50, false};
      ModeSpec removed{SolidMode::kHiddenRemoved, 100, 50, false};
      ModeSpec dashed{SolidMode::kHiddenDashed, 100, 50, true};
      const ModeDrawing da = make_mode_drawing(r, all), dr = make_mode_drawing(r, removed),
                        dd = make_mode_drawing(r, dashed);
      auto length = [](const std::vector<Span>& v) {
        int64_t sum = 0;
        for (const Span& x : v) sum += std::abs(x.x1 - x.x0) + std::abs(x.y1 - x.y0);
        return sum;
      };
      // all: 8 front and back square edges per box of 1000 steps (depth edges are points).
      CHECK_MSG(length(da.spans) == 16 * 1000,
                w + ": all-edges length " + std::to_string(length(da.spans)));
      // hidden removed: A's front square less the 500 + 500 behind B, and B's front square.
      CHECK_MSG(length(dr.spans) == 4000 - 1000 + 4000,
                w + ": visible length " + std::to_string(length(dr.spans)));
      // dashed: the visible part, plus the 16000 - 7000 hidden cut into 100-on 50-off dashes.
      // Each hidden piece of length L gives ceil(L / 150) dashes of at most 100 steps.
      const int64_t hidden = length(dd.spans) - length(dr.spans);
      CHECK_MSG(hidden > 0 && hidden <= 9000 * 100 / 150 + 12 * 100 &&
                    hidden >= 9000 * 100 / 150 - 12 * 100,
                w + ": dashed hidden length " + std::to_string(hidden));
      for (const Span& x : dd.spans) CHECK(std::abs(x.x1 - x.x0) + std::abs(x.y1 - x.y0) <= 1000);
      // The outline: the union's boundary, 8 sides: 1000 + 500 + 1000 + 500 + ... = 6000 steps.
      // haloed (HALO on the edges alone, W = 100): A's top edges pass behind B's left side at
      // (1500, 2000) and A's right edges behind B's bottom at (2000, 1500), square on, so each
      // loses 2 x 100 steps; nothing else crosses. 16 edges of 1000 less 4 gaps of 200.
      std::vector<Edge3> edges;
      for (size_t e = 0; e < s.edge_pairs.size() / 2; ++e)
        edges.push_back(
            Edge3{s.vertices[s.edge_pairs[2 * e]], s.vertices[s.edge_pairs[2 * e + 1]]});
      HostCut cut;
      HostDraw drawn;
      CHECK(host_cut(edges, CutParams{}, &cut) == Status::kOk);
      CHECK(host_draw(cut.set, DrawParams{100, HaloMode::kPaper}, &drawn) == Status::kOk);
      CHECK_MSG(length(drawn.spans) == 16 * 1000 - 4 * 200,
                w + ": haloed length " + std::to_string(length(drawn.spans)));
      // (Outlines come with the QI method only.)
      if (r.used_qi)
        CHECK_MSG(length(dd.outline) == 6000,
                  w + ": outline length " + std::to_string(length(dd.outline)));
    });
  }

  // A vertex exactly on a contour (delta q.i.): a rear prism's corner on B's right side.
  //   triangle (2500, 2000), (3500, 1000), (3500, 3000): everything right of B, so visible;
  //   its corner (2500, 2000) lies inside B's right edge on paper.
  {
    Mesh m;
    front_box(&m);
    rear_prism(&m, {{2500, 2000}, {3500, 1000}, {3500, 3000}});
    const SolidScene s = plot_scene(m);
    both(s, "vertex on a contour", [&](const SolidRun& r, const std::string& w) {
      expect(s, r, w, P(2500, 2000, 1000), P(3500, 1000, 1000), {{0, 1, 0}});
      expect(s, r, w, P(3500, 3000, 1000), P(2500, 2000, 1000), {{0, 1, 0}});
      expect(s, r, w, P(2500, 1500, 4000), P(2500, 2500, 4000), {{0, 1, 0}});
    });
  }

  // An edge passing exactly through a vertex (half q.i.): rear triangles whose sides pass
  // through B's corner (2500, 2500). One side just grazes it (visible on both sides); the other
  // comes out from under B there (hidden before, visible after).
  {
    Mesh m;
    front_box(&m);
    rear_prism(&m,
               {{2000, 3000}, {3000, 2000}, {3500, 3500}});  // grazing side (2000,3000)-(3000,2000)
    const SolidScene s = plot_scene(m);
    both(s, "edge through a vertex, grazing", [&](const SolidRun& r, const std::string& w) {
      expect(s, r, w, P(2000, 3000, 1000), P(3000, 2000, 1000), {{0, 1, 0}});
    });
  }
  {
    Mesh m;
    front_box(&m);
    rear_prism(&m, {{2000, 2000}, {3000, 2000}, {3000, 3000}});  // side (2000,2000)-(3000,3000)
    const SolidScene s = plot_scene(m);
    both(s, "edge through a vertex, emerging", [&](const SolidRun& r, const std::string& w) {
      expect(s, r, w, P(3000, 3000, 1000), P(2000, 2000, 1000), {{0, 0.5, 0}, {0.5, 1, 2}});
      // Its side (2000, 2000)-(3000, 2000) leaves B at x = 2500: hidden, then visible.
      expect(s, r, w, P(2000, 2000, 1000), P(3000, 2000, 1000), {{0, 0.5, 2}, {0.5, 1, 0}});
    });
  }

  // Vertex on vertex (quarter q.i.): a rear triangle with a corner exactly under B's corner
  // (1500, 1500), one side leaving outside B, the other running under it.
  //   triangle (1500, 1500), (1000, 500), (2000, 1000)... the side to (2000, 1000) stays below
  //   B (y < 1500): visible; the side (1500, 1500)-(1000, 500) is left of and below B: visible.
  //   A second triangle (1500, 1500), (2000, 1000), (2000, 2000): its side to (2000, 2000) runs
  //   inside B: hidden; its side x = 2000 from 1000 to 2000 is under B above y = 1500.
  {
    Mesh m;
    front_box(&m);
    rear_prism(&m, {{1500, 1500}, {1000, 500}, {2000, 1000}});
    const SolidScene s = plot_scene(m);
    both(s, "vertex on vertex, outside", [&](const SolidRun& r, const std::string& w) {
      expect(s, r, w, P(1500, 1500, 1000), P(1000, 500, 1000), {{0, 1, 0}});
      expect(s, r, w, P(1000, 500, 1000), P(2000, 1000, 1000), {{0, 1, 0}});
      expect(s, r, w, P(2000, 1000, 1000), P(1500, 1500, 1000), {{0, 1, 0}});
    });
  }
  {
    Mesh m;
    front_box(&m);
    rear_prism(&m, {{1500, 1500}, {2000, 1000}, {2000, 2000}});
    const SolidScene s = plot_scene(m);
    both(s, "vertex on vertex, inside", [&](const SolidRun& r, const std::string& w) {
      expect(s, r, w, P(2000, 2000, 1000), P(1500, 1500, 1000), {{0, 1, 2}});
      expect(s, r, w, P(1500, 1500, 1000), P(2000, 1000, 1000), {{0, 1, 0}});
      expect(s, r, w, P(2000, 1000, 1000), P(2000, 2000, 1000), {{0, 0.5, 0}, {0.5, 1, 2}});
    });
  }

  // Coincident edges in front and behind: a rear box sharing B's left side line on paper,
  //   x in [500, 1500], y in [1800, 2200]: its right edge x = 1500 lies along B's left edge
  //   (occluded: half of B's front face), the rest is left of B and visible.
  {
    Mesh m;
    front_box(&m);
    box(&m, 500, 1800, 0, 1500, 2200, 1000);
    const SolidScene s = plot_scene(m);
    both(s, "coincident edges", [&](const SolidRun& r, const std::string& w) {
      expect(s, r, w, P(1500, 1800, 1000), P(1500, 2200, 1000), {{0, 1, 1}});
      expect(s, r, w, P(500, 2200, 1000), P(1500, 2200, 1000), {{0, 1, 0}});
      expect(s, r, w, P(500, 1800, 1000), P(500, 2200, 1000), {{0, 1, 0}});
    });
  }
  // A concave face with a slot narrower than a grid cell (issue 18): a U-shaped prism in front,
  //   x in [1000, 3000], y in [1000, 3000], depth 3000..4000, with a slot 20 steps wide,
  //   x in [1990, 2010], from y = 1200 up to its top; behind it, depth 0..1000, a thin box
  //   x in [1995, 2005], y in [500, 3500], whose front edges run up through the slot. Seen
  //   through the slot they are visible; only the bar under the slot, y in [1000, 1200],
  //   hides them. Franklin's blocking test took the whole polygon holding a cell's four
  //   corners as covering the cell, so a cell across the slot hid what is seen through it.
  {
    Mesh m;
    prism(&m,
          {{1000, 1000},
           {3000, 1000},
           {3000, 3000},
           {2010, 3000},
           {2010, 1200},
           {1990, 1200},
           {1990, 3000},
           {1000, 3000}},
          3000, 4000);
    box(&m, 1995, 500, 0, 2005, 3500, 1000);
    const SolidScene s = plot_scene(m);
    both(s, "slot narrower than a cell", [&](const SolidRun& r, const std::string& w) {
      const double bar0 = 500.0 / 3000, bar1 = 700.0 / 3000;  // y = 1000 and 1200
      for (int32_t x : {1995, 2005})
        expect(s, r, w, P(x, 500, 1000), P(x, 3500, 1000),
               {{0, bar0, 0}, {bar0, bar1, 2}, {bar1, 1, 0}});
    });
  }
  return check::finish("solid_cases");
}
