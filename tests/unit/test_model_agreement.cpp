// Real meshes against their unrounded model (issue 18): assimp's WusonOBJ.obj (an open mesh,
// so the topology-free fallback draws it) and spider.obj, plotted hidden-line, every drawn
// edge's visible length compared with a double-precision ray cast of the model itself
// (tests/reference/ray_cast.h: the OBJ's integer world vertices, before the view rounds them
// to steps). An edge agrees when the two lengths differ by at most 3 steps + 1 % of its length.
//
// spider.obj repeats vertex positions under other ids: the reference skips only the faces
// that hold both of an edge's vertex ids, so a face that touches an edge through repeated
// positions counts as any other face does (it hides only where the segment to the eye passes
// through its inside).
//
// A second cast of the core's own rounded scene (on paper) tells where a difference comes
// from. Before the fallback cut edges where they pass through faces (solid/pierce.h), 51 edges
// of WusonOBJ at 30,25 disagreed with the model (99.12 %) and as many with the rounded scene:
// the mesh's parts interpenetrate, and visibility changed where the core made no cut. With
// those cuts: 99.78 % at 30,25, 99.26 % at 200,-40 (99.54 % against the rounded scene: the
// rest lie on or within rounding of another part's surface, where both casts flicker) and
// 99.81 % for spider.obj (96.95 % before).
//
// In whole steps the rest of 200,-40 is rounding: with the scene fitted in units of 2^-5 steps
// (View::substep_bits, the tool's default) the same views agree on 100 %, 99.62 % and 100 %
// (the 22 edges left at 200,-40 lie on or within a hair of another part's surface, where the
// casts flicker). The test asserts the goal, 99.5 % on every view, at the default
// units, and that whole steps fall short at 200,-40, so the check is seen to see rounding.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "../check.h"
#include "cli/options.h"
#include "cli/scene_input.h"
#include "haloplot/view/projection.h"
#include "io/obj_file.h"
#include "pipeline/solid_pipeline.h"
#include "reference/ray_cast.h"

using namespace haloplot;
using namespace haloplot::host;

namespace {

struct Agreement {
  size_t edges = 0, agree = 0, paper_agree = 0;
  double worst = 0;
};

Agreement measure(const std::string& path, const std::string& view_text, int substep) {
  Agreement a;
  Options o;
  o.values["--view"] = view_text;
  o.values["--substep"] = std::to_string(substep);
  o.values["--up"] = "y";
  // The scene as the file gives it: its vertex ids are the file's, as the reference reads them,
  // and its edges the ones measured before the defaults followed the file's rounding.
  o.values["--weld"] = "off";
  o.values["--crease"] = "exact";
  SolidScene scene;
  TriangulateStats ts;
  std::string error;
  if (!load_solid_scene(o, path, &scene, &ts, &error)) {
    CHECK_MSG(false, path + ": " + error);
    return a;
  }
  ObjModel model;
  CHECK_MSG(!read_obj_file(path, &model).failed(), path + ": unreadable");
  make_z_up(&model, UpAxis::kY);
  SolidRun run;
  CHECK_MSG(run_hidden_lines(scene, HiddenMethod::kAuto, FallbackParams{}, &run) == Status::kOk,
            path + ": hidden lines failed");
  std::vector<double> share(scene.edge_pairs.size() / 2, 0.0);
  for (const SolidPiece& p : run.pieces)
    if (!p.hidden && p.edge < share.size()) share[p.edge] += double(p.t1 - p.t0) / 4294967296.0;
  View v;
  const size_t comma = view_text.find(',');
  v.azimuth_mdeg = int32_t(std::lround(std::stod(view_text.substr(0, comma)) * 1000));
  v.elevation_mdeg = int32_t(std::lround(std::stod(view_text.substr(comma + 1)) * 1000));
  const ray_cast::Scene truth(ray_cast::camera(v, model.vertices), model.vertices, scene.triangles);
  const ray_cast::Scene paper(ray_cast::on_paper(substep), scene.vertices, scene.triangles);
  for (uint32_t e = 0; e < share.size(); ++e) {
    const uint32_t i = scene.edge_pairs[2 * e], j = scene.edge_pairs[2 * e + 1];
    double length = 0, paper_length = 0;
    const double theirs = truth.visible_length(i, j, &length);
    const double on_paper = paper.visible_length(i, j, &paper_length);
    const double diff = std::fabs(share[e] * length - theirs);
    ++a.edges;
    if (diff <= 3 + 0.01 * length) ++a.agree;
    if (std::fabs(share[e] * paper_length - on_paper) <= 3 + 0.01 * paper_length) ++a.paper_agree;
    a.worst = std::max(a.worst, diff);
  }
  std::printf(
      "%s at %s, %d sub-step bits (%s): %zu of %zu edges agree with the model (%.2f %%), worst "
      "%.1f steps; with "
      "the rounded scene: %zu\n",
      path.c_str(), view_text.c_str(), substep, run.used_qi ? "QI" : "fallback", a.agree, a.edges,
      100.0 * double(a.agree) / double(std::max<size_t>(a.edges, 1)), a.worst, a.paper_agree);
  return a;
}

}  // namespace

int main() {
  const std::string dir = "/usr/share/assimp/models/OBJ/";
  const int units = kDefaultSubstepBits;  // what `plot` and the job files use
  const Agreement w1 = measure(dir + "WusonOBJ.obj", "30,25", units);
  const Agreement w2 = measure(dir + "WusonOBJ.obj", "200,-40", units);
  const Agreement sp = measure(dir + "spider.obj", "30,25", units);
  // Whole steps, for the difference sub-step units make (docs/reports/accuracy.md, the resolution
  // axis).
  const Agreement w2_whole = measure(dir + "WusonOBJ.obj", "200,-40", 0);
  CHECK(w1.edges > 5000 && w2.edges > 5000 && sp.edges > 2000);
  auto share = [](const Agreement& a) {
    return double(a.agree) / double(std::max<size_t>(a.edges, 1));
  };
  CHECK_MSG(share(w1) >= 0.995, "WusonOBJ at 30,25: under the goal of 99.5 %");
  CHECK_MSG(share(w2) >= 0.995, "WusonOBJ at 200,-40: under the goal of 99.5 %");
  CHECK_MSG(share(sp) >= 0.995, "spider at 30,25: under 99.5 %");
  // The check sees rounding to whole steps: there the same view falls short of the goal.
  CHECK_MSG(share(w2_whole) < 0.995, "whole steps reach the goal at 200,-40: the check is blind");
  return check::finish("model_agreement");
}
