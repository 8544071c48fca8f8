// CUT against the brute-force reference on hand-built hard families, plus exact expectations
// worked out by hand where the family has an obvious answer.
#include <string>

#include "../check.h"
#include "../support/run_core.h"
#include "../support/scenes.h"

using namespace haloplot;
using scenes::edge;

static host::HostCut run(const std::vector<Edge3>& edges, CutParams params = {}) {
  host::HostCut c;
  const Status s = host::host_cut(edges, params, &c);
  CHECK_MSG(ok(s), std::string("CUT status ") + status_name(s));
  return c;
}

// Agreement with the reference under several grids, including cells aligned to the family.
static size_t agree(const std::vector<Edge3>& edges, const std::string& label,
                    int32_t aligned_cell = 0) {
  const reference::Result ref = reference::brute_cut(edges);
  std::vector<CutParams> variants(3);
  variants[1].cover = CellCover::kBoundingBox;
  variants[2].grid.lambda_q8 = 64;
  if (aligned_cell > 0) {
    variants.push_back({});
    variants.back().grid.cell = aligned_cell;
    variants.back().grid.max_cells = 1u << 24;
  }
  for (size_t v = 0; v < variants.size(); ++v) {
    const host::HostCut c = run(edges, variants[v]);
    CHECK_MSG(support::cutset_well_formed(c.set), label + ": malformed CUTSET");
    CHECK_MSG(support::records_of(c.set) == ref.records,
              label + " variant " + std::to_string(v) + ": records differ from the reference (" +
                  std::to_string(c.set.n_crossings) + " vs " + std::to_string(ref.records.size()) +
                  ")");
    CHECK_MSG(c.stats.equal_depth == ref.equal_depth, label + ": equal-depth count");
  }
  return ref.records.size();
}

