// The plot SVG against the G-code and HPGL of the same planned layers, each read back by a
// small reader written here: as many subpaths as pen-down runs, every point at the same paper
// position (SVG y = page height - G-code Y), the strokes covering exactly the input spans;
// and the page: named sizes, orientation, the drawable area and the centring offset against
// hand-worked values.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <random>
#include <sstream>
#include <tuple>

#include "../check.h"
#include "cli/page_options.h"
#include "export/exporters.h"
#include "export/page.h"
#include "export/plot_layers.h"
#include "render/svg.h"

using namespace haloplot;
using namespace haloplot::host;

namespace {

using Pt = std::pair<int64_t, int64_t>;  // thousandths of a millimetre
using Run = std::vector<Pt>;
using Seg = std::tuple<int64_t, int64_t, int64_t, int64_t>;

Seg undirected(Pt a, Pt b) {
  if (b < a) std::swap(a, b);
  return Seg{a.first, a.second, b.first, b.second};
}

int64_t thousandths(const std::string& t) {
  const bool neg = !t.empty() && t[0] == '-';
  const std::string a = neg ? t.substr(1) : t;
  const size_t dot = a.find('.');
  std::string frac = dot == std::string::npos ? "" : a.substr(dot + 1);
  frac = (frac + "000").substr(0, 3);
  const int64_t v = std::stoll(a.substr(0, dot)) * 1000 + std::stoll(frac);
  return neg ? -v : v;
}

// Every `d="..."`: "M x,y L x,y x,y ...", one subpath per M.
std::vector<Run> svg_runs(const std::string& svg) {
  std::vector<Run> runs;
  for (size_t at = svg.find(" d=\""); at != std::string::npos; at = svg.find(" d=\"", at + 1)) {
    const size_t end = svg.find('"', at + 4);
    std::string d = svg.substr(at + 4, end - at - 4);
    for (char& c : d)
      if (c == ',') c = ' ';
    std::istringstream in(d);
    std::string tok;
    while (in >> tok) {
      if (tok[0] == 'M') runs.emplace_back();
      const std::string x = std::isalpha(static_cast<unsigned char>(tok[0])) ? tok.substr(1) : tok;
      std::string y;
      in >> y;
      runs.back().push_back({thousandths(x), thousandths(y)});
    }
  }
  return runs;
}

// G-code: a run starts where the pen goes down (M3) and takes each G1 X Y after it.
std::vector<Run> gcode_runs(const std::string& g) {
  std::vector<Run> runs;
  std::istringstream in(g);
  std::string line;
  Pt at{0, 0};
  bool down = false;
  while (std::getline(in, line)) {
    std::istringstream f(line);
    std::string w, a, b;
    f >> w >> a >> b;
    if (w == "M3") down = true, runs.push_back({at});
    if (w == "M5") down = false;
    if ((w == "G0" || w == "G1") && !a.empty() && a[0] == 'X') {
      at = {thousandths(a.substr(1)), thousandths(b.substr(1))};
      if (down) runs.back().push_back(at);
    }
  }
  return runs;
}

// HPGL: PD x,y,... after the pen's last position, in 1/40 mm.
std::vector<std::vector<Pt>> hpgl_runs(const std::string& h) {
  std::vector<std::vector<Pt>> runs;
  Pt at{0, 0};
  std::istringstream in(h);
  std::string cmd;
  while (std::getline(in, cmd, ';')) {
    if (cmd.size() < 2 || (cmd.compare(0, 2, "PU") != 0 && cmd.compare(0, 2, "PD") != 0)) continue;
    std::vector<int64_t> v;
    std::istringstream nums(cmd.substr(2));
    std::string n;
    while (std::getline(nums, n, ',')) v.push_back(std::stoll(n));
    if (cmd[1] == 'D') runs.push_back({at});
    for (size_t i = 0; i + 1 < v.size(); i += 2) {
      at = {v[i], v[i + 1]};
      if (cmd[1] == 'D') runs.back().push_back(at);
    }
  }
  return runs;
}

void layers_against_exports() {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int32_t> coord(0, 30), step(-2, 2);
  std::vector<StrokeLayer> layers = {
      {"1 visible", {}, 1}, {"2 hidden", {}, 1}, {"5 outlines", {}, 2.5}};
  std::map<Seg, int> want;
  for (StrokeLayer& l : layers)
    for (int i = 0; i < 300; ++i) {
      // On a coarse grid, so spans share ends and the planner joins them into polylines.
      const int32_t x0 = 500 + 40 * coord(rng), y0 = 700 + 40 * coord(rng);
      const int32_t x1 = x0 + 40 * step(rng), y1 = y0 + 40 * step(rng);
      if (x0 == x1 && y0 == y1) continue;
      l.spans.push_back(Span{{0, 0, 0}, x0, y0, x1, y1});
      ++want[undirected(Pt{x0, y0}, Pt{x1, y1})];
    }
  std::vector<PlannedLayer> planned;
  // Every span as given (the clean-up would merge the grid's overlaps: path_export tests it).
  CHECK(ok(plan_layers(layers, &planned, PathClean{false, 0})));
  PlotSvgStyle style;
  style.placement.steps_per_mm = 80;
  style.placement.offset_x = 37, style.placement.offset_y = -12;  // any page placement
  std::ostringstream svg, gcode, hpgl;
  write_plot_svg(svg, planned, style);
  write_gcode(gcode, joined_path(planned), Machine{}, style.placement);
  write_hpgl(hpgl, joined_path(planned), style.placement);
  const std::vector<Run> s = svg_runs(svg.str()), g = gcode_runs(gcode.str());
  const auto h = hpgl_runs(hpgl.str());
  CHECK_EQ(s.size(), g.size());
  CHECK_EQ(s.size(), h.size());
  CHECK(s.size() < 900);  // joined: fewer strokes than spans
  const int64_t page_h = style.page.height_um;
  std::map<Seg, int> got;
  for (size_t r = 0; r < std::min({s.size(), g.size(), h.size()}); ++r) {
    CHECK_EQ(s[r].size(), g[r].size());
    CHECK_EQ(s[r].size(), h[r].size());
    for (size_t i = 0; i < std::min({s[r].size(), g[r].size(), h[r].size()}); ++i) {
      const Pt paper{s[r][i].first, page_h - s[r][i].second};  // y up, as the G-code's
      CHECK(paper == g[r][i]);
      // 1/40 mm: 0.025 mm = 25 thousandths, to the HPGL's rounding and the SVG's.
      CHECK(std::llabs(h[r][i].first * 25 - paper.first) <= 13);
      CHECK(std::llabs(h[r][i].second * 25 - paper.second) <= 13);
      if (i == 0) continue;
      // Back to steps: thousandths * 80 / 1000 less the offset; exact at 80 steps/mm.
      const auto steps = [&](Pt p) {
        return Pt{(p.first * 80 + 500) / 1000 - 37, (p.second * 80 + 500) / 1000 + 12};
      };
      ++got[undirected(steps(g[r][i - 1]), steps(g[r][i]))];
    }
  }
  CHECK(got == want);
  CHECK(svg.str().find("<rect") == std::string::npos);
  CHECK(svg.str().find("inkscape:label=\"5 outlines\"") != std::string::npos);
}

void pages() {
  Options o;
  Page p;
  std::string error;
  CHECK(parse_page(o, &p, &error) && p.width_um == 297000 && p.height_um == 210000 &&
        p.margin_um == 10000);  // the default: A4 landscape, 10 mm
  o.values["--page"] = "a4";
  CHECK(parse_page(o, &p, &error) && p.width_um == 210000 && p.height_um == 297000);
  o.flags.insert("--landscape");
  CHECK(parse_page(o, &p, &error) && p.width_um == 297000 && p.height_um == 210000);
  o.values["--page"] = "Letter";
  CHECK(parse_page(o, &p, &error) && p.width_um == 279400 && p.height_um == 215900);
  o.flags.clear();
  o.values["--page"] = "300x100.5";
  o.values["--margin"] = "2.5";
  CHECK(parse_page(o, &p, &error) && p.width_um == 300000 && p.height_um == 100500 &&
        p.margin_um == 2500);
  for (const char* bad : {"a9", "300x", "x100", "300x100.1234", "-3x4"}) {
    o.values["--page"] = bad;
    CHECK(!parse_page(o, &p, &error) && error.find("--page") == 0);
  }
  o.values["--page"] = "a4";
  o.values["--margin"] = "105";  // half the short side: nothing left
  CHECK(!parse_page(o, &p, &error));
  o.values["--margin"] = "10";
  o.values["--scale"] = "0.5";
  o.flags.insert("--fit");
  CHECK(!parse_page(o, &p, &error));

  // A4 landscape, 10 mm margins, 80 steps/mm: the area from (800, 800), 277 x 190 mm.
  Page a4;
  int32_t m = 0, w = 0, h = 0;
  CHECK(page_area(a4, 80, &m, &w, &h) && m == 800 && w == 22160 && h == 15200);
  // Letter at 3 steps/mm, margin 0.5 mm: the margin rounds up (2), the far edges down.
  Page letter;
  letter.width_um = 215900, letter.height_um = 279400, letter.margin_um = 500;
  CHECK(page_area(letter, 3, &m, &w, &h) && m == 2 && w == 646 - 2 && h == 836 - 2);

  // Centring by hand: 100 x 100 mm, margin 10, 10 steps/mm: the area [100, 900] on both axes.
  Page sq;
  sq.width_um = sq.height_um = 100000;
  std::vector<PathPoint> path = {{0, 0, 0}, {100, 50, 0}, {300, 150, 1}, {5000, 5000, 0}};
  int32_t ox = 0, oy = 0;
  centring_offset(sq, 10, path, &ox, &oy);
  CHECK(ox == 300 && oy == 400);  // the box [100, 300] x [50, 150] to [400, 600] x [450, 550]
  path = {{0, 0, 0}, {101, 50, 0}, {300, 150, 1}};
  centring_offset(sq, 10, path, &ox, &oy);
  CHECK(ox == 299 && oy == 400);  // a half step: the step below
  centring_offset(sq, 10, {{0, 0, 0}, {10, 10, 0}}, &ox, &oy);
  CHECK(ox == 0 && oy == 0);  // nothing drawn
}

// The SVG's layers cut from one path the job planned for all of them (plot --gcode plans once)
// against plan_layers(), which plans each layer on its own: the same points, starts, labels and
// widths; and counts that do not fit the layers are refused, never cut anyhow.
void layers_cut_from_one_path() {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int32_t> coord(0, 20), step(-1, 1);
  std::vector<StrokeLayer> layers = {{"1 visible", {}, 1},
                                     {"2 hidden", {}, 1},
                                     {"3 intersections", {}, 1},
                                     {"4 hatching", {}, 1},
                                     {"5 outlines", {}, 2.5}};
  for (size_t k : {0, 1, 4})  // the third and fourth layers empty, as in most drawings
    for (int i = 0; i < 200; ++i) {
      const int32_t x0 = 100 + 30 * coord(rng), y0 = 100 + 30 * coord(rng);
      const int32_t x1 = x0 + 30 * step(rng), y1 = y0 + 30 * step(rng);
      if (x0 != x1 || y0 != y1) layers[k].spans.push_back(Span{{0, 0, 0}, x0, y0, x1, y1});
    }
  std::vector<Segment2> segs;
  LayerCounts counts;
  counts.n = uint32_t(layers.size());
  for (size_t k = 0; k < layers.size(); ++k) {
    counts.count[k] = uint32_t(layers[k].spans.size());
    for (const Span& x : layers[k].spans) segs.push_back(Segment2{x.x0, x.y0, x.x1, x.y1});
  }
  const uint32_t n = uint32_t(segs.size());
  std::vector<uint64_t> work(path_plan_bytes(n) / 8 + 1);
  std::vector<PathPoint> points(path_points_max(n));
  uint32_t count = 0;
  LayerCounts per_layer;
  CHECK(ok(plan_path_layers(segs.data(), n, counts, 0, 0, work.data(), work.size() * 8,
                            points.data(), uint32_t(points.size()), &count, &per_layer, nullptr)));
  points.resize(count);
  std::vector<PlannedLayer> want, got;
  CHECK(ok(plan_layers(layers, &want)));
  CHECK(cut_planned_layers(layers, points, per_layer, &got));
  CHECK_EQ(got.size(), size_t{3});
  CHECK_EQ(got.size(), want.size());
  for (size_t i = 0; i < std::min(got.size(), want.size()); ++i) {
    CHECK(got[i].label == want[i].label);
    CHECK(got[i].pen_width == want[i].pen_width);
    CHECK(got[i].start_x == want[i].start_x && got[i].start_y == want[i].start_y);
    CHECK_EQ(got[i].path.size(), want[i].path.size());
    CHECK(std::equal(got[i].path.begin(), got[i].path.end(), want[i].path.begin(),
                     want[i].path.end(), [](const PathPoint& a, const PathPoint& b) {
                       return a.x == b.x && a.y == b.y && a.pen_down == b.pen_down;
                     }));
  }
  CHECK(got[1].start_x != 0 || got[1].start_y != 0);  // the second layer starts where one ended
  // Counts that do not fit: another layer count, a point moved between layers, a point short.
  LayerCounts bad = per_layer;
  bad.n = 4;
  CHECK(!cut_planned_layers(layers, points, bad, &got) && got.empty());
  bad = per_layer;
  ++bad.count[0], --bad.count[1];
  CHECK(cut_planned_layers(layers, points, bad, &got));  // fits, though cut elsewhere
  bad.count[2] = 1, --bad.count[4];                      // a point for a layer with no strokes
  CHECK(!cut_planned_layers(layers, points, bad, &got) && got.empty());
  bad = per_layer;
  --bad.count[4];
  CHECK(!cut_planned_layers(layers, points, bad, &got) && got.empty());
  points.pop_back();
  CHECK(!cut_planned_layers(layers, points, per_layer, &got) && got.empty());
}

}  // namespace

int main() {
  layers_against_exports();
  layers_cut_from_one_path();
  pages();
  return check::finish("plot_svg");
}
