// DRAW on cases worked by hand. The behind edge is always edge 0, horizontal at y = 1000,
// running from x = 1000; every expected span below is computed in the comment beside it.
#include <cmath>

#include "../support/plot.h"
#include "../support/scenes.h"

using namespace haloplot;
using scenes::edge;
using support::plot;
using support::spans_of;

int main() {
  const HaloMode paper = HaloMode::kPaper, exact = HaloMode::kExact;
  {  // Right angle: vertical front edge at x = 1500, W = 100: gap [1400, 1600] in both modes.
    const std::vector<Edge3> e = {edge(1000, 1000, 0, 2000, 1000, 0),
                                  edge(1500, 500, 9, 1500, 1500, 9)};
    CHECK_EQ(spans_of(plot(e, 100, paper), 0),
             std::string("1000,1000-1400,1000;1600,1000-2000,1000;"));
    CHECK_EQ(spans_of(plot(e, 100, exact), 0),
             std::string("1000,1000-1400,1000;1600,1000-2000,1000;"));
    CHECK_EQ(spans_of(plot(e, 100, paper), 1), std::string("1500,500-1500,1500;"));  // front: whole
  }
  {  // sin(theta) = 3/5 (direction 800, 600), W = 60: half-gap W / sin = 100 around x = 2000.
    const std::vector<Edge3> e = {edge(1000, 1000, 0, 3000, 1000, 0),
                                  edge(1600, 700, 9, 2400, 1300, 9)};
    CHECK_EQ(spans_of(plot(e, 60, paper), 0),
             std::string("1000,1000-1900,1000;2100,1000-3000,1000;"));
  }
  {  // About 30 degrees: direction (1732, 1000); half-gap W / sin(theta), W = 50: about 100.
    const std::vector<Edge3> e = {edge(1000, 1000, 0, 5000, 1000, 0),
                                  edge(3000 - 1732, 0, 9, 3000 + 1732, 2000, 9)};
    const double half = 50.0 / std::sin(std::atan2(1000.0, 1732.0));  // 100.0004
    const auto p = plot(e, 50, paper);
    CHECK_EQ(p.spans.size(), size_t{3});  // two pieces of edge 0, edge 1 whole
    CHECK(std::abs(p.spans[0].x1 - (3000 - half)) <= 0.5 + 1e-3);
    CHECK(std::abs(p.spans[1].x0 - (3000 + half)) <= 0.5 + 1e-3);
  }
  {  // Near-parallel: front from (5000, 999) to (7000, 1001) crosses at x = 6000 with
     // sin(theta) = 2 / sqrt(2000^2 + 4), so the paper's half-gap is about 1000 * W: W = 10
     // hides the whole behind edge. The exact halo stops W past the front edge's ends:
     // x in [5000 - sqrt(10^2 - 1^2), 7000 + sqrt(99)] = [4990.05, 7009.95].
    const std::vector<Edge3> e = {edge(1000, 1000, 0, 11000, 1000, 0),
                                  edge(5000, 999, 9, 7000, 1001, 9)};
    const auto pp = plot(e, 10, paper);
    CHECK_EQ(spans_of(pp, 0), std::string(""));
    CHECK_EQ(pp.stats.hidden_edges, uint64_t{1});
    CHECK_EQ(spans_of(plot(e, 10, exact), 0),
             std::string("1000,1000-4990,1000;7010,1000-11000,1000;"));
  }
  {  // Overlapping halos: fronts at x = 1500 and 1550, W = 50: gaps [1450, 1550] and
     // [1500, 1600] merge into one [1450, 1600].
    const std::vector<Edge3> e = {edge(1000, 1000, 0, 2000, 1000, 0),
                                  edge(1500, 500, 9, 1500, 1500, 9),
                                  edge(1550, 500, 9, 1550, 1500, 9)};
    CHECK_EQ(spans_of(plot(e, 50, paper), 0),
             std::string("1000,1000-1450,1000;1600,1000-2000,1000;"));
  }
  {  // A halo running off the end: front at x = 1980, W = 50: gap [1930, 2030] clipped to 2000.
    const std::vector<Edge3> e = {edge(1000, 1000, 0, 2000, 1000, 0),
                                  edge(1980, 500, 9, 1980, 1500, 9)};
    CHECK_EQ(spans_of(plot(e, 50, paper), 0), std::string("1000,1000-1930,1000;"));
  }
  {  // The behind edge is cut even when it is the second edge and runs right to left.
    const std::vector<Edge3> e = {edge(1500, 500, 9, 1500, 1500, 9),
                                  edge(2000, 1000, 0, 1000, 1000, 0)};
    CHECK_EQ(spans_of(plot(e, 100, paper), 1),
             std::string("2000,1000-1600,1000;1400,1000-1000,1000;"));
  }
  {  // Figure 5's near miss: the front edge stops 5 steps short of the behind one. Exact halo
     // W = 20 (reach 20): gap x in 1500 +/- sqrt(20^2 - 5^2) = [1480.64, 1519.36].
    const std::vector<Edge3> e = {edge(1000, 1000, 0, 2000, 1000, 0),
                                  edge(1500, 1005, 9, 1500, 1500, 9)};
    CHECK_EQ(spans_of(plot(e, 20, exact, 20), 0),
             std::string("1000,1000-1481,1000;1519,1000-2000,1000;"));
    CHECK_EQ(spans_of(plot(e, 20, paper, 20), 0),
             std::string("1000,1000-2000,1000;"));   // paper: no cut
    const auto short_reach = plot(e, 20, exact, 0);  // CUT did not look for near misses
    CHECK_EQ(spans_of(short_reach, 0), std::string("1000,1000-2000,1000;"));
    CHECK(short_reach.stats.reach_short);
    // 21 steps apart: just out of reach of a 20-step halo.
    const std::vector<Edge3> far = {edge(1000, 1000, 0, 2000, 1000, 0),
                                    edge(1500, 1021, 9, 1500, 1500, 9)};
    CHECK_EQ(spans_of(plot(far, 20, exact, 20), 0), std::string("1000,1000-2000,1000;"));
  }
  {  // Heger's occluded edge: a nearer edge lies along the middle of a farther one (a collinear
     // overlap at different depths). No proper crossing, so the paper's DRAW cannot see it;
     // the exact halo (reach >= W) hides the covered length and W beyond each end:
     // x in [1300 - 5, 1700 + 5].
    const std::vector<Edge3> e = {edge(1000, 1000, 0, 2000, 1000, 0),
                                  edge(1300, 1000, 9, 1700, 1000, 9)};
    CHECK_EQ(spans_of(plot(e, 5, exact, 5), 0),
             std::string("1000,1000-1295,1000;1705,1000-2000,1000;"));
    CHECK_EQ(spans_of(plot(e, 5, exact, 5), 1),
             std::string("1300,1000-1700,1000;"));  // front: whole
    CHECK_EQ(spans_of(plot(e, 5, paper, 5), 0), std::string("1000,1000-2000,1000;"));
    // The same overlap at equal depth is one edge drawn twice, not an occlusion: no cut.
    const std::vector<Edge3> same = {edge(1000, 1000, 4, 2000, 1000, 4),
                                     edge(1300, 1000, 4, 1700, 1000, 4)};
    CHECK_EQ(spans_of(plot(same, 5, exact, 5), 0), std::string("1000,1000-2000,1000;"));
  }
  {  // W = 0 draws every edge whole, crossings or not.
    const std::vector<Edge3> e = {edge(1000, 1000, 0, 2000, 1000, 0),
                                  edge(1500, 500, 9, 1500, 1500, 9)};
    const auto p = plot(e, 0, paper);
    CHECK_EQ(p.spans.size(), size_t{2});
    CHECK_EQ(spans_of(p, 0), std::string("1000,1000-2000,1000;"));
  }
  {  // Equal depth at the crossing: the edges meet in space, so no gap at any W.
    const std::vector<Edge3> e = {edge(1000, 1000, 5, 2000, 1000, 5),
                                  edge(1500, 500, 0, 1500, 1500, 10)};
    CHECK_EQ(spans_of(plot(e, 100, paper), 0), std::string("1000,1000-2000,1000;"));
  }
  return check::finish("draw_cases");
}
