// The one sized-stage protocol (core/include/haloplot/memory/sized_stage.h): run_sized() raises
// exactly the needs a short run reports and nothing else, stops when a report raises nothing (so a
// stage that under-reports cannot spin), never runs a fixed arena below a known floor, and the
// core's stages report what really fits: CUT's records equal a brute-force count, a buffer one byte
// short of the reported bytes fails and the reported bytes succeed.
#include <algorithm>
#include <vector>

#include "../check.h"
#include "../reference/brute_cut.h"
#include "haloplot/cut/cut.h"
#include "haloplot/job/job.h"
#include "haloplot/memory/sized_stage.h"
#include "haloplot/scene/random_edges.h"
#include "pipeline/host_memory.h"

using namespace haloplot;

namespace {

// A stage with hidden true needs: each run reports only the first need it falls short of
// (as the core's stages do: CUT stops before Franklin's incidences are known).
struct FakeStage {
  StageNeeds truth;
  bool honest = true;  // false: reports a shortfall but asks for nothing more
  int runs = 0;
  size_t last_buffer = 0;
  size_t bytes(const StageNeeds& k) const { return 100 + size_t{k.crossings} * 8; }
  Status run(const StageNeeds& k, void*, size_t bytes, StageNeeds* want) {
    ++runs;
    last_buffer = bytes;
    if (k.crossings < truth.crossings) {
      if (honest) want->crossings = truth.crossings;
      return Status::kCrossingCapacity;
    }
    if (k.incidences < truth.incidences) {
      if (honest) want->incidences = truth.incidences;
      return Status::kIncidenceCapacity;
    }
    if (bytes < truth.bytes) {
      if (honest) want->bytes = truth.bytes;
      return Status::kWorkspaceTooSmall;
    }
    return Status::kOk;
  }
};

void protocol_on_a_fake_stage() {
  FakeStage f;
  f.truth.crossings = 37;
  f.truth.incidences = 5;
  f.truth.bytes = 5000;
  host::HostMemory memory;
  StageNeeds needs;
  int rounds = 0;
  CHECK(run_sized(f, memory.memory(), &needs, &rounds) == Status::kOk);
  // One round per need the first guess was short of, and the needs end at the truth.
  CHECK_EQ(rounds, 4);
  CHECK_EQ(f.runs, 4);
  CHECK_EQ(needs.crossings, 37u);
  CHECK_EQ(needs.incidences, 5u);
  CHECK_EQ(needs.bytes, size_t{5000});
  CHECK(f.last_buffer >= 5000);

  // A first guess that is already enough: one run.
  FakeStage g = f;
  g.runs = 0;
  StageNeeds enough = needs;
  CHECK(run_sized(g, memory.memory(), &enough, &rounds) == Status::kOk);
  CHECK_EQ(rounds, 1);

  // A stage that reports a shortfall and asks for nothing: one run, its status returned.
  FakeStage liar = f;
  liar.runs = 0;
  liar.honest = false;
  StageNeeds none;
  CHECK(run_sized(liar, memory.memory(), &none, &rounds) == Status::kCrossingCapacity);
  CHECK_EQ(liar.runs, 1);

  // A fixed arena below the bytes a run reported: the run that found the floor is the last.
  std::vector<uint64_t> small(4000 / 8);
  FixedMemory fixed{small.data(), small.size() * 8};
  FakeStage h = f;
  h.runs = 0;
  StageNeeds from_zero;
  CHECK(run_sized(h, fixed.memory(), &from_zero, &rounds) == Status::kWorkspaceTooSmall);
  CHECK_EQ(h.runs, 3);  // crossings, incidences, then the bytes it found short
  CHECK_EQ(from_zero.bytes, size_t{5000});

  // A shortfall that keeps growing is cut off at kSizedRounds.
  struct Greedy {
    int runs = 0;
    size_t bytes(const StageNeeds&) const { return 8; }
    Status run(const StageNeeds& k, void*, size_t, StageNeeds* want) {
      ++runs;
      want->crossings = k.crossings + 1;
      return Status::kCrossingCapacity;
    }
  } greedy;
  StageNeeds g0;
  CHECK(run_sized(greedy, memory.memory(), &g0, &rounds) == Status::kCrossingCapacity);
  CHECK_EQ(greedy.runs, kSizedRounds);
}

void cut_reports_what_fits() {
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    std::vector<Edge3> edges(400);
    random_edges(uint32_t(edges.size()), 60000, seed, edges.data());
    const size_t truth = reference::brute_cut(edges).records.size();
    CutPlan plan;
    CHECK(ok(plan_cut(edges.data(), uint32_t(edges.size()), CutParams{}, &plan)));
    CutSet set;
    CutStats stats;
    CutStage stage{&plan, edges.data(), &set, &stats};
    host::HostMemory memory;
    StageNeeds needs;
    needs.crossings = 1;  // far short: the second run is sized by the first one's count
    int rounds = 0;
    CHECK(run_sized(stage, memory.memory(), &needs, &rounds) == Status::kOk);
    CHECK_EQ(rounds, truth > 1 ? 2 : 1);
    CHECK_EQ(size_t{needs.crossings}, truth);
    CHECK_EQ(size_t{set.n_crossings}, truth);

    // The query's bytes for those needs fit exactly: one byte less is refused, by name.
    const size_t exact = stage.bytes(needs);
    std::vector<uint64_t> buffer(exact / 8 + 1);
    StageNeeds want = needs;
    CHECK(stage.run(needs, buffer.data(), exact - 1, &want) == Status::kWorkspaceTooSmall);
    CHECK_EQ(want.bytes, exact);
    CHECK(ok(stage.run(needs, buffer.data(), exact, &want)));
    CHECK_EQ(size_t{set.n_crossings}, truth);
  }
}

// The controller's job stage in a fixed arena from a short first guess: the same points as
// from a first guess that is already right, and one more CUT run.
void job_stage_in_a_fixed_arena() {
  std::vector<Edge3> edges(300);
  random_edges(uint32_t(edges.size()), 80000, 7, edges.data());
  JobSpec spec;
  std::vector<uint64_t> arena(1 << 15);
  std::vector<PathPoint> first;
  uint32_t guess = 1;
  for (int pass = 0; pass < 2; ++pass) {
    PreparedJob job;
    JobCounters counters;
    EdgeJobStage stage{&spec, Edges{edges.data(), uint32_t(edges.size())}, &job, &counters,
                       nullptr};
    FixedMemory fixed{arena.data(), arena.size() * 8};
    StageNeeds needs;
    needs.crossings = guess;
    CHECK(run_sized(stage, fixed.memory(), &needs) == Status::kOk);
    CHECK_EQ(stage.cut_runs, pass == 0 ? 2u : 1u);
    guess = needs.crossings;  // the second pass starts from the count the first one found
    std::vector<PathPoint> points(job.points, job.points + job.n_points);
    if (first.empty()) {
      first = points;
      continue;
    }
    CHECK_EQ(points.size(), first.size());
    CHECK(std::equal(points.begin(), points.end(), first.begin(),
                     [](const PathPoint& a, const PathPoint& b) {
                       return a.x == b.x && a.y == b.y && a.pen_down == b.pen_down;
                     }));
  }
}

}  // namespace

int main() {
  protocol_on_a_fake_stage();
  cut_reports_what_fits();
  job_stage_in_a_fixed_arena();
  return check::finish("sized_stage");
}
