// Symmetries CUT and DRAW must respect: relabelling edges, mirroring or swapping axes,
// translating, and reversing an edge's direction leave the crossings unchanged.
#include <algorithm>
#include <set>

#include "../support/plot.h"
#include "../support/run_core.h"
#include "../support/scenes.h"

using namespace haloplot;
using Pairs = std::set<std::pair<uint32_t, uint32_t>>;

static std::vector<reference::Record> cut(const std::vector<Edge3>& e) {
  host::HostCut c;
  CHECK(ok(host::host_cut(e, {}, &c)));
  return support::records_of(c.set);
}

static Pairs pairs(const std::vector<reference::Record>& r) {
  Pairs p;
  for (const auto& x : r) p.insert({x.behind, x.front});
  return p;
}

int main() {
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    const auto edges = scenes::paper_random(2500, 40000, seed);
    const auto base = cut(edges);
    CHECK(base.size() > 100);
    scenes::Rng r(seed * 77);
    {  // relabel: edge i becomes edge perm[i]
      std::vector<uint32_t> perm(edges.size());
      for (uint32_t i = 0; i < perm.size(); ++i) perm[i] = i;
      for (size_t i = perm.size(); i > 1; --i) std::swap(perm[i - 1], perm[r.next() % i]);
      std::vector<Edge3> moved(edges.size());
      for (uint32_t i = 0; i < edges.size(); ++i) moved[perm[i]] = edges[i];
      std::vector<reference::Record> want;
      for (const auto& x : base) want.push_back({perm[x.behind], perm[x.front], x.t});
      std::sort(want.begin(), want.end());
      CHECK_MSG(cut(moved) == want, "relabelling changed the crossings");
    }
    {  // mirror x, swap x and y, translate: t along each edge is an affine invariant
      std::vector<Edge3> mx = edges, sw = edges, tr = edges;
      for (auto& e : mx) e.a.x = kCoordMax - e.a.x, e.b.x = kCoordMax - e.b.x;
      for (auto& e : sw) std::swap(e.a.x, e.a.y), std::swap(e.b.x, e.b.y);
      int32_t minx = kCoordMax;
      for (const auto& e : edges) minx = std::min({minx, e.a.x, e.b.x});
      for (auto& e : tr) e.a.x -= minx, e.b.x -= minx;
      CHECK_MSG(cut(mx) == base, "mirroring x changed the crossings");
      CHECK_MSG(cut(sw) == base, "swapping x and y changed the crossings");
      CHECK_MSG(cut(tr) == base, "translating changed the crossings");
    }
    {  // reverse every other edge: same (behind, front) pairs
      std::vector<Edge3> rev = edges;
      for (size_t i = 0; i < rev.size(); i += 2) std::swap(rev[i].a, rev[i].b);
      CHECK_MSG(pairs(cut(rev)) == pairs(base), "reversing edges changed the crossing pairs");
    }
    {  // DRAW commutes with mirroring, up to the half-step rounding of each end
      std::vector<Edge3> mx = edges;
      for (auto& e : mx) e.a.x = kCoordMax - e.a.x, e.b.x = kCoordMax - e.b.x;
      const auto a = support::plot(edges, 300, HaloMode::kPaper),
                 b = support::plot(mx, 300, HaloMode::kPaper);
      CHECK_EQ(a.spans.size(), b.spans.size());
      bool close = a.spans.size() == b.spans.size();
      for (size_t i = 0; close && i < a.spans.size(); ++i)
        close = a.spans[i].edge == b.spans[i].edge &&
                std::abs(kCoordMax - a.spans[i].x0 - b.spans[i].x0) <= 1 &&
                std::abs(kCoordMax - a.spans[i].x1 - b.spans[i].x1) <= 1 &&
                a.spans[i].y0 == b.spans[i].y0 && a.spans[i].y1 == b.spans[i].y1;
      CHECK_MSG(close, "DRAW of the mirrored scene is not the mirrored drawing");
    }
  }
  return check::finish("cut_properties");
}
