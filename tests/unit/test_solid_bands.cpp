// Solids in bands: the banded drawing is the unbanded drawing.
//
// Each scene is plotted by the band conductor's solid stage (core/band/solid_band.cpp) in small
// arenas (many bands) and in one band, and every stroke (edge, Q0.32 ends) must be the same,
// hidden-dashed included: a piece cut at a border and carried up must be stroked whole, its
// dashes measured from its true start, by exactly one band. Independently, the visible runs of
// every drawn edge must equal the whole-model QI propagation's (solid/qi.h: Appel and Heger's
// method, which shares only CUT and the cover predicate with the bands' Franklin tests).
// A checker must see the defect it guards: a band source that loses one face, and one that
// calls the model open (back faces then count), must both change the strokes.
// Intersection lines (solids through each other): each band draws their visible parts in its
// rows; joined across the borders they equal the whole-model run's exactly.
#include <algorithm>
#include <array>
#include <cstdio>
#include <iterator>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "check.h"
#include "haloplot/band/conductor.h"
#include "pipeline/solid_pipeline.h"
#include "support/solid_refs.h"
#include "support/solid_scenes.h"

using namespace haloplot;
using namespace haloplot::host;
using namespace solid_scenes;

namespace {

using solid_refs::joined;
using solid_refs::Stroke;

// A stroke of an intersection line: its segment's ends (the same in every band: two faces
// give one segment), then the Q0.32 ends along it.
using LineStroke = std::array<int64_t, 8>;

LineStroke line_stroke(const Edge3& e, int64_t t0, int64_t t1) {
  return {e.a.x, e.a.y, e.a.z, e.b.x, e.b.y, e.b.z, t0, t1};
}

// Adjacent strokes of one segment joined.
std::vector<LineStroke> joined_lines(std::vector<LineStroke> v) {
  std::sort(v.begin(), v.end());
  std::vector<LineStroke> out;
  for (const LineStroke& s : v) {
    if (!out.empty() && std::equal(s.begin(), s.begin() + 6, out.back().begin()) &&
        out.back()[7] == s[6])
      out.back()[7] = s[7];
    else
      out.push_back(s);
  }
  return out;
}

struct Banded {
  Status status = Status::kOk;
  std::vector<Stroke> strokes;
  std::vector<LineStroke> lines;  // intersection and hatch lines' strokes, when asked
  BandStats stats;
};

Banded run_bands(const StrokeStyle& style, size_t arena_bytes, SolidSource source,
                 bool outline = false, bool lines = false, const HatchParams* hatch = nullptr) {
  Banded r;
  BandSpec spec;
  spec.style = style;
  spec.outline = outline;
  spec.intersections = lines;
  spec.hatch = hatch != nullptr;
  if (hatch != nullptr) spec.hatch_params = *hatch;
  spec.cut.compact_cells = false;
  // Left uninitialised, as a controller's arena is: zeroing the 256 MB "one band" arena took
  // nine tenths of this test's time, and the stages must not read what they did not write.
  const std::unique_ptr<uint64_t[]> arena(new uint64_t[arena_bytes / 8]);
  BandConductor bc;
  bc.set_observer(PieceObserver{[](void* ctx, const BandPiece& p) {
                                  Banded* self = static_cast<Banded*>(ctx);
                                  if (p.line != nullptr)
                                    self->lines.push_back(line_stroke(*p.line, p.t0, p.t1));
                                  else
                                    self->strokes.emplace_back(p.edge, p.t0, p.t1);
                                },
                                &r});
  r.status = bc.begin_solid(spec, source, arena.get(), arena_bytes / 8 * 8);
  if (ok(r.status)) r.status = run_all_bands(bc);
  r.stats = bc.stats();
  std::sort(r.strokes.begin(), r.strokes.end());
  std::sort(r.lines.begin(), r.lines.end());
  return r;
}

size_t first_difference(const std::vector<Stroke>& a, const std::vector<Stroke>& b) {
  size_t i = 0;
  while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
  return i;
}

struct Scene {
  std::string name;
  SolidScene scene;
  std::vector<size_t> arenas;  // each must plot it, in as many bands as it takes
  bool pierced = false;        // solids through each other: the whole-model QI looks for pierces
  bool open = false;           // not a closed solid: every face hides, both sides
};

void check_scene(const Scene& sc) {
  const SolidInput in = solid_input(sc.scene);
  SolidRun qi;
  const Status qs = run_hidden_lines(sc.scene, HiddenMethod::kAuto, FallbackParams{}, &qi);
  CHECK_MSG(ok(qs) && qi.used_qi && (qi.qi.pierces > 0) == sc.pierced,
            sc.name + (sc.pierced ? ": the whole-model QI run, stopping where edges pierce faces"
                                  : ": the whole-model QI run"));
  const bool closed = qi.check.manifold();
  CHECK_MSG(closed, sc.name + ": a closed solid");
  std::vector<Stroke> qi_visible;
  for (const SolidPiece& p : qi.pieces)
    if (!p.hidden) qi_visible.emplace_back(p.edge, p.t0, p.t1);
  qi_visible = joined(qi_visible);

  const SolidSource source = array_solid_source(&in, closed);
  for (SolidMode mode : {SolidMode::kHiddenRemoved, SolidMode::kHiddenDashed}) {
    const StrokeStyle style{mode, 160, 80};
    const char* mode_name = mode == SolidMode::kHiddenRemoved ? "hidden-removed" : "hidden-dashed";
    const Banded one = run_bands(style, size_t{256} << 20, source);
    CHECK_MSG(ok(one.status) && one.stats.bands == 1,
              sc.name + " " + mode_name + ": one band (" + status_name(one.status) + ", " +
                  std::to_string(one.stats.bands) + " bands)");
    if (mode == SolidMode::kHiddenRemoved) {
      const std::vector<Stroke> vis = joined(one.strokes);
      CHECK_MSG(vis == qi_visible,
                sc.name + ": one band's visible runs equal QI's (" + std::to_string(vis.size()) +
                    " vs " + std::to_string(qi_visible.size()) + ", first difference at " +
                    std::to_string(first_difference(vis, qi_visible)) + ")");
    }
    for (size_t arena : sc.arenas) {
      const Banded b = run_bands(style, arena, source);
      const std::string what = sc.name + " " + mode_name + " in " + std::to_string(arena >> 10) +
                               " KB (" + std::to_string(b.stats.bands) + " bands)";
      if (!ok(b.status)) {
        CHECK_MSG(false, what + ": " + status_name(b.status));
        continue;
      }
      CHECK_MSG(b.stats.peak_bytes <= arena, what + ": within the arena");
      CHECK_MSG(b.strokes == one.strokes,
                what + ": strokes equal the one-band run's (" + std::to_string(b.strokes.size()) +
                    " vs " + std::to_string(one.strokes.size()) + ", first difference at " +
                    std::to_string(first_difference(b.strokes, one.strokes)) + ")");
      std::printf("%s: peak %zu bytes, %zu strokes, %llu band edges\n", what.c_str(),
                  b.stats.peak_bytes, b.strokes.size(), (unsigned long long)b.stats.band_edges);
    }
  }
}

Mesh cube_array_mesh(int n) {
  Mesh m;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      box(&m, i * 3000, j * 3000, 0, i * 3000 + 2000, j * 3000 + 2000, 2000);
  return m;
}

Scene make(const std::string& name, const Mesh& m, int32_t az, int32_t el,
           std::vector<size_t> arenas_kb) {
  Scene s{name, {}, {}};
  for (size_t kb : arenas_kb) s.arenas.push_back(kb << 10);
  CHECK_MSG(project(m, view(az, el), &s.scene), name + ": projects");
  return s;
}

// The checker sees what it guards: a source that drops one face, and one that reports the
// model open (back faces then count), must change the strokes. Both may change only the QI of
// hidden parts, which the drawing `all` shows (a stroke per run of one QI) and hidden-dashed
// no longer does (a hidden run's dashes go on across a change of QI: solid/modes.h).
void check_the_check(const Scene& sc) {
  const SolidInput in = solid_input(sc.scene);
  const StrokeStyle style{SolidMode::kAll, 160, 80};
  const Banded one = run_bands(style, size_t{256} << 20, array_solid_source(&in, true));
  SolidInput lost = in;
  std::vector<Triangle> tris(sc.scene.triangles);
  tris.erase(tris.begin() + long(tris.size() / 2));
  lost.triangles = tris.data();
  lost.n_triangles = uint32_t(tris.size());
  const Banded a = run_bands(style, size_t{64} << 10, array_solid_source(&lost, true));
  CHECK_MSG(ok(a.status) && a.strokes != one.strokes, sc.name + ": a lost face is seen");
  const Banded b = run_bands(style, size_t{64} << 10, array_solid_source(&in, false));
  CHECK_MSG(ok(b.status) && b.strokes != one.strokes, sc.name + ": back faces counted are seen");
}

// Strokes of `with` that `without` lacks (a multiset difference of sorted lists).
std::vector<Stroke> minus(const std::vector<Stroke>& with, const std::vector<Stroke>& without) {
  std::vector<Stroke> out;
  std::set_difference(with.begin(), with.end(), without.begin(), without.end(),
                      std::back_inserter(out));
  return out;
}

// Outline runs of drawn edges, joined (QI also outlines contour diagonals, triangle sides inside
// one polygon, which the fallback never draws: docs/firmware.md).
std::vector<Stroke> outline_runs(const std::vector<OutlineSegment>& v, uint32_t n_drawn) {
  std::vector<Stroke> out;
  for (const OutlineSegment& o : v)
    if (o.edge < n_drawn) out.emplace_back(o.edge, o.t0, o.t1);
  return joined(out);
}

// Kira's outlines without the QI: the fallback asks the condition of every visible contour
// part; joined into runs they must equal the QI method's traced circuits on a closed solid. In
// bands each band draws the runs inside its rows: joined across the borders, the same again.
void check_outlines(const Scene& sc) {
  SolidRun qi, fb;
  CHECK(ok(run_hidden_lines(sc.scene, HiddenMethod::kAuto, FallbackParams{}, &qi, true)));
  CHECK(ok(run_hidden_lines(sc.scene, HiddenMethod::kFallback, FallbackParams{}, &fb, true)));
  const uint32_t n_drawn = uint32_t(sc.scene.edge_pairs.size() / 2);
  const std::vector<Stroke> traced = outline_runs(qi.outline, n_drawn),
                            asked = outline_runs(fb.outline, n_drawn);
  CHECK_MSG(qi.used_qi && !traced.empty() && asked == traced,
            sc.name + ": the fallback's outlines equal QI's (" + std::to_string(asked.size()) +
                " runs vs " + std::to_string(traced.size()) + ")");
  const SolidInput in = solid_input(sc.scene);
  const SolidSource source = array_solid_source(&in, true);
  const StrokeStyle removed{SolidMode::kHiddenRemoved, 160, 80};
  const Banded plain = run_bands(removed, size_t{256} << 20, source);
  for (size_t arena : {size_t{256} << 20, sc.arenas.front()}) {
    const Banded with = run_bands(removed, arena, source, true);
    const std::vector<Stroke> drawn = joined(minus(with.strokes, plain.strokes));
    CHECK_MSG(ok(with.status) && drawn == traced,
              sc.name + ": outlines in " + std::to_string(with.stats.bands) +
                  " bands, joined, equal QI's (" + std::to_string(drawn.size()) + " runs vs " +
                  std::to_string(traced.size()) + ")");
  }
}

// In every arena of the scene: the lines' strokes (intersection or hatch lines), joined across
// the borders, equal `reference`, and the edges' strokes equal `plain`'s.
void check_lines_in_bands(const Scene& sc, const std::string& kind, SolidSource source,
                          const std::vector<LineStroke>& reference, const Banded& plain,
                          bool intersections, const HatchParams* hatch) {
  const StrokeStyle style{SolidMode::kHiddenDashed, 160, 80};
  for (size_t arena : sc.arenas) {
    const Banded b = run_bands(style, arena, source, false, intersections, hatch);
    const std::vector<LineStroke> runs = joined_lines(b.lines);
    const std::string what = sc.name + " " + kind + " in " + std::to_string(arena >> 10) + " KB (" +
                             std::to_string(b.stats.bands) + " bands)";
    CHECK_MSG(ok(b.status) && b.stats.bands > 1, what + ": plots in bands");
    CHECK_MSG(runs == reference, what + ": strokes, joined across the borders, equal the " +
                                     "whole-model run's (" + std::to_string(runs.size()) +
                                     " runs vs " + std::to_string(reference.size()) + ")");
    CHECK_MSG(b.strokes == plain.strokes, what + ": the edges' strokes unchanged");
    std::printf("%s: %zu strokes, %zu runs joined\n", what.c_str(), b.lines.size(), runs.size());
  }
}

// The scene's input without triangle f (the triangles kept in *storage).
SolidInput without_face(const Scene& sc, uint32_t f, std::vector<Triangle>* storage) {
  SolidInput lost = solid_input(sc.scene);
  *storage = sc.scene.triangles;
  storage->erase(storage->begin() + long(f));
  lost.triangles = storage->data();
  lost.n_triangles = uint32_t(storage->size());
  return lost;
}

// Intersection lines in bands (solids through each other): each band draws the visible parts
// in its rows, cut at its borders; joined across the borders they are the whole-model run's
// (solid/intersection_lines.h on every face at once), and the edges' strokes do not change.
void check_lines(const Scene& sc) {
  SolidRun whole;
  CHECK(ok(run_hidden_lines(sc.scene, HiddenMethod::kAuto, FallbackParams{}, &whole, false, true)));
  std::vector<LineStroke> reference;
  for (const SolidPiece& p : whole.intersections)
    if (!p.hidden) reference.push_back(line_stroke(whole.edges[p.edge], p.t0, p.t1));
  reference = joined_lines(reference);
  CHECK_MSG(!reference.empty(), sc.name + ": the whole-model run draws intersection lines");
  const SolidInput in = solid_input(sc.scene);
  const SolidSource source = array_solid_source(&in, true);
  const StrokeStyle style{SolidMode::kHiddenDashed, 160, 80};
  const Banded plain = run_bands(style, size_t{256} << 20, source);
  const Banded one = run_bands(style, size_t{256} << 20, source, false, true);
  CHECK_MSG(ok(one.status) && joined_lines(one.lines) == reference,
            sc.name + ": one band's intersection lines equal the whole-model run's (" +
                std::to_string(joined_lines(one.lines).size()) + " runs vs " +
                std::to_string(reference.size()) + ")");
  CHECK_MSG(one.strokes == plain.strokes, sc.name + ": the lines leave the edges' strokes alone");
  check_lines_in_bands(sc, "intersection lines", source, reference, plain, true, nullptr);
  // The control: a band source that lost a face of a visible crossing must change the lines.
  size_t seen = 0;
  while (seen + 1 < whole.intersections.size() && whole.intersections[seen].hidden) ++seen;
  std::vector<Triangle> tris;
  const SolidInput lost = without_face(sc, whole.intersection_faces[seen][0], &tris);
  const Banded c =
      run_bands(style, sc.arenas.front(), array_solid_source(&lost, true), false, true);
  CHECK_MSG(ok(c.status) && joined_lines(c.lines) != reference,
            sc.name + ": a lost crossing face is seen in the lines");
}

// Hatching in bands: each band draws the visible parts of the hatch lines in its rows, cut at
// its borders, from every triangle of each polygon it holds; joined across the borders they are
// the whole-model run's hatching (solid/hatch_lines.h on every face at once: the QI's grid and
// facing for a closed model), and the edges' strokes do not change.
void check_hatch(Scene sc, int32_t spacing, std::vector<size_t> arenas_kb = {}) {
  if (!arenas_kb.empty()) sc.arenas.clear();
  for (size_t kb : arenas_kb) sc.arenas.push_back(kb << 10);
  HatchParams hp;
  hp.spacing = spacing;
  hp.angle_mdeg = 30000;
  hp.mdeg_per_depth = 90000;
  SolidRun whole;
  CHECK(ok(run_hidden_lines(sc.scene, HiddenMethod::kAuto, FallbackParams{}, &whole, false, false,
                            &hp)));
  std::vector<LineStroke> reference;
  for (const SolidPiece& p : whole.hatch)
    if (!p.hidden) reference.push_back(line_stroke(whole.edges[p.edge], p.t0, p.t1));
  reference = joined_lines(reference);
  CHECK_MSG(reference.size() > 20, sc.name + ": the whole-model run hatches (" +
                                       std::to_string(reference.size()) + " strokes)");
  const SolidInput in = solid_input(sc.scene);
  const SolidSource source = array_solid_source(&in, !sc.open);
  const StrokeStyle style{SolidMode::kHiddenDashed, 160, 80};
  const Banded plain = run_bands(style, size_t{256} << 20, source);
  check_lines_in_bands(sc, "hatched", source, reference, plain, false, &hp);
  // The controls: a band source that lost a hatched face, and one that turned the hatch (the
  // lines' direction reads the whole polygon), must change the hatching.
  uint32_t hatched = 0;
  while (hatched < whole.hatch_faces.size() && whole.hatch[hatched].hidden) ++hatched;
  std::vector<Triangle> tris;
  const SolidInput lost = without_face(sc, whole.hatch_faces[hatched], &tris);
  const Banded c =
      run_bands(style, sc.arenas.front(), array_solid_source(&lost, !sc.open), false, false, &hp);
  CHECK_MSG(ok(c.status) && joined_lines(c.lines) != reference,
            sc.name + ": a lost hatched face is seen in the hatching");
  HatchParams turned = hp;
  turned.mdeg_per_depth += 1000;
  const Banded t = run_bands(style, sc.arenas.front(), source, false, false, &turned);
  CHECK_MSG(ok(t.status) && joined_lines(t.lines) != reference,
            sc.name + ": a turned hatch is seen in the hatching");
}

// An open surface (a box without its lid) takes the QI counting both sides of every face, and
// gets outlines too: every run lies on the boundary of what the picture covers (brute force
// over all faces, both sides), by the QI's traced circuits and by the fallback's condition.
void check_open_outlines(const Scene& sc, HiddenMethod method);

void check_open_outlines() {
  Mesh m;
  box(&m, 0, 0, 0, 4000, 3000, 2000);
  m.faces.erase(m.faces.begin() + 1);  // the lid (+z) is the box's second face
  Scene sc = make("open box at 30,25", m, 30000, 25000, {16});
  for (HiddenMethod method : {HiddenMethod::kAuto, HiddenMethod::kFallback})
    check_open_outlines(sc, method);
}

void check_open_outlines(const Scene& sc, HiddenMethod method) {
  const bool qi = method == HiddenMethod::kAuto;
  SolidRun fb;
  CHECK(ok(run_hidden_lines(sc.scene, method, FallbackParams{}, &fb, true)));
  CHECK_MSG(fb.used_qi == qi && !fb.outline.empty(),
            std::string("open box: ") + (qi ? "the QI" : "the fallback") + " draws outlines (" +
                std::to_string(fb.outline.size()) + ")");
  size_t on = 0;
  for (const OutlineSegment& o : fb.outline) {
    const uint32_t v0 = sc.scene.edge_pairs[2 * o.edge], v1 = sc.scene.edge_pairs[2 * o.edge + 1];
    const Edge3 e{sc.scene.vertices[v0], sc.scene.vertices[v1]};
    if (solid_refs::on_boundary(sc.scene, e, o.t0 + (o.t1 - o.t0) / 2)) ++on;
  }
  CHECK_MSG(on == fb.outline.size(), "open box: every outline run on the picture's boundary (" +
                                         std::to_string(on) + " of " +
                                         std::to_string(fb.outline.size()) + ")");
}

}  // namespace

