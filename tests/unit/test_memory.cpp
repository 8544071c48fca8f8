// The memory contract: every stage says what it needs, refuses less with a status that names
// the problem, never writes outside the buffers it was given, and DRAW reruns from the CUTSET
// alone (CUT's scratch can be destroyed in between).
#include <cstring>

#include "../check.h"
#include "../reference/brute_cut.h"
#include "../support/run_core.h"
#include "../support/scenes.h"
#include "haloplot/cut/cutset.h"
#include "haloplot/motion/planner.h"

// The size queries a firmware sizes static storage with are constant expressions, and count
// what their headers say: the CUTSET's index (4 bytes an edge, plus 4) and 12-byte records; the
// planner's look-ahead ring only with acceleration on.
static_assert(haloplot::cutset_bytes(10, 5) == (10 + 1) * 4 + 5 * 12);
static_assert(haloplot::MotionPlanner::workspace_bytes(haloplot::PlotterEffects{false, true,
                                                                                false}) == 0);
static_assert(haloplot::MotionPlanner::workspace_bytes(haloplot::PlotterEffects{}, 16) ==
              2 * haloplot::MotionPlanner::workspace_bytes(haloplot::PlotterEffects{}, 8));

using namespace haloplot;

static constexpr size_t kGuard = 64;

// A buffer with guard bytes on both sides.
struct Guarded {
  std::vector<uint8_t> bytes;
  size_t size;
  explicit Guarded(size_t n) : bytes(n + 2 * kGuard + 8, 0xAB), size(n) {}
  void* data() {
    return bytes.data() + kGuard + 8 - (reinterpret_cast<uintptr_t>(bytes.data() + kGuard) % 8);
  }
  bool guards_intact() {
    const uint8_t* d = static_cast<uint8_t*>(data());
    for (const uint8_t* p = bytes.data(); p < d; ++p)
      if (*p != 0xAB) return false;
    for (const uint8_t* p = d + size; p < bytes.data() + bytes.size(); ++p)
      if (*p != 0xAB) return false;
    return true;
  }
};

struct Collect {
  std::vector<Span> spans;
  size_t limit = SIZE_MAX;
  static Status emit(void* c, const Span& s) {
    auto* self = static_cast<Collect*>(c);
    if (self->spans.size() >= self->limit) return Status::kSinkFull;
    self->spans.push_back(s);
    return Status::kOk;
  }
};

