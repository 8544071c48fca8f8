// Issue 45's reference for meshes of any kind: `haloplot plot --mode hidden-removed --crease 40`
// against a brute-force float64 drawing of the same OBJ (tests/reference/mesh_reference.h:
// every edge classified from the faces, every piece's visibility ray cast; no code of core/ or
// host_sim/ is included or linked: the plot is read from its SVG). Both ways, at least 97 % of
// the ink must lie within 2 steps of the other's.
//
// Scenes: Debian's assimp-testmodels OBJ/WusonOBJ.obj and OBJ/spider.obj, and generated here:
// a torus with a slot cut along its tube (open: boundary rims, the tube's inside seen through
// the slot), a Moebius strip beside two closed boxes (one shell that cannot be oriented), three
// curved fins on one edge beside a box, and two boxes sharing an edge beside a sphere
// (non-manifold edges), and a
// closed torus beside a closed box (the sanity scene). Each at two views, each by the plot's
// default method and by `--method fallback` (so a topology-free method that leaves contours
// out fails even where the default method is right).
//
// Usage: mesh_reference HALOPLOT MODELS_DIR OUT_DIR [scenes=a,b,...] [legs=auto,fallback]
//        [plant]
// `plant` compares the reference with `--mode all --crease 40`'s visible layer: the visible
// edges with no contours worked out, which must fail. OUT_DIR keeps, per run, the plot's SVG
// and NAME.check.svg: the plot's ink in grey, what of it the reference lacks in red, what of
// the reference it lacks in blue. Exit 0 when every run agrees, 1 when one does not, 77 (skip)
// when a model file is missing.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "reference/mesh_reference.h"

namespace mr = mesh_reference;

