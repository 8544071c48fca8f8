// STL and PLY models, welding and orientation repair, checked against independent copies of
// the same model.
//
// `mesh_files assimp`: assimp's STL and PLY test models (Debian's assimp-testmodels, not
// written here) each plotted hidden-removed, compared with the same model as assimp ships it
// in OBJ: every step along every stroke of one drawing lies within a step of a stroke of the
// other, both ways. Exits 77 (skipped) when the models are not installed.
//
// `mesh_files repair`: a closed box and a torus written here in the files an exporter gets
// wrong: every face wound backwards (inside out), mirrored (x negated; y and z swapped: each
// turns the solid inside out, since a mirror reverses every face's winding as seen from
// outside), and as a triangle soup (binary STL, each triangle with its own three vertices).
// The reference is the correct model projected by the test's own generator path
// (solid_scenes::project: no reader, no welding, no repair): for a mirror, the mirrored
// vertices with every face wound back outward, which is the same solid as the mirrored file,
// so the drawing must be the same picture (the mirror image of the unmirrored one). Each is
// compared in hidden-removed (the visible pieces) and hidden-dashed (visible and hidden pieces
// apart), and the soup must have as many edges as the reference and the same visible length
// (an edge drawn twice would double it).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <unordered_map>

#include "../check.h"
#include "cli/options.h"
#include "cli/scene_input.h"
#include "cli/solid_options.h"
#include "pipeline/drawing_modes.h"
#include "pipeline/solid_pipeline.h"
#include "pipeline/units.h"
#include "support/solid_scenes.h"

using namespace haloplot;
using namespace haloplot::host;

