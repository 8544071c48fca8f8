// Path planning covers exactly the input spans (each once, in either direction, nothing
// else), with or without a known end, chains what touches, beats the naive order and plain
// greedy nearest neighbour (and comes near the optimum found by brute force), and the G-code and
// HPGL exporters parse back, in a small reader written here, to the same strokes. Spans in
// layers are planned layer after layer, each layer drawing exactly its own spans.
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <sstream>
#include <tuple>

#include "../check.h"
#include "../support/scenes.h"
#include "demo/cube_array.h"
#include "export/exporters.h"
#include "haloplot/motion/path_plan.h"

using namespace haloplot;
using namespace haloplot::host;

using Key = std::tuple<int32_t, int32_t, int32_t, int32_t>;
static Key undirected(int32_t a, int32_t b, int32_t c, int32_t d) {
  return std::make_pair(a, b) <= std::make_pair(c, d) ? Key{a, b, c, d} : Key{c, d, a, b};
}

// The planner as such: the spans planned exactly as given (the clean-up has its own tests).
static std::vector<PathPoint> plan(const std::vector<Segment2>& spans, PathStats* st,
                                   PathEnd end = PathEnd{}, PathClean clean = PathClean{false, 0}) {
  std::vector<uint64_t> ws(path_plan_bytes(uint32_t(spans.size())) / 8 + 1);
  std::vector<PathPoint> out(path_points_max(uint32_t(spans.size())));
  uint32_t n = 0;
  std::vector<Segment2> cleaned = spans;  // the clean-up works in place
  CHECK(ok(plan_path(cleaned.data(), uint32_t(spans.size()), PenAt{0, 0}, ws.data(), ws.size() * 8,
                     out.data(), uint32_t(out.size()), &n, st, end, clean)));
  out.resize(n);
  return out;
}

static void covers(const std::vector<Segment2>& spans, const std::string& label,
                   PathEnd end = PathEnd{}) {
  PathStats st;
  const auto pts = plan(spans, &st, end);
  std::map<Key, int> want, got;
  for (const auto& s : spans) ++want[undirected(s.x0, s.y0, s.x1, s.y1)];
  for (size_t i = 1; i < pts.size(); ++i)
    if (pts[i].pen_down) ++got[undirected(pts[i - 1].x, pts[i - 1].y, pts[i].x, pts[i].y)];
  CHECK_MSG(got == want, label + ": planned strokes differ from the spans");
  CHECK_MSG(!pts.empty() && pts[0].pen_down == 0, label + ": starts with travel");
  CHECK_MSG(st.pen_up_length <= st.naive_pen_up_length,
            label + ": planned travel longer than naive");
}

// Pen-up travel of a planned path, in double precision from its points.
static double travel(const std::vector<PathPoint>& pts) {
  double t = 0;
  int32_t x = 0, y = 0;
  for (const PathPoint& p : pts) {
    if (!p.pen_down) t += std::hypot(double(p.x - x), double(p.y - y));
    x = p.x, y = p.y;
  }
  return t;
}

