// CUT against the brute-force reference on scenes from the HALO paper's random distribution,
// up to 50,000 edges, with both cell covers and several grid sizes.
#include <cstdio>
#include <string>

#include "../check.h"
#include "../support/run_core.h"
#include "../support/scenes.h"

using namespace haloplot;

static void compare(const std::vector<Edge3>& edges, const CutParams& params,
                    const std::string& label) {
  const reference::Result ref = reference::brute_cut(edges);
  host::HostCut got;
  const Status s = host::host_cut(edges, params, &got);
  CHECK_MSG(ok(s), label + ": CUT status " + status_name(s));
  if (!ok(s)) return;
  CHECK_MSG(support::cutset_well_formed(got.set), label + ": CUTSET malformed");
  const auto records = support::records_of(got.set);
  CHECK_MSG(records == ref.records, label + ": " + std::to_string(records.size()) + " records vs " +
                                        std::to_string(ref.records.size()) + " in the reference");
  CHECK_MSG(got.stats.crossings == ref.records.size(), label + ": crossing count");
  CHECK_MSG(got.stats.equal_depth == ref.equal_depth, label + ": equal-depth count");
  std::printf("%-40s N=%-6zu V=%-6zu grid=%ux%u cell_pairs=%u pairs=%llu rejected=%llu\n",
              label.c_str(), edges.size(), ref.records.size(), got.plan.grid.nx, got.plan.grid.ny,
              got.stats.cell_pairs, (unsigned long long)got.stats.pairs_tested,
              (unsigned long long)got.stats.rejected);
}

int main() {
  struct Row {
    uint32_t n;
    int64_t l_millionths;
  };
  // Rows of the paper's EDGE table (L in millionths of the screen).
  const Row rows[] = {{100, 100000},  {300, 100000}, {1000, 10000}, {1000, 30000},
                      {1000, 100000}, {3000, 10000}, {3000, 30000}, {10000, 3000},
                      {10000, 10000}, {30000, 3000}, {50000, 1000}, {50000, 10000}};
  uint64_t seed = 1;
  for (const Row& r : rows) {
    const auto edges = scenes::paper_random(r.n, r.l_millionths, seed++);
    CutParams p;
    compare(edges, p,
            "paper N=" + std::to_string(r.n) + " L=" + std::to_string(r.l_millionths) + "e-6");
  }
  // Other covers and grid sizes on one mid-size scene: the answer must not depend on them.
  const auto edges = scenes::paper_random(3000, 30000, 99);
  for (uint32_t lambda_q8 : {32u, 128u, 256u, 1024u}) {
    CutParams p;
    p.grid.lambda_q8 = lambda_q8;
    compare(edges, p, "lambda_q8=" + std::to_string(lambda_q8));
    p.cover = CellCover::kBoundingBox;
    compare(edges, p, "bbox lambda_q8=" + std::to_string(lambda_q8));
  }
  CutParams one_cell;
  one_cell.grid.cell = kCoordLimit;  // the whole scene in one cell: plain all-pairs
  compare(edges, one_cell, "single cell");
  CutParams tiny;
  tiny.grid.cell = 7;  // cells far smaller than edges: every crossing near many borders
  tiny.grid.max_cells = 1u << 26;
  compare(scenes::paper_random(400, 20000, 5), tiny, "cell=7 steps");
  return check::finish("cut_random");
}