namespace {

struct Seg {
  double x0, y0, x1, y1;
};

// What a drawing is made of, in steps: the pieces the hidden lines decided (visible, hidden)
// and the strokes the mode draws.
struct Drawing {
  bool ok = false;
  std::string error;
  size_t edges = 0;
  bool qi = false;
  std::vector<Seg> visible, hidden, strokes;
};

Seg piece_seg(const Edge3& e, int64_t t0, int64_t t1, int32_t units) {
  const double k = 1.0 / double(int64_t(1) << units), q = 1.0 / 4294967296.0;
  const double dx = double(e.b.x) - e.a.x, dy = double(e.b.y) - e.a.y;
  return Seg{(e.a.x + dx * double(t0) * q) * k, (e.a.y + dy * double(t0) * q) * k,
             (e.a.x + dx * double(t1) * q) * k, (e.a.y + dy * double(t1) * q) * k};
}

Drawing draw_scene(const SolidScene& scene, SolidMode mode) {
  Drawing d;
  SolidOptions so;
  so.spec.mode = mode;
  SolidRun run;
  const Status s = run_solid_options(scene, so, &run);
  d.ok = s == Status::kOk;
  d.error = status_name(s);
  if (!d.ok) return d;
  d.edges = scene.edge_pairs.size() / 2;
  d.qi = run.used_qi;
  for (const auto* list : {&run.pieces, &run.contour_diagonals, &run.intersections})
    for (const SolidPiece& p : *list)
      (p.hidden ? d.hidden : d.visible)
          .push_back(piece_seg(run.edges[p.edge], p.t0, p.t1, scene.substep_bits));
  ModeDrawing md = make_mode_drawing(run, mode_in_units(so.spec, scene.substep_bits));
  drawing_to_steps(&md, scene.substep_bits);
  for (const Span& x : md.spans)
    d.strokes.push_back(Seg{double(x.x0), double(x.y0), double(x.x1), double(x.y1)});
  return d;
}

Drawing draw_file(const std::string& path, const std::string& view, SolidMode mode,
                  const std::string& up, const std::map<std::string, std::string>& extra = {}) {
  Options o;
  o.values = extra;
  o.values["--view"] = view;
  o.values["--up"] = up;
  SolidScene scene;
  Drawing d;
  if (!load_solid_scene(o, path, &scene, nullptr, &d.error)) return d;
  return draw_scene(scene, mode);
}

double dist(const Seg& s, double x, double y) {
  const double dx = s.x1 - s.x0, dy = s.y1 - s.y0, len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((x - s.x0) * dx + (y - s.y0) * dy) / len2 : 0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  return std::hypot(s.x0 + t * dx - x, s.y0 + t * dy - y);
}

// The samples (every step along each segment of a, both ends included) farther than `tol`
// steps from every segment of b; *samples counts them all.
size_t uncovered(const std::vector<Seg>& a, const std::vector<Seg>& b, double tol,
                 size_t* samples) {
  const double cell = 64;
  std::unordered_map<int64_t, std::vector<size_t>> grid;
  auto key = [](int64_t cx, int64_t cy) { return cx * 1000003 + cy; };
  for (size_t i = 0; i < b.size(); ++i) {
    const Seg& s = b[i];
    const int64_t x0 = int64_t(std::floor((std::min(s.x0, s.x1) - tol) / cell)),
                  x1 = int64_t(std::floor((std::max(s.x0, s.x1) + tol) / cell)),
                  y0 = int64_t(std::floor((std::min(s.y0, s.y1) - tol) / cell)),
                  y1 = int64_t(std::floor((std::max(s.y0, s.y1) + tol) / cell));
    for (int64_t cx = x0; cx <= x1; ++cx)
      for (int64_t cy = y0; cy <= y1; ++cy) grid[key(cx, cy)].push_back(i);
  }
  size_t far = 0;
  for (const Seg& s : a) {
    const int n = int(std::ceil(std::max(std::fabs(s.x1 - s.x0), std::fabs(s.y1 - s.y0))));
    for (int k = 0; k <= n; ++k) {
      const double t = n > 0 ? double(k) / n : 0;
      const double x = s.x0 + t * (s.x1 - s.x0), y = s.y0 + t * (s.y1 - s.y0);
      ++*samples;
      bool near = false;
      auto it = grid.find(key(int64_t(std::floor(x / cell)), int64_t(std::floor(y / cell))));
      if (it != grid.end())
        for (size_t i : it->second) near = near || dist(b[i], x, y) <= tol;
      far += near ? 0 : 1;
    }
  }
  return far;
}

// Both ways round: the samples of either drawing not within a step of the other.
size_t differ(const std::vector<Seg>& a, const std::vector<Seg>& b, size_t* samples) {
  return uncovered(a, b, 1.0, samples) + uncovered(b, a, 1.0, samples);
}

double length(const std::vector<Seg>& v) {
  double sum = 0;
  for (const Seg& s : v) sum += std::hypot(s.x1 - s.x0, s.y1 - s.y0);
  return sum;
}

// The strokes reflected left-right about the middle of their bounding box.
std::vector<Seg> reflected(std::vector<Seg> v) {
  double lo = 1e300, hi = -1e300;
  for (const Seg& s : v) lo = std::min({lo, s.x0, s.x1}), hi = std::max({hi, s.x0, s.x1});
  for (Seg& s : v) s.x0 = lo + hi - s.x0, s.x1 = lo + hi - s.x1;
  return v;
}

// Assimp's models in pairs. Its spider STLs are the OBJ's vertex set with y and z swapped (a
// mirror image: found by matching the two vertex sets). Read Z-up, the STL is the OBJ (read
// Y-up) with world y negated; seen from azimuth 90 or 270, y runs across the paper and the
// depth does not change, so the picture is the OBJ's reflected left to right.
//
// Both files are cleaned alike, welded at one world position (--weld 0) with only exactly
// coplanar edges left out (--crease exact): the defaults follow each file's own rounding
// (float32 for the STL, 6 decimals for the OBJ), which differ, and a few of Wuson's edges lie
// between the two bounds (at 200,-40 about 100 of 1.7 million samples). assimp's OBJ files give
// vertices on texture seams separate ids at one position, which STL (no ids) cannot, and that
// topology changes what the topology-free fallback decides on these open meshes (printed
// below as "unwelded": --weld off). Cleaned alike, the two files are one mesh and any
// difference is the reader's.
int assimp_models() {
  const std::string dir = "/usr/share/assimp/models/";
  if (!std::ifstream(dir + "OBJ/spider.obj") || !std::ifstream(dir + "STL/Spider_binary.stl")) {
    std::printf("mesh_files: assimp-testmodels not installed (%s): skipped\n", dir.c_str());
    return 77;
  }
  const struct {
    const char *model, *obj, *up;
    bool mirror;
  } pairs[] = {{"STL/Spider_binary.stl", "OBJ/spider.obj", "z", true},
               {"STL/Spider_ascii.stl", "OBJ/spider.obj", "z", true},
               {"STL/Wuson.stl", "OBJ/WusonOBJ.obj", "y", false},
               {"PLY/Wuson.ply", "OBJ/WusonOBJ.obj", "y", false},
               {"PLY/cube.ply", "OBJ/box.obj", "y", false},
               {"PLY/cube_binary.ply", "OBJ/box.obj", "y", false}};
  for (const auto& p : pairs)
    for (const char* view : {p.mirror ? "90,25" : "30,25", p.mirror ? "270,-40" : "200,-40"}) {
      // The plot area these pairs were measured in (20000 x 16000 steps from (400, 400)), not
      // the default A4 page: the binary STL's float32 coordinates against the OBJ's decimals
      // flip a few near-degenerate decisions of the fallback at some scales (on the A4
      // default, 55 of 1.5 million samples of the spider at 270,-40 lie a step or more apart).
      const std::map<std::string, std::string> area = {
          {"--page", "260x210"}, {"--margin", "5"}, {"--crease", "exact"}};
      std::map<std::string, std::string> welded = area, unwelded = area;
      welded["--weld"] = "0";
      unwelded["--weld"] = "off";
      const Drawing a = draw_file(dir + p.model, view, SolidMode::kHiddenRemoved, p.up, welded);
      const Drawing b = draw_file(dir + p.obj, view, SolidMode::kHiddenRemoved, "y", welded);
      const Drawing raw = draw_file(dir + p.obj, view, SolidMode::kHiddenRemoved, "y", unwelded);
      const std::string label = std::string(p.model) + " against " + p.obj + " at " + view;
      CHECK_MSG(a.ok && b.ok && raw.ok, label + ": " + a.error + " / " + b.error);
      if (!a.ok || !b.ok || !raw.ok) continue;
      size_t samples = 0, raw_samples = 0;
      const std::vector<Seg> want = p.mirror ? reflected(b.strokes) : b.strokes;
      const size_t bad = differ(a.strokes, want, &samples);
      const size_t raw_bad =
          differ(a.strokes, p.mirror ? reflected(raw.strokes) : raw.strokes, &raw_samples);
      std::printf(
          "%s: %zu and %zu strokes, %zu of %zu samples farther than a step (unwelded "
          "OBJ: %zu of %zu)\n",
          label.c_str(), a.strokes.size(), b.strokes.size(), bad, samples, raw_bad, raw_samples);
      CHECK_MSG(bad == 0 && samples > 100, label + ": the visible lines differ");
    }
  return check::finish("mesh_files assimp");
}

}  // namespace