// Six separate spans: the best order by brute force (every order, every direction), plain
// greedy nearest neighbour written here, and the planner (greedy, then 2-opt).
static void against_optimum(scenes::Rng& r) {
  double ours_sum = 0, greedy_sum = 0, best_sum = 0;
  int worse_than_greedy = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Segment2> s;
    for (int i = 0; i < 6; ++i) {
      const int32_t x = int32_t(r.uniform(0, 1000)), y = int32_t(r.uniform(0, 1000));
      s.push_back({x, y, int32_t(x + r.uniform(-120, 120)), int32_t(y + r.uniform(-120, 120))});
    }
    auto d = [](double ax, double ay, double bx, double by) {
      return std::hypot(bx - ax, by - ay);
    };
    std::vector<int> perm = {0, 1, 2, 3, 4, 5};
    double best = 1e300;
    do {
      for (int flips = 0; flips < 64; ++flips) {
        double x = 0, y = 0, t = 0;
        for (int k = 0; k < 6; ++k) {
          const Segment2& g = s[size_t(perm[size_t(k)])];
          const bool f = (flips >> k) & 1;
          t += d(x, y, f ? g.x1 : g.x0, f ? g.y1 : g.y0);
          x = f ? g.x0 : g.x1, y = f ? g.y0 : g.y1;
        }
        best = std::min(best, t);
      }
    } while (std::next_permutation(perm.begin(), perm.end()));
    double gx = 0, gy = 0, greedy = 0;
    std::vector<bool> used(6, false);
    for (int k = 0; k < 6; ++k) {
      int bi = -1;
      bool bf = false;
      double bd = 1e300;
      for (int i = 0; i < 6; ++i)
        for (bool f : {false, true}) {
          const Segment2& g = s[size_t(i)];
          const double dd = d(gx, gy, f ? g.x1 : g.x0, f ? g.y1 : g.y0);
          if (!used[size_t(i)] && dd < bd) bd = dd, bi = i, bf = f;
        }
      used[size_t(bi)] = true;
      greedy += bd;
      const Segment2& g = s[size_t(bi)];
      gx = bf ? g.x0 : g.x1, gy = bf ? g.y0 : g.y1;
    }
    PathStats st;
    const double ours = travel(plan(s, &st));
    if (ours > greedy + 3) ++worse_than_greedy;  // a few steps: integer lengths in the planner
    ours_sum += ours, greedy_sum += greedy, best_sum += best;
  }
  std::printf("six spans, 200 trials: planner %.3f x the optimum, greedy alone %.3f x\n",
              ours_sum / best_sum, greedy_sum / best_sum);
  CHECK_EQ(worse_than_greedy, 0);
  CHECK(ours_sum < greedy_sum);
  CHECK(ours_sum < 1.05 * best_sum);
}

// Whole steps of a move, rounded down (an exact integer square root, not the planner's).
static uint64_t floor_length(int64_t dx, int64_t dy) {
  const uint64_t d2 = uint64_t(dx * dx + dy * dy);
  uint64_t r = uint64_t(std::sqrt(double(d2)));
  while (r * r > d2) --r;
  while ((r + 1) * (r + 1) <= d2) ++r;
  return r;
}

// Spans in layers (some empty): each layer's strokes are its spans, nothing of another's, the
// layers one after the other in order, each starting with a pen-up move; the stats add up
// the moves as they are; a wrong count is refused.
static void layered(scenes::Rng& r) {
  std::vector<Segment2> s;
  LayerCounts layers;
  layers.n = kMaxLayers;
  const uint32_t sizes[kMaxLayers] = {40, 0, 25, 60, 7};
  for (uint32_t k = 0; k < kMaxLayers; ++k) {
    layers.count[k] = sizes[k];
    for (uint32_t i = 0; i < sizes[k]; ++i) {  // shared ends within and across layers
      const int32_t x = int32_t(r.uniform(0, 20)) * 100, y = int32_t(r.uniform(0, 20)) * 100;
      s.push_back({x, y, x + 100 * int32_t(r.uniform(-2, 2)), y + 100 * int32_t(r.uniform(-2, 2))});
    }
  }
  const uint32_t n = uint32_t(s.size());
  std::vector<uint64_t> ws(path_plan_bytes(n) / 8 + 1);
  std::vector<PathPoint> out(path_points_max(n));
  uint32_t count = 0;
  LayerCounts written;
  PathStats st;
  // The planner's layers as such: every span as given (dots and overlaps too).
  CHECK(ok(plan_path_layers(s.data(), n, layers, 50, -70, ws.data(), ws.size() * 8, out.data(),
                            uint32_t(out.size()), &count, &written, &st, PathClean{false, 0})));
  CHECK_EQ(written.n, kMaxLayers);
  uint32_t at = 0, first = 0, lifts = 0;
  uint64_t up = 0, naive = 0;
  int32_t x = 50, y = -70;
  for (uint32_t k = 0; k < kMaxLayers; ++k) {
    std::map<Key, int> want, got;
    for (uint32_t i = first; i < first + sizes[k]; ++i)
      ++want[undirected(s[i].x0, s[i].y0, s[i].x1, s[i].y1)];
    CHECK_MSG((written.count[k] == 0) == (sizes[k] == 0), "a layer has points iff it has spans");
    if (written.count[k] > 0) CHECK_MSG(out[at].pen_down == 0, "a layer starts pen up");
    for (uint32_t i = at; i < at + written.count[k]; ++i) {
      if (out[i].pen_down)
        ++got[undirected(x, y, out[i].x, out[i].y)];
      else
        up += floor_length(out[i].x - x, out[i].y - y), lifts += i > 0;
      x = out[i].x, y = out[i].y;
    }
    CHECK_MSG(got == want, "layer " + std::to_string(k) + " draws exactly its spans");
    at += written.count[k];
    first += sizes[k];
  }
  CHECK_EQ(at, count);
  int32_t px = 50, py = -70;
  for (const Segment2& g : s) naive += floor_length(g.x0 - px, g.y0 - py), px = g.x1, py = g.y1;
  CHECK_EQ(st.pen_up_length, up);
  CHECK_EQ(st.pen_lifts, lifts);
  CHECK_EQ(st.naive_pen_up_length, naive);
  layers.count[2] += 1;  // the counts no longer add up to the spans
  CHECK(plan_path_layers(s.data(), n, layers, 0, 0, ws.data(), ws.size() * 8, out.data(),
                         uint32_t(out.size()), &count, nullptr, nullptr) == Status::kBadParameter);
}