namespace {

constexpr double kTolerance = 2.0;  // steps
constexpr double kShare = 0.97;
constexpr double kCrease = 40.0;

// ---- Generated scenes, written as OBJ (Y-up: a world point (x, y, z) is written x z -y) ----

struct Obj {
  std::ostringstream text;
  int n = 0;
  int v(double x, double y, double z) {
    text << "v " << x << ' ' << z << ' ' << -y << '\n';
    return ++n;
  }
  void f(std::initializer_list<int> ids) {
    text << 'f';
    for (int i : ids) text << ' ' << i;
    text << '\n';
  }
};

void box(Obj* o, double x0, double y0, double z0, double x1, double y1, double z1) {
  int c[8];
  for (int i = 0; i < 8; ++i) c[i] = o->v(i & 1 ? x1 : x0, i & 2 ? y1 : y0, i & 4 ? z1 : z0);
  // Counter-clockwise seen from outside.
  o->f({c[0], c[2], c[3], c[1]});  // bottom
  o->f({c[4], c[5], c[7], c[6]});  // top
  o->f({c[0], c[1], c[5], c[4]});  // front (y0)
  o->f({c[2], c[6], c[7], c[3]});  // back (y1)
  o->f({c[0], c[4], c[6], c[2]});  // left (x0)
  o->f({c[1], c[3], c[7], c[5]});  // right (x1)
}

// A torus about the z axis at (cx, cy); faces with keep(i, j) false left out (the slot).
template <typename Keep>
void torus(Obj* o, double cx, double cy, double R, double r, int nu, int nv, Keep keep) {
  std::vector<int> id(size_t(nu * nv));
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * mr::kPi * i / nu, w = 2 * mr::kPi * j / nv;
      id[size_t(i * nv + j)] = o->v(cx + (R + r * std::cos(w)) * std::cos(u),
                                    cy + (R + r * std::cos(w)) * std::sin(u), r * std::sin(w));
    }
  auto at = [&](int i, int j) { return id[size_t((i % nu) * nv + j % nv)]; };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
      if (keep(i, j)) o->f({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
}

// A UV sphere: nu around, nv from pole to pole, triangles at the poles.
void sphere(Obj* o, double cx, double cy, double cz, double r, int nu, int nv) {
  const int south = o->v(cx, cy, cz - r);
  std::vector<int> id(size_t(nu * (nv - 1)));
  for (int j = 1; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double u = 2 * mr::kPi * i / nu, w = mr::kPi * j / nv - mr::kPi / 2;
      id[size_t((j - 1) * nu + i)] = o->v(cx + r * std::cos(w) * std::cos(u),
                                          cy + r * std::cos(w) * std::sin(u), cz + r * std::sin(w));
    }
  const int north = o->v(cx, cy, cz + r);
  auto at = [&](int j, int i) { return id[size_t((j - 1) * nu + i % nu)]; };
  for (int i = 0; i < nu; ++i) {
    o->f({south, at(1, i + 1), at(1, i)});
    o->f({north, at(nv - 1, i), at(nv - 1, i + 1)});
    for (int j = 1; j + 1 < nv; ++j) o->f({at(j, i), at(j, i + 1), at(j + 1, i + 1), at(j + 1, i)});
  }
}

// A Moebius strip about (cx, cy): radius R, half-width h, nu steps round, two triangles
// strips across; its last column joins the first turned over.
void moebius(Obj* o, double cx, double cy, double R, double h, int nu) {
  std::vector<int> id(size_t(nu * 3));
  for (int i = 0; i < nu; ++i)
    for (int k = 0; k < 3; ++k) {
      const double u = 2 * mr::kPi * i / nu, s = h * (k - 1);
      id[size_t(i * 3 + k)] =
          o->v(cx + (R + s * std::cos(u / 2)) * std::cos(u),
               cy + (R + s * std::cos(u / 2)) * std::sin(u), s * std::sin(u / 2));
    }
  for (int i = 0; i < nu; ++i)
    for (int k = 0; k < 2; ++k) {
      const int a = id[size_t(i * 3 + k)], b = id[size_t(i * 3 + k + 1)];
      const bool wrap = i + 1 == nu;
      const int c = wrap ? id[size_t(2 - k)] : id[size_t((i + 1) * 3 + k)];
      const int d = wrap ? id[size_t(2 - (k + 1))] : id[size_t((i + 1) * 3 + k + 1)];
      o->f({a, c, d});
      o->f({a, d, b});
    }
}

std::string scene_text(const std::string& name) {
  Obj o;
  if (name == "torus_slot") {
    // A slot along the top of the tube over 135 degrees of the near side (u from 165 to 300
    // degrees, the tube's angle from 30 to 120 up its outer side): two boundary rims, the tube's
    // inside seen through it.
    torus(&o, 0, 0, 3, 1, 48, 24,
          [](int i, int j) { return !(i >= 22 && i < 40 && j >= 2 && j < 8); });
  } else if (name == "moebius_boxes") {
    moebius(&o, 0, 0, 2, 0.8, 60);
    box(&o, 3.5, -1, -0.8, 5, 0.5, 0.8);
    box(&o, -5, -1.5, -1, -3.5, 1, 0.4);
  } else if (name == "fins") {
    // Three curved fins on the edge x = y = 0, z in [0, 2] (each bowed sideways, 8 x 2 quads:
    // contours along it); a box beside them.
    const int base = o.v(0, 0, 0), mid = o.v(0, 0, 1), top = o.v(0, 0, 2);
    for (int k = 0; k < 3; ++k) {
      const double a = 2 * mr::kPi * k / 3 + 0.3, cx = std::cos(a), cy = std::sin(a);
      int c[9][3];
      c[0][0] = base, c[0][1] = mid, c[0][2] = top;
      for (int s = 1; s < 9; ++s)
        for (int t = 0; t < 3; ++t) {
          const double r = 1.8 * s / 8, bow = 0.5 * std::sin(mr::kPi * s / 8);
          c[s][t] = o.v(r * cx - bow * cy, r * cy + bow * cx, t);
        }
      for (int s = 0; s < 8; ++s)
        for (int t = 0; t < 2; ++t) o.f({c[s][t], c[s + 1][t], c[s + 1][t + 1], c[s][t + 1]});
    }
    box(&o, 2.5, -1, 0, 3.5, 0.5, 1.5);
  } else if (name == "boxes_edge") {
    // Two boxes sharing one edge (x = y = 1, z in [0, 1]): four faces on it.
    box(&o, 0, 0, 0, 1, 1, 1);
    box(&o, 1, 1, 0, 2, 2, 1);
    sphere(&o, 3.5, 0, 0.6, 0.8, 32, 16);
  } else if (name == "torus_box") {
    torus(&o, 0, 0, 3, 1, 48, 24, [](int, int) { return true; });
    box(&o, 4.5, -1, -1, 6, 0.5, 1);
  } else {
    return "";
  }
  return o.text.str();
}

// ---- The plot, read from its SVG and spans ----

struct PlotInk {
  std::vector<mr::Seg> ink;  // layer "1 visible", steps, before the page's centring offset
  bool ok = false;
  std::string why;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

PlotInk read_plot(const std::string& svg_path, const std::string& spans_path, double per_mm) {
  PlotInk out;
  const std::string svg = slurp(svg_path);
  if (svg.empty()) {
    out.why = "no SVG";
    return out;
  }
  double page_h = 0;
  {
    const size_t vb = svg.find("viewBox=\"");
    double x0, y0, w;
    if (vb == std::string::npos ||
        std::sscanf(svg.c_str() + vb + 9, "%lf %lf %lf %lf", &x0, &y0, &w, &page_h) != 4) {
      out.why = "no viewBox";
      return out;
    }
  }
  // Every path, with the label of the layer it is in.
  std::vector<mr::Seg> all, visible;
  std::string layer;
  size_t pos = 0;
  while (true) {
    const size_t g = svg.find("inkscape:label=\"", pos), p = svg.find("<path d=\"", pos);
    if (p == std::string::npos) break;
    if (g != std::string::npos && g < p) {
      const size_t e = svg.find('"', g + 16);
      layer = svg.substr(g + 16, e - g - 16);
      pos = e;
      continue;
    }
    const size_t e = svg.find('"', p + 9);
    std::string d = svg.substr(p + 9, e - p - 9);
    pos = e;
    for (char& c : d)
      if (c == 'M' || c == 'L' || c == ',') c = ' ';
    std::istringstream ds(d);
    double X, Y, px = 0, py = 0;
    bool first = true;
    while (ds >> X >> Y) {
      const double x = X * per_mm, y = (page_h - Y) * per_mm;
      if (!first) {
        all.push_back({px, py, x, y});
        if (layer == "1 visible") visible.push_back({px, py, x, y});
      }
      first = false, px = x, py = y;
    }
  }
  // The centring offset: the SVG's strokes' box less the spans' box (docs/formats.md).
  double sx0 = 1e300, sy0 = 1e300, sx1 = -1e300, sy1 = -1e300;
  for (const mr::Seg& s : all)
    sx0 = std::min({sx0, s.x0, s.x1}), sx1 = std::max({sx1, s.x0, s.x1}),
    sy0 = std::min({sy0, s.y0, s.y1}), sy1 = std::max({sy1, s.y0, s.y1});
  double tx0 = 1e300, ty0 = 1e300, tx1 = -1e300, ty1 = -1e300;
  std::ifstream spans(spans_path);
  std::string line;
  while (std::getline(spans, line)) {
    if (line.size() < 2 || line[0] != 's') continue;
    long e, a, b, c, d;
    if (std::sscanf(line.c_str(), "s %ld %ld %ld %ld %ld", &e, &a, &b, &c, &d) != 5) continue;
    tx0 = std::min({tx0, double(a), double(c)}), tx1 = std::max({tx1, double(a), double(c)});
    ty0 = std::min({ty0, double(b), double(d)}), ty1 = std::max({ty1, double(b), double(d)});
  }
  if (!all.empty()) {
    const double ox = std::round(sx0 - tx0), oy = std::round(sy0 - ty0);
    if (std::fabs(sx1 - tx1 - ox) > 0.5 || std::fabs(sy1 - ty1 - oy) > 0.5) {
      out.why = "the SVG's box is not the spans' box moved";
      return out;
    }
    for (mr::Seg& s : visible) s.x0 -= ox, s.x1 -= ox, s.y0 -= oy, s.y1 -= oy;
  }
  out.ink = visible;
  out.ok = true;
  return out;
}

// ---- One comparison ----

struct Run {
  std::string scene, model, view, leg;
};

void write_check_svg(const std::string& path, const std::vector<mr::Seg>& plot,
                     const std::vector<mr::Seg>& plot_miss, const std::vector<mr::Seg>& ref_miss,
                     double per_mm) {
  std::ofstream o(path);
  const double w = 297, h = 210;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "mm\" height=\"" << h
    << "mm\" viewBox=\"0 0 " << w << ' ' << h << "\">\n";
  auto layer = [&](const std::vector<mr::Seg>& segs, const char* colour, double width) {
    o << "<g fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"" << width
      << "\" stroke-linecap=\"round\">\n";
    for (const mr::Seg& s : segs)
      o << "<path d=\"M" << s.x0 / per_mm << ',' << h - s.y0 / per_mm << " L" << s.x1 / per_mm
        << ',' << h - s.y1 / per_mm << "\"/>\n";
    o << "</g>\n";
  };
  layer(plot, "#888", 0.2);
  layer(plot_miss, "red", 0.6);
  layer(ref_miss, "blue", 0.6);
  o << "</svg>\n";
}

bool run_one(const std::string& haloplot, const Run& r, const std::string& out_dir, bool plant) {
  std::string base = out_dir + "/" + r.scene + "_" + r.view + "_" + r.leg;
  for (char& c : base)
    if (c == ',') c = '_';
  std::string cmd = "'" + haloplot + "' plot '" + r.model + "' --crease 40 --weld 0 --view " +
                    r.view + " --no-intersections -o '" + base + ".svg' --spans '" + base +
                    ".spans'";
  cmd += plant ? " --mode all" : " --mode hidden-removed";
  if (!plant && r.leg != "auto") cmd += " --method " + r.leg;
  cmd += " 2> '" + base + ".err'";
  const int rc = std::system(cmd.c_str());
  std::string name = r.scene + " view " + r.view + " " + (plant ? "mode all (planted)" : r.leg);
  if (rc != 0) {
    std::cout << name << ": FAIL: haloplot exited " << rc << ": " << slurp(base + ".err");
    return false;
  }
  const PlotInk plot = read_plot(base + ".svg", base + ".spans", 80);
  if (!plot.ok) {
    std::cout << name << ": FAIL: " << plot.why << "\n";
    return false;
  }
  // The reference.
  const mr::Mesh mesh = mr::read_obj(r.model);
  if (!mesh.error.empty()) {
    std::cout << name << ": FAIL: " << mesh.error << "\n";
    return false;
  }
  mr::View v;
  std::sscanf(r.view.c_str(), "%lf,%lf", &v.az_deg, &v.el_deg);
  const mr::Projected P = mr::project(mesh, v);
  std::vector<mr::Edge> edges = mr::edges_of(mesh);
  mr::classify(mesh, P, kCrease, &edges);
  const mr::Caster caster(mesh, P);
  std::vector<mr::Seg> ref;
  int count[5] = {0, 0, 0, 0, 0};
  for (const mr::Edge& e : edges) {
    ++count[e.kind];
    if (e.kind != mr::kSmooth) caster.visible_pieces(e.a, e.b, &ref);
  }
  std::vector<mr::Seg> plot_miss, ref_miss;
  const mr::Share a = mr::ink_within(plot.ink, ref, kTolerance, &plot_miss);
  const mr::Share b = mr::ink_within(ref, plot.ink, kTolerance, &ref_miss);
  write_check_svg(base + ".check.svg", plot.ink, plot_miss, ref_miss, 80);
  const bool pass = a.fraction() >= kShare && b.fraction() >= kShare;
  char line[400];
  std::snprintf(line, sizeof line,
                "%s: %s: plot ink near the reference %.2f %% of %.0f steps, reference ink near "
                "the plot %.2f %% of %.0f steps (edges: %d boundary, %d non-manifold, %d crease, "
                "%d contour, %d smooth)\n",
                name.c_str(), pass ? "ok" : "FAIL", 100 * a.fraction(), a.total, 100 * b.fraction(),
                b.total, count[mr::kBoundary], count[mr::kNonManifold], count[mr::kCrease],
                count[mr::kContour], count[mr::kSmooth]);
  std::cout << line << std::flush;
  return pass;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  std::string item;
  while (std::getline(in, item, ',')) out.push_back(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::cerr << "usage: mesh_reference HALOPLOT MODELS_DIR OUT_DIR [scenes=a,b] "
                 "[legs=auto,fallback] [plant]\n";
    return 2;
  }
  const std::string haloplot = argv[1], models = argv[2], out_dir = argv[3];
  std::vector<std::string> scenes = {"wuson", "spider",     "torus_slot", "moebius_boxes",
                                     "fins",  "boxes_edge", "torus_box"};
  std::vector<std::string> legs = {"auto", "fallback"};
  bool plant = false;
  for (int i = 4; i < argc; ++i) {
    const std::string a = argv[i];
    if (a.rfind("scenes=", 0) == 0)
      scenes = split(a.substr(7));
    else if (a.rfind("legs=", 0) == 0)
      legs = split(a.substr(5));
    else if (a == "plant")
      plant = true;
    else {
      std::cerr << "unknown argument " << a << "\n";
      return 2;
    }
  }
  if (plant) legs = {"auto"};
  if (std::system(("mkdir -p '" + out_dir + "'").c_str()) != 0) {
    std::cerr << "cannot make " << out_dir << "\n";
    return 2;
  }
  const std::vector<std::string> views = {"30,25", "120,35"};
  bool all_ok = true, missing = false;
  for (const std::string& s : scenes) {
    std::string model;
    if (s == "wuson" || s == "spider") {
      model = models + (s == "wuson" ? "/WusonOBJ.obj" : "/spider.obj");
      if (!std::ifstream(model)) {
        std::cout << s << ": skipped: no " << model << " (Debian's assimp-testmodels)\n";
        missing = true;
        continue;
      }
    } else {
      const std::string text = scene_text(s);
      if (text.empty()) {
        std::cerr << "unknown scene " << s << "\n";
        return 2;
      }
      model = out_dir + "/" + s + ".obj";
      std::ofstream(model) << text;
    }
    for (const std::string& view : views)
      for (const std::string& leg : legs)
        all_ok = run_one(haloplot, {s, model, view, leg}, out_dir, plant) && all_ok;
  }
  if (!all_ok) return 1;
  return missing ? 77 : 0;
}
