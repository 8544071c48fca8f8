// Path planning covers exactly the input spans (each once, in either direction, nothing
// else), chains what touches, beats the naive order, and the G-code and HPGL exporters parse
// back, in a small reader written here, to the same strokes.
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

#include "../check.h"
#include "../support/scenes.h"
#include "demo/cube_array.h"
#include "export/exporters.h"
#include "motion/path_plan.h"

using namespace haloplot;
using namespace haloplot::host;

using Key = std::tuple<int32_t, int32_t, int32_t, int32_t>;
static Key undirected(int32_t a, int32_t b, int32_t c, int32_t d) {
  return std::make_pair(a, b) <= std::make_pair(c, d) ? Key{a, b, c, d} : Key{c, d, a, b};
}

static std::vector<PathPoint> plan(const std::vector<Segment2>& spans, PathStats* st) {
  std::vector<uint64_t> ws(path_plan_bytes(uint32_t(spans.size())) / 8 + 1);
  std::vector<PathPoint> out(path_points_max(uint32_t(spans.size())));
  uint32_t n = 0;
  CHECK(ok(plan_path(spans.data(), uint32_t(spans.size()), 0, 0, ws.data(), ws.size() * 8,
                     out.data(), uint32_t(out.size()), &n, st)));
  out.resize(n);
  return out;
}

static void covers(const std::vector<Segment2>& spans, const std::string& label) {
  PathStats st;
  const auto pts = plan(spans, &st);
  std::map<Key, int> want, got;
  for (const auto& s : spans) ++want[undirected(s.x0, s.y0, s.x1, s.y1)];
  for (size_t i = 1; i < pts.size(); ++i)
    if (pts[i].pen_down) ++got[undirected(pts[i - 1].x, pts[i - 1].y, pts[i].x, pts[i].y)];
  CHECK_MSG(got == want, label + ": planned strokes differ from the spans");
  CHECK_MSG(!pts.empty() && pts[0].pen_down == 0, label + ": starts with travel");
  CHECK_MSG(st.pen_up_length <= st.naive_pen_up_length,
            label + ": planned travel longer than naive");
}

int main() {
  scenes::Rng r(21);
  {  // Chains in shuffled order and mixed directions become one stroke.
    const std::vector<Segment2> chain = {
        {200, 0, 300, 50}, {100, 0, 200, 0}, {300, 50, 400, 0}, {100, 0, 0, 0}};
    PathStats st;
    const auto pts = plan(chain, &st);
    CHECK_EQ(st.polylines, 1u);
    CHECK_EQ(pts.size(), size_t{5});  // one travel, four strokes
    covers(chain, "chain");
  }
  {  // Random families: loops, stars (degree > 2), dots, duplicates, isolated spans.
    std::vector<Segment2> s;
    for (int i = 0; i < 300; ++i) {
      const int32_t x = int32_t(r.uniform(0, 5000)), y = int32_t(r.uniform(0, 5000));
      s.push_back({x, y, int32_t(x + r.uniform(-300, 300)), int32_t(y + r.uniform(-300, 300))});
    }
    for (int i = 0; i < 12; ++i)
      s.push_back({2500, 2500, int32_t(r.uniform(0, 5000)), int32_t(r.uniform(0, 5000))});
    for (int i = 0; i < 8; ++i)
      s.push_back({1000 + 100 * i, 1000, 1000 + 100 * (i + 1) % 800, 1000 + 50 * (i % 2)});
    s.push_back({77, 77, 77, 77});
    s.push_back(s[5]);
    covers(s, "random families");
  }
  {  // The demo: polylines through the cube edges, and a large travel saving.
    CubeArrayParams c;
    c.cubes = 10;
    std::vector<Segment2> s;
    for (const Edge3& e : cube_array(c)) s.push_back({e.a.x, e.a.y, e.b.x, e.b.y});
    std::reverse(s.begin(), s.end());
    PathStats st;
    plan(s, &st);
    covers(s, "cube array");
    CHECK(st.polylines < s.size() / 2);
    CHECK(st.pen_up_length * 3 < st.naive_pen_up_length);
  }
  {  // Exporters parse back to the same strokes.
    CubeArrayParams c;
    c.cubes = 4;
    std::vector<Segment2> s;
    for (const Edge3& e : cube_array(c)) s.push_back({e.a.x, e.a.y, e.b.x, e.b.y});
    PathStats st;
    const auto pts = plan(s, &st);
    for (bool by_z : {false, true}) {
      ExportStyle style;
      style.pen_by_z = by_z;
      std::ostringstream g;
      write_gcode(g, pts, Machine{}, style);
      // Reader: pen state from M3/M5 or Z, positions from X/Y on G0/G1, in mm -> steps.
      std::istringstream in(g.str());
      std::string line;
      bool down = false;
      std::vector<PathPoint> back;
      while (std::getline(in, line)) {
        std::istringstream w(line);
        std::string cmd;
        w >> cmd;
        if (cmd == "M3") down = true;
        if (cmd == "M5") down = false;
        std::string word;
        double x = 0, y = 0;
        bool has_xy = false;
        while (w >> word) {
          if (word[0] == 'X') x = std::stod(word.substr(1)), has_xy = true;
          if (word[0] == 'Y') y = std::stod(word.substr(1));
          if (word[0] == 'Z') down = std::stod(word.substr(1)) < 1.0;
        }
        if ((cmd == "G0" || cmd == "G1") && has_xy)
          back.push_back(
              PathPoint{int32_t(std::lround(x * 80)), int32_t(std::lround(y * 80)), uint8_t(down)});
      }
      bool same = back.size() == pts.size();
      for (size_t i = 0; same && i < pts.size(); ++i)
        same =
            back[i].x == pts[i].x && back[i].y == pts[i].y && back[i].pen_down == pts[i].pen_down;
      CHECK_MSG(same, std::string("G-code parse-back") + (by_z ? " (Z pen)" : " (M3/M5)"));
    }
    std::ostringstream h;
    write_hpgl(h, pts, ExportStyle{});
    // Reader: instructions split on ';', PU/PD followed by x,y pairs in 1/40 mm.
    std::vector<PathPoint> back;
    std::string text = h.str(), ins;
    std::istringstream in(text);
    CHECK(text.rfind("IN;SP1;", 0) == 0);
    while (std::getline(in, ins, ';')) {
      if (ins.size() < 2 || (ins.substr(0, 2) != "PU" && ins.substr(0, 2) != "PD")) continue;
      const bool down = ins[1] == 'D';
      std::istringstream nums(ins.substr(2));
      std::string a, b;
      while (std::getline(nums, a, ',') && std::getline(nums, b, ','))
        back.push_back(
            PathPoint{int32_t(std::stol(a)) * 2, int32_t(std::stol(b)) * 2, uint8_t(down)});
    }
    bool same = back.size() == pts.size();
    for (size_t i = 0; same && i < pts.size(); ++i)  // 40 units/mm vs 80 steps/mm: within 1 step
      same = std::abs(back[i].x - pts[i].x) <= 1 && std::abs(back[i].y - pts[i].y) <= 1 &&
             back[i].pen_down == pts[i].pen_down;
    CHECK_MSG(same, "HPGL parse-back");
  }
  return check::finish("path_export");
}