// The unit steps a span covers on the integer lattice: (line direction, line offset, position
// of the step's start along the line), the line's direction primitive and pointing right (or
// up). Written here, apart from the clean-up's own keys.
using Cell = std::tuple<int64_t, int64_t, int64_t, int64_t>;
static void add_cells(int32_t x0, int32_t y0, int32_t x1, int32_t y1, std::map<Cell, int>* cells) {
  int64_t dx = int64_t{x1} - x0, dy = int64_t{y1} - y0;
  const int64_t g = std::gcd(std::abs(dx), std::abs(dy));
  if (g == 0) return;
  dx /= g, dy /= g;
  int64_t sx = x0, sy = y0;
  if (dx < 0 || (dx == 0 && dy < 0)) dx = -dx, dy = -dy, sx = x1, sy = y1;
  for (int64_t k = 0; k < g; ++k) {
    const int64_t px = sx + k * dx, py = sy + k * dy;
    ++(*cells)[Cell{dx, dy, dy * px - dx * py, dx * px + dy * py}];
  }
}

// The planned strokes cover exactly the spans' unit steps, each once; no stroke is a dot.
static bool drawn_once(const std::vector<Segment2>& spans, const std::vector<PathPoint>& pts) {
  std::map<Cell, int> want, got;
  for (const Segment2& g : spans) add_cells(g.x0, g.y0, g.x1, g.y1, &want);
  for (auto& c : want) c.second = 1;
  for (size_t i = 1; i < pts.size(); ++i) {
    if (!pts[i].pen_down) continue;
    if (pts[i].x == pts[i - 1].x && pts[i].y == pts[i - 1].y) return false;
    add_cells(pts[i - 1].x, pts[i - 1].y, pts[i].x, pts[i].y, &got);
  }
  return got == want;
}