int main() {
  std::vector<Scene> scenes;
  scenes.push_back(make("3 x 3 cubes at 30,25", cube_array_mesh(3), 30000, 25000, {16, 24}));
  scenes.push_back(make("10 x 10 cubes at 30,25", cube_array_mesh(10), 30000, 25000, {48, 64}));
  scenes.push_back(make("10 x 10 cubes at 200,-40", cube_array_mesh(10), 200000, -40000, {48, 64}));
  {
    Mesh m;
    sphere(&m, 0, 0, 0, 5000, 24, 48);
    scenes.push_back(make("sphere 24 x 48 at 30,25", m, 30000, 25000, {32, 64}));
  }
  {
    Mesh m;
    torus(&m, 0, 0, 0, 6000, 2000, 48, 24, true);
    scenes.push_back(make("upright torus 48 x 24 at 30,25", m, 30000, 25000, {32, 64}));
  }
  {
    Mesh m;
    frame(&m, 0, 0, 6000, 3000, 0, 2000);
    box(&m, 1500, 1500, -4000, 4500, 4500, -2000);
    scenes.push_back(make("frame before a box at 20,10", m, 20000, 10000, {8, 16}));
  }
  // Solids through each other (edges cut where they pierce faces, core/solid/pierce.h): the
  // bands against one band, and one band against the whole-model fallback.
  std::vector<Scene> pierced;
  {
    Mesh m;
    box(&m, 0, 0, 0, 4000, 4000, 4000);
    box(&m, 2000, 1500, 1000, 6000, 5500, 5000);
    pierced.push_back(make("overlapping boxes at 30,25", m, 30000, 25000, {6, 8}));
  }
  {
    Mesh m;
    torus(&m, 0, 0, 0, 6000, 2000, 32, 12);
    sphere(&m, 6000, 0, 800, 3200, 12, 24);
    pierced.push_back(make("sphere through a torus at 30,25", m, 30000, 25000, {32, 48}));
  }
  for (Scene& s : pierced) s.pierced = true;
  for (const Scene& s : scenes) check_scene(s);
  for (const Scene& s : pierced) check_scene(s);
  for (const Scene& s : pierced) check_lines(s);
  check_hatch(scenes[0], 200);
  check_hatch(scenes[2], 300);
  check_hatch(scenes[4], 400);
  // (In 32 KB it takes 5,108 bands: a band's hatch lines cost 40 bytes each however thin it is.)
  check_hatch(pierced[1], 400, {40, 48});
  {  // an open surface: every face hides, both sides, and the front faces are hatched
    Mesh m;
    box(&m, 0, 0, 0, 4000, 3000, 2000);
    m.faces.erase(m.faces.begin() + 1);  // the lid
    Scene open = make("open box at 30,25", m, 30000, 25000, {8, 16});
    open.open = true;
    check_hatch(open, 150, {12, 16});
  }
  for (const Scene& s : scenes) check_outlines(s);
  check_open_outlines();
  check_the_check(scenes[1]);
  return check::finish("solid_bands");
}