int repair_cases();

int main(int argc, char** argv) {
  const std::string part = argc > 1 ? argv[1] : "";
  if (part == "assimp") return assimp_models();
  if (part == "repair") return repair_cases();
  std::fprintf(stderr, "usage: mesh_files assimp|repair\n");
  return 2;
}

namespace {

using solid_scenes::Mesh;

void write_obj(const std::string& path, const Mesh& m) {
  std::ofstream out(path);
  for (const Point3& p : m.v) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
  for (const auto& f : m.faces) {
    out << 'f';
    for (uint32_t c : f) out << ' ' << c + 1;
    out << '\n';
  }
}

// Binary STL, each triangle (each polygon fanned) with its own vertices: a soup.
void write_soup_stl(const std::string& path, const Mesh& m) {
  std::vector<std::array<uint32_t, 3>> tris;
  for (const auto& f : m.faces)
    for (size_t i = 1; i + 1 < f.size(); ++i) tris.push_back({f[0], f[i], f[i + 1]});
  std::string b(80, ' ');
  auto u32 = [&](uint32_t v) {
    for (int k = 0; k < 4; ++k) b += char((v >> (8 * k)) & 0xFF);
  };
  u32(uint32_t(tris.size()));
  for (const auto& t : tris) {
    b += std::string(12, '\0');  // the normal: readers ignore it
    for (uint32_t c : t)
      for (int32_t x : {m.v[c].x, m.v[c].y, m.v[c].z}) {
        const float f = float(x);  // exact: |x| < 2^24
        uint32_t u;
        std::memcpy(&u, &f, 4);
        u32(u);
      }
    b += std::string(2, '\0');
  }
  std::ofstream(path, std::ios::binary) << b;
}

Mesh reversed(Mesh m) {
  for (auto& f : m.faces) std::reverse(f.begin(), f.end());
  return m;
}

// x negated, or y and z swapped: mirrors, so the faces as given now wind inward.
Mesh mirrored(Mesh m, bool swap_yz) {
  for (Point3& p : m.v) p = swap_yz ? Point3{p.x, p.z, p.y} : Point3{-p.x, p.y, p.z};
  return m;
}

// The solids, centred with their largest extent 2^19 so the readers' fitting leaves every
// coordinate as written (the reference and the files then hold the same integers).
Mesh box_model() {
  Mesh m;
  solid_scenes::box(&m, -262144, -180000, -120000, 262144, 180000, 120000);
  return m;
}

Mesh torus_model() {  // as triangles: its soup and its mesh have the same faces
  Mesh q;
  solid_scenes::torus(&q, 0, 0, 0, 180000, 82144, 16, 8);
  Mesh m;
  m.v = q.v;
  for (const auto& f : q.faces) {
    m.face({f[0], f[1], f[2]});
    m.face({f[0], f[2], f[3]});
  }
  return m;
}

Drawing reference(const Mesh& m, const std::string& view_text, SolidMode mode) {
  Options o;
  o.values["--view"] = view_text;
  View v;
  std::string error;
  parse_view(o, &v, &error);
  SolidScene scene;
  if (!solid_scenes::project(m, v, &scene)) return Drawing{};
  return draw_scene(scene, mode);
}

void same_drawing(const Drawing& got, const Drawing& want, bool dashed, const std::string& label) {
  CHECK_MSG(got.ok && want.ok, label + ": not drawn: " + got.error);
  if (!got.ok || !want.ok) return;
  size_t samples = 0;
  size_t bad = differ(got.visible, want.visible, &samples);
  if (dashed) bad += differ(got.hidden, want.hidden, &samples);
  std::printf("%s: %zu edges (reference %zu), %s, %zu of %zu samples farther than a step\n",
              label.c_str(), got.edges, want.edges, got.qi ? "QI" : "fallback", bad, samples);
  CHECK_MSG(bad == 0 && samples > 100, label + ": draws differently from the correct model");
}

void model_cases(const std::string& name, const Mesh& m, const std::string& view) {
  struct Case {
    std::string file;
    Mesh reference;
    std::map<std::string, std::string> options;
  };
  const std::string dir = "mesh_files_" + name;
  write_obj(dir + "_correct.obj", m);
  write_obj(dir + "_reversed.obj", reversed(m));
  write_obj(dir + "_mirror_x.obj", mirrored(m, false));
  write_obj(dir + "_mirror_yz.obj", mirrored(m, true));
  write_soup_stl(dir + "_soup.stl", m);
  // The torus is triangles in the reference too, every side drawn: no crease filter there.
  // The box is quads, so its soup's diagonals go by the default crease (coplanar faces).
  std::map<std::string, std::string> o;
  if (name == "torus") o["--crease"] = "off";
  const Case cases[] = {{dir + "_correct.obj", m, o},
                        {dir + "_reversed.obj", m, o},
                        {dir + "_mirror_x.obj", reversed(mirrored(m, false)), o},
                        {dir + "_mirror_yz.obj", reversed(mirrored(m, true)), o},
                        {dir + "_soup.stl", m, o}};
  for (const Case& c : cases)
    for (SolidMode mode : {SolidMode::kHiddenRemoved, SolidMode::kHiddenDashed}) {
      const bool dashed = mode == SolidMode::kHiddenDashed;
      const Drawing want = reference(c.reference, view, mode);
      const Drawing got = draw_file(c.file, view, mode, "z", c.options);
      same_drawing(got, want, dashed,
                   c.file + (dashed ? " hidden-dashed" : " hidden-removed") + " at " + view);
      CHECK_MSG(got.qi, c.file + ": a closed solid is drawn by QI");
      CHECK_MSG(got.edges == want.edges && std::fabs(length(got.visible) - length(want.visible)) <
                                               1e-6 * length(want.visible) + 1,
                c.file + ": every edge drawn once (" + std::to_string(got.edges) + " edges, " +
                    std::to_string(length(got.visible)) + " visible steps; the reference " +
                    std::to_string(want.edges) + ", " + std::to_string(length(want.visible)) + ")");
    }
}

}  // namespace

int repair_cases() {
  for (const char* view : {"30,25", "250,-35"}) {
    model_cases("box", box_model(), view);
    model_cases("torus", torus_model(), view);
  }
  return check::finish("mesh_files repair");
}
