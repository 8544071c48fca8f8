// Freeman-Loutrel (core/view2d) against the brute-force ray caster (tests/reference): the
// visible parts of every edge must agree exactly, as ratios, on thousands of random simple
// polygons of every configuration (star-shaped seen from inside and out, spirals seen from
// their centre, combs, lattice polygons with vertices collinear with E and E collinear with
// edges); the paper's Figure 5 rebuilt with its labels; hand-worked cases for each
// configuration type; and the input errors.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "../check.h"
#include "haloplot/view2d/polygon_view.h"
#include "reference/view2d_reference.h"

using namespace haloplot;

namespace {

struct Run {
  Status status;
  View2dStats stats;
  std::vector<reference::Interval> spans;
};

Run run(const std::vector<Point2>& poly, Point2 eye) {
  Run r;
  std::vector<uint8_t> scratch(view2d_scratch_bytes(uint32_t(poly.size())));
  std::vector<VisibleSpan> raw;
  r.status = view2d(poly.data(), uint32_t(poly.size()), eye, scratch.data(), scratch.size(),
                    VisibleSink{[](void* c, const VisibleSpan& s) {
                                  static_cast<std::vector<VisibleSpan>*>(c)->push_back(s);
                                  return Status::kOk;
                                },
                                &raw},
                    &r.stats);
  // Merge pieces of one edge that touch (the walk may report an edge in two pieces).
  std::sort(raw.begin(), raw.end(), [](const VisibleSpan& a, const VisibleSpan& b) {
    if (a.edge != b.edge) return a.edge < b.edge;
    return (__int128)a.s0.num * b.s0.den < (__int128)b.s0.num * a.s0.den;
  });
  for (const VisibleSpan& s : raw) {
    const reference::Frac f0{s.s0.num, s.s0.den}, f1{s.s1.num, s.s1.den};
    if (!r.spans.empty() && r.spans.back().edge == s.edge &&
        reference::frac_eq(r.spans.back().s1, f0))
      r.spans.back().s1 = f1;
    else
      r.spans.push_back({s.edge, f0, f1});
  }
  return r;
}

std::string describe(const std::vector<Point2>& poly, Point2 eye) {
  std::string s = "E=(" + std::to_string(eye.x) + "," + std::to_string(eye.y) + ") P=";
  for (const Point2& p : poly) s += "(" + std::to_string(p.x) + "," + std::to_string(p.y) + ")";
  return s;
}

// Compare with the brute force; returns false (and records one failure) on disagreement.
bool agrees(const std::vector<Point2>& poly, Point2 eye, const char* family) {
  const Run r = run(poly, eye);
  if (!ok(r.status)) {
    CHECK_MSG(false,
              std::string(family) + ": " + status_name(r.status) + " " + describe(poly, eye));
    return false;
  }
  std::vector<reference::Pt> p;
  for (const Point2& q : poly) p.push_back({q.x, q.y});
  const auto want = reference::visible_brute(p, {eye.x, eye.y});
  bool same = want.size() == r.spans.size();
  for (size_t i = 0; same && i < want.size(); ++i)
    same = want[i].edge == r.spans[i].edge && reference::frac_eq(want[i].s0, r.spans[i].s0) &&
           reference::frac_eq(want[i].s1, r.spans[i].s1);
  if (!same) {
    CHECK_MSG(false, std::string(family) + ": " + std::to_string(want.size()) + " brute spans, " +
                         std::to_string(r.spans.size()) + " walk spans " + describe(poly, eye));
  }
  return same;
}

bool simple(const std::vector<Point2>& poly, Point2 eye) {
  std::vector<uint8_t> scratch(view2d_scratch_bytes(uint32_t(poly.size())));
  const Status s =
      view2d(poly.data(), uint32_t(poly.size()), eye, scratch.data(), scratch.size(),
             VisibleSink{[](void*, const VisibleSpan&) { return Status::kOk; }, nullptr}, nullptr);
  return s != Status::kSelfIntersecting && s != Status::kBadParameter;
}

std::vector<Point2> star(std::mt19937_64& rng, int n, int cx, int cy, int rmin, int rmax) {
  std::vector<double> ang;
  for (int i = 0; i < n; ++i)
    ang.push_back(std::uniform_real_distribution<double>(0, 2 * M_PI)(rng));
  std::sort(ang.begin(), ang.end());
  std::vector<Point2> p;
  for (double a : ang) {
    const double r = std::uniform_int_distribution<int>(rmin, rmax)(rng);
    p.push_back(
        {cx + int32_t(std::lround(r * std::cos(a))), cy + int32_t(std::lround(r * std::sin(a)))});
  }
  return p;
}

std::vector<Point2> spiral(double turns, int per_turn, double gap, double width) {
  std::vector<Point2> out, back;
  const int steps = int(turns * per_turn);
  for (int i = 0; i <= steps; ++i) {
    const double t = 2 * M_PI * i / per_turn, r = 200 + gap * t / (2 * M_PI);
    out.push_back({int32_t(std::lround(r * std::cos(t))), int32_t(std::lround(r * std::sin(t)))});
    back.push_back({int32_t(std::lround((r + width) * std::cos(t))),
                    int32_t(std::lround((r + width) * std::sin(t)))});
  }
  std::reverse(back.begin(), back.end());
  out.insert(out.end(), back.begin(), back.end());
  return out;
}

std::vector<Point2> comb(std::mt19937_64& rng, int teeth) {
  std::vector<Point2> p = {{0, 0}};
  int x = 0;
  for (int t = 0; t < teeth; ++t) {
    const int w = std::uniform_int_distribution<int>(5, 40)(rng),
              g = std::uniform_int_distribution<int>(5, 40)(rng);
    const int h = std::uniform_int_distribution<int>(20, 300)(rng);
    p.push_back({x, 100 + h});
    p.push_back({x + w, 100 + h});
    p.push_back({x + w, 100});
    p.push_back({x + w + g, 100});
    x += w + g;
  }
  p.push_back({x, 0});
  // Remove the collinear run at the start so no edge folds back: p[0] -> first tooth.
  return p;
}

void random_families() {
  std::mt19937_64 rng(2026);
  int cases = 0, failures = 0;
  auto one = [&](const std::vector<Point2>& poly, Point2 eye, const char* family) {
    if (!simple(poly, eye)) return;
    ++cases;
    if (!agrees(poly, eye, family) && ++failures > 20) return;
  };
  for (int k = 0; k < 1500 && failures <= 20; ++k) {
    const auto p = star(rng, 5 + int(rng() % 40), 0, 0, 50, 1000);
    const Point2 e{int32_t(rng() % 3001) - 1500, int32_t(rng() % 3001) - 1500};
    one(p, e, "star");
  }
  for (int k = 0; k < 300 && failures <= 20; ++k) {  // E near the centre: often interior
    const auto p = star(rng, 5 + int(rng() % 60), 0, 0, 300, 1000);
    one(p, Point2{int32_t(rng() % 201) - 100, int32_t(rng() % 201) - 100}, "star, inside");
  }
  for (int k = 0; k < 200 && failures <= 20; ++k) {
    const auto p = spiral(1.2 + double(rng() % 300) / 100.0, 8 + int(rng() % 20),
                          double(300 + rng() % 200), 120);
    one(p, Point2{int32_t(rng() % 101) - 50, int32_t(rng() % 101) - 50}, "spiral");
    one(p, Point2{int32_t(rng() % 8001) - 4000, int32_t(rng() % 8001) - 4000}, "spiral, outside");
  }
  for (int k = 0; k < 300 && failures <= 20; ++k) {
    const auto p = comb(rng, 2 + int(rng() % 12));
    one(p, Point2{int32_t(rng() % 1200) - 100, int32_t(rng() % 1400) - 700}, "comb");
  }
  // Lattice polygons on a small grid, E on lattice points: vertices collinear with E and E
  // collinear with edges all the time.
  for (int k = 0; k < 1500 && failures <= 20; ++k) {
    auto p = star(rng, 4 + int(rng() % 14), 0, 0, 2, 8);
    p.erase(std::unique(p.begin(), p.end(),
                        [](Point2 a, Point2 b) { return a.x == b.x && a.y == b.y; }),
            p.end());
    if (p.size() >= 3 && p.front().x == p.back().x && p.front().y == p.back().y) p.pop_back();
    if (p.size() < 3) continue;
    one(p, Point2{int32_t(rng() % 25) - 12, int32_t(rng() % 25) - 12}, "lattice");
  }
  CHECK(cases > 3000);
  std::printf("view2d: %d random cases against the brute force\n", cases);
}

// The paper's Figure 5, rebuilt: a blocked exterior with A1..A20 in the paper's labelling
// (A1 the most clockwise vertex, E at the origin; built from polar positions, rounded).
// The paper's account: a1 hidden from A1 to B1 and visible from B1 to A2; a2, a3, a4 visible;
// a backward bay at A5 hides a5 and a6, and a7 is visible only from B7 to A8; a forward bay
// marked by A11 hides a9 and a10, and a8 is visible only from A8 to C8; a11 is visible (A11
// to Q, and Q to A12 where the walk began); a12 to a20 are invisible by Proposition 3.
// B1, B7 and C8 lie exactly on the rays E A12, E A5 and E A11.
void figure5() {
  const std::vector<Point2> p = {{1000, 0},     {766, 643},    {174, 985},    {-500, 866},
                                 {-940, 342},   {-1149, 964},  {-1638, 1147}, {-1879, -684},
                                 {-684, -1879}, {-650, -1126}, {-771, -919},  {750, 150},
                                 {640, -113},   {222, -611},   {1026, -2819}, {-2819, -1026},
                                 {-1500, 2598}, {2298, 1928},  {2954, 521},   {1494, 131}};
  const Point2 e{0, 0};
  const Run r = run(p, e);
  CHECK(ok(r.status));
  CHECK(r.stats.config == ViewConfig::kBlockedExterior);
  CHECK_EQ(r.stats.prop3_edges, 9u);    // a12 .. a20
  CHECK_EQ(r.stats.backward_bays, 2u);  // at A5, and at A12 after the start at Q
  CHECK_EQ(r.stats.forward_bays, 1u);   // marked by A11
  auto piece = [&](uint32_t edge) -> const reference::Interval* {
    for (const auto& s : r.spans)
      if (s.edge == edge) return &s;
    return nullptr;
  };
  const reference::Frac zero{0, 1}, one{1, 1};
  // On the ray from E through vertex k: cross(A + s D, V_k) = 0.
  auto on_ray = [&](const reference::Interval* s, bool start, uint32_t k) {
    const Point2 a = p[s->edge], b = p[(s->edge + 1) % p.size()], v = p[k];
    const reference::Frac f = start ? s->s0 : s->s1;
    const __int128 c0 = (__int128)a.x * v.y - (__int128)a.y * v.x;
    const __int128 cd = (__int128)(b.x - a.x) * v.y - (__int128)(b.y - a.y) * v.x;
    return f.num * cd + f.den * c0 == 0;
  };
  const auto* a1 = piece(0);
  CHECK(a1 && !reference::frac_eq(a1->s0, zero) && reference::frac_eq(a1->s1, one) &&
        on_ray(a1, true, 11));
  for (uint32_t k : {1u, 2u, 3u, 10u}) {
    const auto* s = piece(k);
    CHECK_MSG(s && reference::frac_eq(s->s0, zero) && reference::frac_eq(s->s1, one),
              "a" + std::to_string(k + 1) + " visible whole");
  }
  const auto* a7 = piece(6);
  CHECK(a7 && reference::frac_eq(a7->s1, one) && on_ray(a7, true, 4));  // from B7 (ray E A5)
  const auto* a8 = piece(7);
  CHECK(a8 && reference::frac_eq(a8->s0, zero) && on_ray(a8, false, 10));  // to C8 (ray E A11)
  for (uint32_t k : {4u, 5u, 8u, 9u, 11u, 12u, 13u, 14u, 15u, 16u, 17u, 18u, 19u})
    CHECK_MSG(piece(k) == nullptr, "a" + std::to_string(k + 1) + " invisible");
  CHECK(agrees(p, e, "Figure 5"));
}

void hand_cases() {
  // Free exterior: a square seen from the left: only the left edge, whole.
  const std::vector<Point2> square = {{0, 0}, {0, 10}, {10, 10}, {10, 0}};
  Run r = run(square, {-5, 5});
  CHECK(ok(r.status) && r.stats.config == ViewConfig::kFreeExterior);
  CHECK(r.spans.size() == 1 && r.spans[0].edge == 0 && reference::frac_eq(r.spans[0].s0, {0, 1}) &&
        reference::frac_eq(r.spans[0].s1, {1, 1}));
  // Interior: everything of a convex polygon is visible.
  r = run(square, {3, 4});
  CHECK(ok(r.status) && r.stats.config == ViewConfig::kInterior && r.spans.size() == 4);
  // Corner-on: two edges visible.
  r = run(square, {-5, -5});
  CHECK(ok(r.status) && r.spans.size() == 2);
  // E collinear with an edge: that edge is seen edge-on (invisible), the near one is visible.
  r = run(square, {0, -5});
  CHECK(ok(r.status) && r.spans.size() == 1 && r.spans[0].edge == 3);
  // Free exterior though E is in a courtyard: the gap in the wall lets one ray out.
  const std::vector<Point2> c_shape = {{0, 0},   {0, 100}, {100, 100}, {100, 0}, {55, 0},  {55, 10},
                                       {90, 10}, {90, 90}, {10, 90},   {10, 10}, {45, 10}, {45, 0}};
  r = run(c_shape, {50, 50});
  CHECK(ok(r.status) && r.stats.config == ViewConfig::kFreeExterior);
  CHECK(agrees(c_shape, {50, 50}, "C-shape"));
  // Blocked exterior: the centre of a spiral wall of two turns, no ray escapes.
  const auto coil = spiral(2.0, 16, 400, 120);
  r = run(coil, {0, 0});
  CHECK(ok(r.status) && r.stats.config == ViewConfig::kBlockedExterior);
  CHECK(agrees(coil, {0, 0}, "spiral, centre"));
  // A backward bay and a forward bay (Figure 4): an inlet in the near shore.
  const std::vector<Point2> bays = {{0, 0},   {0, 40},  {30, 40},  {30, 20},
                                    {60, 20}, {60, 40}, {100, 40}, {100, 0}};
  r = run(bays, {45, 200});
  CHECK(ok(r.status));
  CHECK(agrees(bays, {45, 200}, "bays"));
  CHECK(agrees(bays, {10, 200}, "bays, from the left"));
  CHECK(r.stats.prop3_edges > 0);
}

void errors() {
  std::vector<uint8_t> scratch(view2d_scratch_bytes(8));
  const VisibleSink none{[](void*, const VisibleSpan&) { return Status::kOk; }, nullptr};
  const std::vector<Point2> bow = {{0, 0}, {10, 10}, {10, 0}, {0, 10}};  // self-intersecting
  uint32_t bad[2] = {9, 9};
  CHECK(view2d(bow.data(), 4, {-5, 5}, scratch.data(), scratch.size(), none, nullptr, bad) ==
        Status::kSelfIntersecting);
  CHECK(bad[0] != 9);
  const std::vector<Point2> two = {{0, 0}, {10, 10}};
  CHECK(view2d(two.data(), 2, {-5, 5}, scratch.data(), scratch.size(), none, nullptr) ==
        Status::kBadParameter);
  const std::vector<Point2> square = {{0, 0}, {0, 10}, {10, 10}, {10, 0}};
  CHECK(view2d(square.data(), 4, {0, 5}, scratch.data(), scratch.size(), none, nullptr) ==
        Status::kBadParameter);  // E on the polygon
  CHECK(view2d(square.data(), 4, {10, 10}, scratch.data(), scratch.size(), none, nullptr) ==
        Status::kBadParameter);  // E on a vertex
  const std::vector<Point2> far = {{0, 0}, {0, kView2dLimit + 1}, {10, 0}};
  CHECK(view2d(far.data(), 3, {-5, 5}, scratch.data(), scratch.size(), none, nullptr) ==
        Status::kCoordinateOutOfRange);
  const std::vector<Point2> fold = {{0, 0}, {10, 0}, {5, 0}, {5, 5}};  // folds back on itself
  CHECK(view2d(fold.data(), 4, {-5, 5}, scratch.data(), scratch.size(), none, nullptr) ==
        Status::kSelfIntersecting);
  CHECK(view2d(square.data(), 4, {-5, 5}, scratch.data(), 3, none, nullptr) ==
        Status::kWorkspaceTooSmall);
}

}  // namespace

int main() {
  figure5();
  hand_cases();
  errors();
  random_families();
  return check::finish("view2d");
}