int main() {
  const auto edges = scenes::paper_random(4000, 30000, 9);
  const uint32_t n = uint32_t(edges.size());
  const size_t v = reference::brute_cut(edges).records.size();
  CutPlan plan;
  CHECK(ok(plan_cut(edges.data(), n, {}, &plan)));
  CHECK(plan.scratch_bytes >= 4 * size_t{n});

  {  // scratch one byte short
    Guarded scratch(plan.scratch_bytes - 1), store(cutset_bytes(n, uint32_t(v)));
    CutSet cs;
    CHECK(run_cut(plan, edges.data(), scratch.data(), scratch.size, store.data(), store.size, &cs,
                  nullptr) == Status::kWorkspaceTooSmall);
  }
  {  // storage without room for the index
    Guarded scratch(plan.scratch_bytes), store(cutset_bytes(n, 0) - 4);
    CutSet cs;
    CHECK(run_cut(plan, edges.data(), scratch.data(), scratch.size, store.data(), store.size, &cs,
                  nullptr) == Status::kCutsetStorageTooSmall);
  }
  {  // one record short: a named error, the needed count, an empty CUTSET, guards intact
    Guarded scratch(plan.scratch_bytes), store(cutset_bytes(n, uint32_t(v - 1)));
    CutSet cs;
    CutStats st;
    CHECK(run_cut(plan, edges.data(), scratch.data(), scratch.size, store.data(), store.size, &cs,
                  &st) == Status::kCrossingCapacity);
    CHECK_EQ(st.crossings, uint64_t(v));
    CHECK_EQ(cs.n_crossings, 0u);
    CHECK(cs.first == nullptr);
    CHECK(scratch.guards_intact() && store.guards_intact());
  }
  Guarded scratch(plan.scratch_bytes), store(cutset_bytes(n, uint32_t(v)));
  CutSet cs;
  CutStats st;
  {  // exactly enough: success, guards intact
    CHECK(ok(run_cut(plan, edges.data(), scratch.data(), scratch.size, store.data(), store.size,
                     &cs, &st)));
    CHECK_EQ(size_t{cs.n_crossings}, v);
    CHECK(scratch.guards_intact() && store.guards_intact());
  }
  // DRAW scratch: exactly one Gap per record of the busiest edge.
  CHECK_EQ(draw_scratch_bytes(cs), size_t{st.max_per_edge} * sizeof(Gap));
  Collect first;
  {
    Guarded ds(draw_scratch_bytes(cs));
    CHECK(ok(draw(cs, DrawParams{200, HaloMode::kPaper}, ds.data(), ds.size,
                  SpanSink{&Collect::emit, &first}, nullptr)));
    CHECK(ds.guards_intact());
    Guarded small(draw_scratch_bytes(cs) - 1);
    Collect none;
    CHECK(draw(cs, DrawParams{200, HaloMode::kPaper}, small.data(), small.size,
               SpanSink{&Collect::emit, &none}, nullptr) == Status::kWorkspaceTooSmall);
    CHECK(none.spans.empty());
  }
  {  // Re-draw: wipe CUT's scratch, draw at another width, then back: same spans as before.
    std::memset(scratch.data(), 0x5A, scratch.size);
    Guarded ds(draw_scratch_bytes(cs));
    Collect other, again;
    CHECK(ok(draw(cs, DrawParams{50, HaloMode::kExact}, ds.data(), ds.size,
                  SpanSink{&Collect::emit, &other}, nullptr)));
    CHECK(ok(draw(cs, DrawParams{200, HaloMode::kPaper}, ds.data(), ds.size,
                  SpanSink{&Collect::emit, &again}, nullptr)));
    CHECK(other.spans.size() != first.spans.size());
    CHECK_EQ(again.spans.size(), first.spans.size());
    bool same = again.spans.size() == first.spans.size();
    // Field by field: a Span has padding after `edge`, whose bytes no one sets (clang's
    // copies leave them differing, so memcmp would compare garbage).
    auto equal = [](const Span& a, const Span& b) {
      return a.edge == b.edge && a.t0 == b.t0 && a.t1 == b.t1 && a.x0 == b.x0 && a.y0 == b.y0 &&
             a.x1 == b.x1 && a.y1 == b.y1;
    };
    for (size_t i = 0; same && i < first.spans.size(); ++i)
      same = equal(again.spans[i], first.spans[i]);
    CHECK_MSG(same, "DRAW after wiping CUT's scratch differs");
  }
  {  // A full sink stops DRAW with its status.
    Guarded ds(draw_scratch_bytes(cs));
    Collect limited;
    limited.limit = 10;
    CHECK(draw(cs, DrawParams{200, HaloMode::kPaper}, ds.data(), ds.size,
               SpanSink{&Collect::emit, &limited}, nullptr) == Status::kSinkFull);
    CHECK_EQ(limited.spans.size(), size_t{10});
  }
  {  // Bad input and parameters are named.
    std::vector<Edge3> bad = edges;
    bad[17].b.y = kCoordLimit;
    CutPlan p;
    CHECK(plan_cut(bad.data(), n, {}, &p) == Status::kCoordinateOutOfRange);
    bad[17].b.y = -1;
    CHECK(plan_cut(bad.data(), n, {}, &p) == Status::kCoordinateOutOfRange);
    CutParams neg;
    neg.reach = -1;
    CHECK(plan_cut(edges.data(), n, neg, &p) == Status::kBadParameter);
    Guarded ds(draw_scratch_bytes(cs));
    Collect none;
    CHECK(draw(cs, DrawParams{-1, HaloMode::kPaper}, ds.data(), ds.size,
               SpanSink{&Collect::emit, &none}, nullptr) == Status::kBadParameter);
    CHECK(std::strcmp(status_name(Status::kCrossingCapacity), "crossing capacity exceeded") == 0);
  }
  {  // An empty scene is fine and draws nothing.
    CutPlan p;
    CHECK(ok(plan_cut(nullptr, 0, {}, &p)));
    Guarded s0(p.scratch_bytes + 8), st0(cutset_bytes(0, 0));
    CutSet c0;
    CHECK(ok(run_cut(p, nullptr, s0.data(), s0.size, st0.data(), st0.size, &c0, nullptr)));
    CHECK_EQ(c0.n_crossings, 0u);
  }
  return check::finish("memory");
}
