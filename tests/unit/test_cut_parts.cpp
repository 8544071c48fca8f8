// CUT split into parts (memory/parts.h) gives the CUTSET one part gives, byte for byte: for
// any number of parts, run in any order or on threads, with near misses, with rows, with the
// bounding-box cover, and with a record capacity so tight that parts outgrow their slices
// (they run again into what the others left) or that the whole does not fit (the count a
// retry needs, as one part says it); and with edges so uneven that the first parts' cell
// visits outgrow their share of the fill's logs; and with more records than the scratch has room
// for to group them in parts. The plan made in parts is the one-part plan.
// The parts cover each split stage: the plan, the fill (each part's entries dropped from its
// log, or by a walk again), the pairs and the sorting.
#include <cstring>
#include <vector>

#include "../check.h"
#include "../support/scenes.h"
#include "haloplot/cut/cut.h"
#include "pipeline/thread_parts.h"

using namespace haloplot;

namespace {

struct Result {
  Status status = Status::kOk;
  std::vector<uint32_t> first;
  std::vector<Crossing> records;
  CutStats stats;
};

// A runner that runs the parts one after another, last first: the join must not depend on
// the order the parts finish in.
void backwards(void*, uint32_t n, PartFn work, void* arg) {
  for (uint32_t i = n; i-- > 0;) work(arg, i);
}

Result cut(const std::vector<Edge3>& edges, CutParams params, uint32_t capacity) {
  CutPlan plan;
  CHECK(plan_cut(edges.data(), uint32_t(edges.size()), params, &plan) == Status::kOk);
  std::vector<uint64_t> scratch(plan.scratch_bytes / 8 + 1);
  std::vector<uint64_t> storage(cutset_bytes(uint32_t(edges.size()), capacity) / 8 + 1);
  CutSet set;
  Result r;
  r.status = run_cut(plan, edges.data(), scratch.data(), scratch.size() * 8, storage.data(),
                     storage.size() * 8, &set, &r.stats);
  if (r.status == Status::kOk) {
    r.first.assign(set.first, set.first + set.n_edges + 1);
    r.records.assign(set.crossings, set.crossings + set.n_crossings);
  }
  return r;
}

bool same(const Result& a, const Result& b) {
  const CutStats &x = a.stats, &y = b.stats;
  return a.status == b.status && a.first == b.first && a.records.size() == b.records.size() &&
         std::memcmp(a.records.data(), b.records.data(), a.records.size() * sizeof(Crossing)) ==
             0 &&
         x.cell_pairs == y.cell_pairs && x.pairs_tested == y.pairs_tested &&
         x.crossings == y.crossings && x.near_misses == y.near_misses && x.rejected == y.rejected &&
         x.equal_depth == y.equal_depth && x.outside_rows == y.outside_rows &&
         x.max_per_edge == y.max_per_edge;
}

// The plan made in parts (a host's range check, extent, sampled lengths and bound) has the grid
// and bound one part's has (its scratch differs: the fill's own parts need their cursors), and an
// edge out of range in any part is refused as one part refuses it.
void check_plan(const char* name, std::vector<Edge3> edges, CutParams params) {
  CutPlan one;
  CHECK(plan_cut(edges.data(), uint32_t(edges.size()), params, &one) == Status::kOk);
  for (uint32_t n : {2u, 3u, 16u}) {
    Parts parts;
    parts.run = &backwards;
    parts.count = n;
    parts.min_work = 0;
    CutParams p = params;
    p.parts = &parts;
    CutPlan split;
    const std::string what = std::string(name) + ", plan in " + std::to_string(n) + " parts";
    CHECK_MSG(plan_cut(edges.data(), uint32_t(edges.size()), p, &split) == Status::kOk, what);
    const Grid &a = one.grid, &b = split.grid;
    CHECK_MSG(a.ox == b.ox && a.oy == b.oy && a.cell == b.cell && a.nx == b.nx && a.ny == b.ny &&
                  one.cell_pairs == split.cell_pairs,
              what);
    if (edges.empty()) continue;
    std::vector<Edge3> bad = edges;
    bad.back().b.y = -1;
    CHECK_MSG(
        plan_cut(bad.data(), uint32_t(bad.size()), p, &split) == Status::kCoordinateOutOfRange,
        what + ", an edge out of range");
  }
}

void check_scene(const char* name, const std::vector<Edge3>& edges, CutParams params) {
  check_plan(name, edges, params);
  const Result one = cut(edges, params, 4 * uint32_t(edges.size()) + 64);
  CHECK_MSG(one.status == Status::kOk && !one.records.empty(), std::string(name) + ": no cut");
  const uint32_t exact = uint32_t(one.records.size());
  for (uint32_t n : {2u, 3u, 7u, 16u, 100u}) {
    Parts parts;
    parts.run = &backwards;
    parts.count = n;
    parts.min_work = 0;  // split these small scenes too
    CutParams p = params;
    p.parts = &parts;
    const std::string what = std::string(name) + ", " + std::to_string(n) + " parts";
    CHECK_MSG(same(cut(edges, p, 4 * uint32_t(edges.size()) + 64), one), what);
    CHECK_MSG(same(cut(edges, p, exact), one), what + ", exact capacity");
    const Result short_one = cut(edges, params, exact - 1);
    const Result short_parts = cut(edges, p, exact - 1);
    CHECK_MSG(short_parts.status == Status::kCrossingCapacity &&
                  short_parts.stats.crossings + short_parts.stats.near_misses ==
                      short_one.stats.crossings + short_one.stats.near_misses,
              what + ", one record short");
  }
  for (uint32_t threads : {2u, 3u}) {
    CutParams p = params;
    Parts on_threads = *host::thread_parts(threads);
    on_threads.min_work = 0;
    p.parts = &on_threads;
    const std::string what = std::string(name) + ", " + std::to_string(threads) + " threads";
    CHECK_MSG(same(cut(edges, p, exact), one), what);
  }
}

}  // namespace