int main(int argc, char** argv) {
  // With a family name, run only that family (each is its own CTest); without, run all.
  const std::string only = argc > 1 ? argv[1] : "";
  int matched = 0;
  auto want = [&](const char* name) {
    const bool yes = only.empty() || only == name;
    matched += yes;
    return yes;
  };
  scenes::Rng rng(7);
  const int32_t M = kCoordMax;

  if (want("cell_corners")) {  // Axis-parallel lattice: every crossing on a grid corner when cells
                               // are 1000 steps.
    std::vector<Edge3> e;
    for (int i = 1; i <= 20; ++i) {
      e.push_back(edge(0, i * 1000, int32_t(rng.uniform(0, M)), 21000, i * 1000,
                       int32_t(rng.uniform(0, M))));
      e.push_back(edge(i * 1000, 0, int32_t(rng.uniform(0, M)), i * 1000, 21000,
                       int32_t(rng.uniform(0, M))));
    }
    const size_t v = agree(e, "lattice on cell corners", 1000);
    CHECK_EQ(v, size_t{400});  // 20 x 20, minus ties in depth (probability ~0 with 20-bit z)
  }
  if (want("one_point")) {  // Many edges through one point: K edges c +/- d_i, all meeting at c.
    std::vector<Edge3> e;
    const int32_t c = 500000;
    for (int i = 0; i < 40; ++i) {
      const int32_t dx = int32_t(rng.uniform(1, 30000)), dy = int32_t(rng.uniform(-30000, 30000));
      e.push_back(edge(c - dx, c - dy, i * 1000, c + dx, c + dy, i * 1000 + 500));
    }
    const size_t v = agree(e, "star through one point", 1000);
    // Directions may repeat only by chance; count distinct-direction pairs by hand.
    size_t expected = 0;
    for (size_t i = 0; i < e.size(); ++i)
      for (size_t j = i + 1; j < e.size(); ++j) {
        const int64_t ax = e[i].b.x - e[i].a.x, ay = e[i].b.y - e[i].a.y;
        const int64_t bx = e[j].b.x - e[j].a.x, by = e[j].b.y - e[j].a.y;
        if (ax * by - ay * bx != 0) ++expected;
      }
    CHECK_EQ(v, expected);
  }
  if (want("shared_endpoints")) {  // Shared endpoints: a fan from one vertex, and a closed polygon:
                                   // no crossings at all.
    std::vector<Edge3> e;
    for (int i = 0; i < 30; ++i)
      e.push_back(
          edge(1000, 1000, 5, int32_t(rng.uniform(0, 50000)), int32_t(rng.uniform(0, 50000)), 99));
    const int32_t px[] = {100, 900, 900, 100}, py[] = {100, 100, 900, 900};
    for (int i = 0; i < 4; ++i)
      e.push_back(edge(px[i], py[i], 7, px[(i + 1) % 4], py[(i + 1) % 4], 9));
    agree(e, "shared endpoints");
    std::vector<Edge3> fan(e.begin(), e.begin() + 30);
    CHECK_EQ(run(fan).set.n_crossings, 0u);
  }
  if (want("t_junctions")) {  // T-junctions: stems ending exactly on a bar's interior, from both
                              // sides.
    std::vector<Edge3> e = {edge(0, 5000, 10, 100000, 5000, 10)};
    for (int i = 1; i < 50; ++i) {
      e.push_back(edge(i * 2000, 5000, 500, i * 2000 + 37, 9000, 600));
      e.push_back(edge(i * 2000 + 11, 1000, 700, i * 2000 + 11, 5000, 800));
    }
    CHECK_EQ(agree(e, "T-junctions", 2000), size_t{0});
  }
  if (want("collinear_duplicates")) {  // Collinear overlaps and duplicates: never crossings among
                                       // themselves.
    std::vector<Edge3> e = {edge(0, 0, 1, 10000, 10000, 2), edge(5000, 5000, 3, 20000, 20000, 4),
                            edge(0, 0, 1, 10000, 10000, 2), edge(2000, 2000, 9, 3000, 3000, 9),
                            edge(0, 10000, 50, 10000, 0, 60)};
    const size_t v = agree(e, "collinear overlaps and duplicates");
    // The cross-diagonal meets the diagonal line at (5000, 5000): inside edge 0 and its
    // duplicate, an endpoint of edge 1 (a touch), and beyond edge 3 (2000..3000).
    CHECK_EQ(v, size_t{2});
  }
  if (want("near_parallel")) {  // Near-parallel long edges: full-range edges offset by one step,
                                // crossing at tiny angles.
    std::vector<Edge3> e;
    for (int i = 0; i < 30; ++i) {
      e.push_back(edge(0, 500000 + i, int32_t(rng.uniform(0, M)), M, 500000 + 30 - i,
                       int32_t(rng.uniform(0, M))));
      e.push_back(edge(0, i, 100, M, M - i, 200 + i));
    }
    agree(e, "near-parallel long edges", 4096);
  }
  if (want("range_ends")) {  // Coordinates at 0 and 2^20 - 1: the border and both diagonals of the
                             // whole range.
    std::vector<Edge3> e = {edge(0, 0, 0, M, M, M),
                            edge(0, M, M, M, 0, 0),
                            edge(0, 0, M, M, 0, 0),
                            edge(0, M, 0, M, M, M),
                            edge(0, 0, 0, 0, M, M),
                            edge(M, 0, M, M, M, 0),
                            edge(0, M / 2, 0, M, M / 2 + 1, 5),
                            edge(M / 2, 0, M, M / 2 + 1, M, M - 3)};
    agree(e, "range ends", 1);
    // By hand: the borders only touch the diagonals at their ends; the six proper crossings
    // are 0-1, 6-0, 6-1, 6-7, 7-0, 7-1. 0 and 1 meet at the centre at equal depth M/2.
    const reference::Result ref = reference::brute_cut(e);
    CHECK_EQ(ref.records.size() + ref.equal_depth, size_t{6});
    CHECK_EQ(run(e).stats.equal_depth, uint64_t{1});
    CHECK_EQ(run(e).set.n_crossings, 5u);
  }
  if (want("zero_length")) {  // Zero-length edges (seen end-on) never cross, even lying on another
                              // edge.
    std::vector<Edge3> e = {edge(0, 0, 0, 1000, 1000, 0), edge(500, 500, 9, 500, 500, 99),
                            edge(300, 700, 5, 300, 700, 5), edge(0, 1000, 4, 1000, 0, 4)};
    CHECK_EQ(agree(e, "zero-length edges"), size_t{1});
  }
  if (want("equal_depth")) {  // Equal depth at the crossing: the edges meet in space and neither is
                              // cut.
    std::vector<Edge3> e = {edge(0, 0, 100, 1000, 1000, 300), edge(0, 1000, 200, 1000, 0, 200),
                            edge(0, 500, 0, 1000, 500, 400)};  // all three have z=200 at (500,500)
    const host::HostCut c = run(e);
    CHECK_EQ(c.set.n_crossings, 0u);
    CHECK_EQ(c.stats.equal_depth, uint64_t{3});
    agree(e, "equal depth");
  }
  if (want("cell_borders")) {  // Crossings exactly on cell borders (cells 1024 steps): diagonals
                               // through border points.
    std::vector<Edge3> e;
    for (int i = 0; i < 30; ++i) {
      const int32_t bx = 1024 * int32_t(rng.uniform(1, 20)),
                    by = 1024 * int32_t(rng.uniform(1, 20));
      const int32_t d = int32_t(rng.uniform(1, 900));
      e.push_back(edge(bx - d, by - d, 10 * i, bx + d, by + d, 10 * i + 5));
      e.push_back(edge(bx - d, by + d, 10 * i + 3, bx + d, by - d, 10 * i + 1));
      e.push_back(edge(bx, by - d, 7, bx, by + d + 3, 900));
    }
    agree(e, "crossings on cell borders", 1024);
  }
  CHECK_MSG(matched > 0, "no family named '" + only + "'");  // a typo must not pass vacuously
  return check::finish(only.empty() ? "cut_families" : ("stability_" + only).c_str());
}