// Hand-worked clean-up cases: a join after a merge, the minimum stroke, a short workspace, a
// layer cleaned away.
static void clean_cases() {
  {  // (5,0)-(20,0) overlaps (0,0)-(10,0); their union meets (20,0)-(20,10): one stroke.
    const std::vector<Segment2> s = {{0, 0, 10, 0}, {5, 0, 20, 0}, {20, 0, 20, 10}};
    PathStats st;
    const auto pts = plan(s, &st, PathEnd{}, PathClean{});
    CHECK_EQ(st.polylines, 1u);
    CHECK_EQ(pts.size(), size_t{3});
    CHECK_EQ(st.overlaps_merged, 1u);
    CHECK_EQ(st.overlap_length, uint64_t{5});
    CHECK(drawn_once(s, pts));
    plan(s, &st);
    CHECK_EQ(st.polylines, 2u);  // without the merge: (0,0)-(10,0) apart
  }
  {  // Minimum 10: a lone 5 is dropped, two joined 6s (12) and a lone 10 are kept.
    const std::vector<Segment2> s = {
        {0, 0, 5, 0}, {100, 0, 106, 0}, {106, 0, 106, 6}, {200, 0, 210, 0}};
    PathStats st;
    const auto pts = plan(s, &st, PathEnd{}, PathClean{true, 10});
    CHECK_EQ(st.crumbs_dropped, 1u);
    CHECK_EQ(st.crumb_length, uint64_t{5});
    CHECK_EQ(st.polylines, 2u);
    CHECK(drawn_once({s[1], s[2], s[3]}, pts));
  }
  {  // A workspace one word short is a status, not a crash.
    std::vector<Segment2> s = {{0, 0, 10, 0}, {5, 0, 20, 0}};
    std::vector<uint64_t> ws(path_plan_bytes(2) / 8 - 1);
    std::vector<PathPoint> out(path_points_max(2));
    uint32_t n = 0;
    CHECK(plan_path(s.data(), 2, PenAt{0, 0}, ws.data(), ws.size() * 8, out.data(), 4, &n,
                    nullptr) == Status::kWorkspaceTooSmall);
  }
  {  // A layer of dots plans to nothing; the next starts from the start.
    std::vector<Segment2> s = {{3, 3, 3, 3}, {7, 7, 7, 7}, {10, 0, 20, 0}};
    LayerCounts layers;
    layers.n = 2, layers.count[0] = 2, layers.count[1] = 1;
    std::vector<uint64_t> ws(path_plan_bytes(3) / 8 + 1);
    std::vector<PathPoint> out(path_points_max(3));
    uint32_t n = 0;
    LayerCounts per;
    PathStats st;
    CHECK(ok(plan_path_layers(s.data(), 3, layers, 0, 0, ws.data(), ws.size() * 8, out.data(),
                              uint32_t(out.size()), &n, &per, &st)));
    CHECK_EQ(n, 2u);
    CHECK_EQ(per.count[0], 0u);
    CHECK_EQ(per.count[1], 2u);
    CHECK_EQ(st.dots_dropped, 2u);
    CHECK_EQ(st.pen_lifts, 0u);
  }
}

// The clean-up (motion/stroke_clean.h): collinear families of overlapping spans, duplicates
// and dots among random spans are drawn once, exactly their union; with the clean-up off the
// same check fails (it sees the overlaps).
static void cleaned(scenes::Rng& r) {
  static const int32_t kDirs[6][2] = {{1, 0}, {0, 1}, {1, 1}, {2, 1}, {3, -2}, {-1, 4}};
  for (int trial = 0; trial < 20; ++trial) {
    std::vector<Segment2> s;
    uint32_t dots = 0;
    for (int line = 0; line < 12; ++line) {
      const int32_t* d = kDirs[r.uniform(0, 5)];
      const int32_t bx = int32_t(r.uniform(1000, 4000)), by = int32_t(r.uniform(1000, 4000));
      for (int k = 0; k < 5; ++k) {
        const int32_t a = int32_t(r.uniform(-60, 60)), b = a + int32_t(r.uniform(1, 50));
        s.push_back({bx + a * d[0], by + a * d[1], bx + b * d[0], by + b * d[1]});
        if (k % 2) std::swap(s.back().x0, s.back().x1), std::swap(s.back().y0, s.back().y1);
      }
    }
    for (int i = 0; i < 40; ++i) {
      const int32_t x = int32_t(r.uniform(0, 5000)), y = int32_t(r.uniform(0, 5000));
      s.push_back({x, y, int32_t(x + r.uniform(-300, 300)), int32_t(y + r.uniform(-300, 300))});
      if (i % 8 == 0) s.push_back({x, y, x, y}), ++dots;
    }
    s.push_back(s[3]);
    std::shuffle(s.begin(), s.end(), std::mt19937(uint32_t(trial)));
    PathStats st;
    CHECK_MSG(drawn_once(s, plan(s, &st, PathEnd{}, PathClean{})), "clean-up: each step once");
    CHECK_EQ(st.dots_dropped, dots);
    CHECK(st.overlaps_merged > 0 && st.overlap_length > 0);
    CHECK_MSG(!drawn_once(s, plan(s, &st)), "clean-up off: the check must see the overlaps");
  }
}

int main() {
  scenes::Rng r(21);
  against_optimum(r);
  layered(r);
  cleaned(r);
  clean_cases();
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
    PathEnd end;
    end.known = true;
    end.x = 5000, end.y = 2500;
    covers(s, "random families, toward a known end", end);
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
      style.pen = by_z ? PenProfile::kZ : PenProfile::kServo;
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