int main() {
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    const std::vector<Edge3> edges = scenes::paper_random(4000, 30000, seed);
    CutParams p;
    check_scene("random", edges, p);
    p.reach = 200;  // near misses too
    check_scene("random, near misses", edges, p);
    p = CutParams{};
    p.cover = CellCover::kBoundingBox;
    check_scene("random, bounding-box cover", edges, p);
    p = CutParams{};
    p.rows = true;  // a band's rows
    p.row_lo = 200000;
    p.row_hi = 600000;
    check_scene("random, rows", edges, p);
  }
  // Long edges first, short ones after: the first parts visit far more cells than their
  // share of the fill's logs, so they walk again (the lists, and so the CUTSET, the same).
  std::vector<Edge3> uneven = scenes::paper_random(600, 150000, 11);
  for (const Edge3& e : scenes::paper_random(3400, 5000, 12)) uneven.push_back(e);
  check_scene("uneven lengths", uneven, CutParams{});
  // A lattice of long lines, each crossing every line of the other direction: far more
  // records than cell entries, so the scratch has no room to group the parts' records in parts
  // and they are joined first (and grouped as one part groups them).
  std::vector<Edge3> lattice;
  for (int32_t i = 0; i < 150; ++i) {
    const int32_t at = 20000 + i * 6000 + (i % 7) * 311;
    lattice.push_back(scenes::edge(10000, at, 5000 + i, 990000, at + 17 * i, 9000 - i));
    lattice.push_back(scenes::edge(at, 10000, 7000 + i, at + 13 * i, 990000, 3000 + 2 * i));
  }
  const Result lattice_one = cut(lattice, CutParams{}, 200000);
  CHECK(lattice_one.status == Status::kOk && lattice_one.records.size() == 150 * 150);
  for (uint32_t n : {2u, 3u, 7u}) {
    Parts parts;
    parts.run = &backwards;
    parts.count = n;
    parts.min_work = 0;
    CutParams p;
    p.parts = &parts;
    CHECK_MSG(same(cut(lattice, p, 200000), lattice_one),
              "lattice, " + std::to_string(n) + " parts");
  }
  // More edges than average_length samples, so the parts' samples start mid-stride; and
  // fewer edges than parts.
  for (uint32_t n : {0u, 1u, 2u, 5u, 17u, 20003u})
    check_plan("a few edges", scenes::paper_random(n, 30000, 13), CutParams{});
  return check::finish("cut_parts");
}
