// The resolution axis (docs/reports/accuracy.md): the same hidden-line run with the projected scene
// in whole steps and in units of 2^-s steps (View::substep_bits), on the cube array, a
// 200k-triangle sphere and torus, and assimp's WusonOBJ and spider meshes. For each
// resolution: how much ink differs from a double-precision ray cast of the unrounded model
// (tests/reference/ray_cast.h; per drawn edge, |visible length drawn - visible length cast|,
// summed), how many edges agree within 3 steps + 1 %, the triangulation diagonals drawn as
// contour (QI: H3 diagonals, visible length) against those the model itself has, and the time
// (median of 5 whole runs, the resolutions interleaved; ns per drawn edge). Writes the markdown
// table body DIR/resolution.body.md. Usage: resolution_bench DIR [--quick]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "../support/must.h"
#include "bench/perf_common.h"
#include "cli/options.h"
#include "cli/scene_input.h"
#include "haloplot/view/projection.h"
#include "io/obj_file.h"
#include "reference/contour_diagonals.h"
#include "reference/ray_cast.h"
#include "support/solid_scenes.h"

using namespace haloplot;
using namespace haloplot::host;

namespace {

// The resolutions, and last whole steps and the default once more with the intersection lines
// a job draws by default (solid/intersection_lines.h): the resolution's cost with them, and
// what they add.
struct Variant {
  int bits;
  bool lines;
};
const Variant kVariants[] = {{0, false}, {2, false}, {3, false}, {4, false},
                             {5, false}, {0, true},  {5, true}};

struct Model {
  std::string name;
  std::vector<Point3> world;
  std::vector<uint32_t> pairs;  // drawn edges
  std::vector<Triangle> triangles;
  View view;
  std::string obj_path, obj_view;  // an OBJ file: loaded through the host's own input path
};

struct Truth {
  std::vector<double> visible, length;  // per drawn edge
  double model_contour_diagonals = 0;   // visible length of the model's own H3 diagonals
  std::set<std::pair<uint32_t, uint32_t>> contour_diagonals;  // theirs, as vertex pairs
};

struct Cell {
  double ink_diff = 0, agree = 0, diagonals = 0, spurious = 0, ns_per_edge = 0, ms = 0;
  bool qi = false;
  uint64_t segments = 0;  // intersection lines (faces that cross), when drawn
};

Truth cast(const Model& m) {
  Truth t;
  const ray_cast::Scene truth(ray_cast::camera(m.view, m.world), m.world, m.triangles);
  for (size_t e = 0; e < m.pairs.size() / 2; ++e) {
    double len = 0;
    t.visible.push_back(truth.visible_length(m.pairs[2 * e], m.pairs[2 * e + 1], &len));
    t.length.push_back(len);
  }
  t.contour_diagonals = contour_diagonals::model_contour_diagonals(truth, m.triangles);
  for (const auto& d : t.contour_diagonals)
    t.model_contour_diagonals += truth.visible_length(d.first, d.second);
  return t;
}

bool load(const Model& m, int s, SolidScene* scene) {
  if (m.obj_path.empty()) {
    View v = m.view;
    v.substep_bits = s;
    scene->vertices.resize(m.world.size());
    scene->edge_pairs = m.pairs;
    scene->triangles = m.triangles;
    scene->substep_bits = s;
    std::string error;
    return project_points(v, m.world.data(), uint32_t(m.world.size()), scene->vertices.data()) ==
               Status::kOk &&
           model_facing_of(v, m.world, scene, &error);
  }
  Options o;
  o.values["--view"] = m.obj_view;
  o.values["--up"] = "y";
  o.values["--substep"] = std::to_string(s);
  std::string error;
  return load_solid_scene(o, m.obj_path, scene, nullptr, &error);
}

// Every resolution's scene, timed in turn: five rounds over all of them, so a slow spell of the
// machine falls on every resolution alike; the median of each.
std::vector<double> time_resolutions(const Model& m) {
  const size_t k = sizeof kVariants / sizeof kVariants[0];
  std::vector<SolidScene> scenes(k);
  std::vector<std::vector<double>> ms(k);
  for (size_t i = 0; i < k; ++i)
    if (!load(m, kVariants[i].bits, &scenes[i])) return std::vector<double>(k, 0.0);
  for (int round = 0; round < 5; ++round)
    for (size_t i = 0; i < k; ++i) {
      SolidRun run;
      const double t0 = bench::now_ms();
      must(run_hidden_lines(scenes[i], HiddenMethod::kAuto, FallbackParams{}, &run, false,
                            kVariants[i].lines));
      ms[i].push_back(bench::now_ms() - t0);
    }
  std::vector<double> out;
  for (const auto& v : ms) out.push_back(bench::median(v));
  return out;
}

Cell measure(const Model& m, const Truth& t, Variant variant, double ms) {
  Cell c;
  SolidScene scene;
  if (!load(m, variant.bits, &scene)) return c;
  SolidRun run;
  if (run_hidden_lines(scene, HiddenMethod::kAuto, FallbackParams{}, &run, false, variant.lines) !=
      Status::kOk)
    return c;
  c.ms = ms;
  c.qi = run.used_qi;
  c.segments = run.intersection_stats.segments;
  const size_t n = scene.edge_pairs.size() / 2;
  c.ns_per_edge = c.ms * 1e6 / double(n);
  std::vector<double> share(n, 0.0);
  for (const SolidPiece& p : run.pieces)
    if (!p.hidden && p.edge < n) share[p.edge] += double(p.t1 - p.t0) / 4294967296.0;
  size_t agree = 0;
  for (size_t e = 0; e < n; ++e) {
    const double diff = std::fabs(share[e] * t.length[e] - t.visible[e]);
    c.ink_diff += diff;
    if (diff <= 3 + 0.01 * t.length[e]) ++agree;
  }
  c.agree = 100.0 * double(agree) / double(std::max<size_t>(n, 1));
  const contour_diagonals::Drawn d =
      contour_diagonals::drawn_contour_diagonals(scene, run, t.contour_diagonals);
  c.diagonals = d.total;
  c.spurious = d.spurious;
  return c;
}

size_t triangles(const solid_scenes::Mesh& m) {
  size_t n = 0;
  for (const auto& f : m.faces) n += f.size() - 2;
  return n;
}

Model mesh_model(const std::string& name, const solid_scenes::Mesh& mesh, const View& v) {
  Model m;
  m.name = name;
  m.world = mesh.v;
  m.pairs = solid_scenes::polygon_edges(mesh);
  m.triangles = triangulate(mesh.v, mesh.faces, nullptr);
  m.view = v;
  return m;
}

Model obj_model(const std::string& name, const std::string& path, const std::string& view_text,
                int32_t az, int32_t el) {
  Model m;
  m.name = name;
  m.obj_path = path;
  m.obj_view = view_text;
  ObjModel obj;
  if (read_obj_file(path, &obj).failed()) return m;
  make_z_up(&obj, UpAxis::kY);
  m.world = obj.vertices;
  SolidScene scene;
  if (!load(m, 0, &scene)) return m;
  m.pairs = scene.edge_pairs;
  m.triangles = scene.triangles;
  m.view.azimuth_mdeg = az;
  m.view.elevation_mdeg = el;
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  const bool quick = argc > 2 && std::strcmp(argv[2], "--quick") == 0;
  std::vector<Model> models;
  {
    solid_scenes::Mesh m;
    for (int i = 0; i < 28; ++i)
      for (int j = 0; j < 28; ++j)
        solid_scenes::box(&m, i * 125, j * 125, 0, i * 125 + 100, j * 125 + 100, 100);
    models.push_back(mesh_model("cube array 28 x 28", m, solid_scenes::view(30000, 40000)));
  }
  {
    solid_scenes::Mesh m;
    const int stacks = quick ? 56 : 224;
    solid_scenes::sphere(&m, 0, 0, 0, 500000, stacks, 2 * stacks);
    models.push_back(mesh_model("sphere, " + std::to_string(triangles(m)) + " triangles", m,
                                solid_scenes::view(30000, 25000)));
  }
  {
    solid_scenes::Mesh m;
    const int k = quick ? 56 : 224;
    solid_scenes::torus(&m, 0, 0, 0, 600000, 250000, 2 * k, k);
    models.push_back(mesh_model("torus, " + std::to_string(triangles(m)) + " triangles", m,
                                solid_scenes::view(30000, 25000)));
  }
  const std::string assimp = "/usr/share/assimp/models/OBJ/";
  models.push_back(obj_model("WusonOBJ at 30,25", assimp + "WusonOBJ.obj", "30,25", 30000, 25000));
  models.push_back(
      obj_model("WusonOBJ at 200,-40", assimp + "WusonOBJ.obj", "200,-40", 200000, -40000));
  models.push_back(obj_model("spider at 30,25", assimp + "spider.obj", "30,25", 30000, 25000));

  std::ofstream body(dir + "/resolution.body.md");
  body << "| scene | method | sub-step bits | edges agreeing | ink off the model (steps) | "
          "diagonals drawn "
          "as contour, steps (not in the model; the model's own) | ms | ns / edge | time vs whole "
          "steps |\n"
       << "|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const Model& m : models) {
    if (m.world.empty() || m.triangles.empty()) {
      std::fprintf(stderr, "%s: not available, skipped\n", m.name.c_str());
      continue;
    }
    const double t0 = bench::now_ms();
    const Truth truth = cast(m);
    std::fprintf(stderr, "%s: %zu edges, reference cast in %.1f s\n", m.name.c_str(),
                 truth.length.size(), (bench::now_ms() - t0) / 1000);
    double whole_ms[2] = {0, 0}, default_ms = 0;  // whole steps without and with the lines
    const std::vector<double> times = time_resolutions(m);
    for (size_t i = 0; i < times.size(); ++i) {
      const int s = kVariants[i].bits;
      const bool lines = kVariants[i].lines;
      const Cell c = measure(m, truth, kVariants[i], times[i]);
      if (s == 0) whole_ms[lines] = c.ms;
      if (s == kDefaultSubstepBits && !lines) default_ms = c.ms;
      char extra[160] = "";
      if (lines && s == kDefaultSubstepBits && default_ms > 0)
        std::snprintf(extra, sizeof extra, "; %.2f× the default without them", c.ms / default_ms);
      const std::string label = std::to_string(s) + (s == kDefaultSubstepBits ? " (default)" : "") +
                                (lines ? " + intersection lines (" + std::to_string(c.segments) +
                                             " crossings" + extra + ")"
                                       : "");
      char line[512];
      std::snprintf(line, sizeof line,
                    "| %s | %s | %s | %.2f %% | %.0f | %.0f (%.0f; %.0f) | %.1f | %.0f | %.2f× |\n",
                    m.name.c_str(), c.qi ? "QI" : "fallback", label.c_str(), c.agree, c.ink_diff,
                    c.diagonals, c.spurious, truth.model_contour_diagonals, c.ms, c.ns_per_edge,
                    whole_ms[lines] > 0 ? c.ms / whole_ms[lines] : 0.0);
      body << line;
      std::fprintf(stderr, "%s", line);
    }
  }
  return 0;
}
