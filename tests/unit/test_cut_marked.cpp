// CUT with marked edges (CutParams::marked) finds exactly the crossings of the unmarked run
// whose behind or front edge is marked: the same records, in the same order, for no edge, every
// edge and a random tenth marked, on one thread and in parts on threads. The hidden lines rely
// on it to leave out the crossings that cannot change a QI.
#include <random>
#include <string>
#include <vector>

#include "../check.h"
#include "../support/scenes.h"
#include "haloplot/cut/cut.h"
#include "pipeline/thread_parts.h"

using namespace haloplot;

namespace {

std::vector<Crossing> cut(const std::vector<Edge3>& edges, CutParams params) {
  CutPlan plan;
  CHECK(plan_cut(edges.data(), uint32_t(edges.size()), params, &plan) == Status::kOk);
  std::vector<uint64_t> scratch(plan.scratch_bytes / 8 + 1);
  const uint32_t capacity = 4 * uint32_t(edges.size()) + 64;
  std::vector<uint64_t> storage(cutset_bytes(uint32_t(edges.size()), capacity) / 8 + 1);
  CutSet set;
  CutStats stats;
  const Status s = run_cut(plan, edges.data(), scratch.data(), scratch.size() * 8, storage.data(),
                           storage.size() * 8, &set, &stats);
  CHECK_MSG(s == Status::kOk, std::string("run_cut: ") + status_name(s));
  if (s != Status::kOk) return {};
  return std::vector<Crossing>(set.crossings, set.crossings + set.n_crossings);
}

bool marked(const std::vector<uint32_t>& m, uint32_t e) { return (m[e / 32] >> (e % 32)) & 1u; }

bool same(const Crossing& a, const Crossing& b) {
  return a.behind == b.behind && a.front == b.front && a.t == b.t;
}

void check_marks(const std::string& name, const std::vector<Edge3>& edges,
                 const std::vector<uint32_t>& m, const Parts* parts) {
  CutParams all;
  const std::vector<Crossing> every = cut(edges, all);
  std::vector<Crossing> want;
  for (const Crossing& c : every)
    if (marked(m, c.behind) || marked(m, c.front_edge())) want.push_back(c);
  CutParams p;
  p.marked = m.data();
  p.parts = parts;
  const std::vector<Crossing> got = cut(edges, p);
  bool equal = got.size() == want.size();
  for (size_t i = 0; equal && i < got.size(); ++i) equal = same(got[i], want[i]);
  CHECK_MSG(equal, name + ": " + std::to_string(got.size()) + " crossings, the unmarked run's " +
                       "with a marked edge: " + std::to_string(want.size()));
  CHECK_MSG(!every.empty(), name + ": the scene has crossings");
}

}  // namespace

int main() {
  std::mt19937 rng(48);
  Parts split = *host::thread_parts(3);
  split.min_work = 0;  // split even these small scenes
  for (uint32_t seed = 1; seed <= 3; ++seed) {
    const std::vector<Edge3> edges = scenes::paper_random(4000, 30000, seed);
    const size_t words = (edges.size() + 31) / 32;
    std::vector<uint32_t> none(words, 0), every(words, ~0u), tenth(words, 0);
    for (uint32_t e = 0; e < edges.size(); ++e)
      if (rng() % 10 == 0) tenth[e / 32] |= 1u << (e % 32);
    const std::string s = "seed " + std::to_string(seed);
    check_marks(s + ", none marked", edges, none, nullptr);
    check_marks(s + ", every edge marked", edges, every, nullptr);
    check_marks(s + ", a tenth marked", edges, tenth, nullptr);
    check_marks(s + ", a tenth marked, in parts", edges, tenth, &split);
  }
  return check::finish("cut_marked");
}
