// The one sized-stage protocol. A stage whose memory depends on counts only a run can find
// (CUT's records, Franklin's incidences, the visible segments, the hatching's crossing list)
// is asked with capacities; a run that ends short stores nothing (never a partial answer) and
// says in the same StageNeeds what would fit. run_sized() is the only loop in the project that
// asks again: the host, the simulator and the controller differ only in where the bytes come
// from (StageMemory: a buffer that grows, or a fixed arena).
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/status/status.h"

namespace haloplot {

// What a stage asks for. The capacities bound the records a run may store; `bytes` is a floor
// on the buffer for needs that the capacities do not say (a workspace known only mid-run).
struct StageNeeds {
  uint32_t crossings = 0;   // CUT records: crossings and near misses
  uint32_t incidences = 0;  // vertex-on-edge incidences
  uint32_t segments = 0;    // visible segments
  size_t bytes = 0;         // a floor on the buffer
};

// A count a run reports (64-bit) as a capacity to ask for: past 32 bits it stays at the
// largest, which then raises nothing, and run_sized() returns the shortfall.
inline uint32_t need_count(uint64_t n) { return n > 0xffffffffu ? 0xffffffffu : uint32_t(n); }

// A run that ended for want of room: it stored nothing and its report says what fits.
inline bool is_shortfall(Status s) {
  return s == Status::kCrossingCapacity || s == Status::kIncidenceCapacity ||
         s == Status::kSegmentCapacity || s == Status::kWorkspaceTooSmall;
}

// Raises each of *have to at least `want`'s; true when one of them grew.
inline bool raise_needs(StageNeeds* have, const StageNeeds& want) {
  bool grew = false;
  auto raise = [&grew](auto* h, auto w) {
    if (w > *h) {
      *h = w;
      grew = true;
    }
  };
  raise(&have->crossings, want.crossings);
  raise(&have->incidences, want.incidences);
  raise(&have->segments, want.segments);
  raise(&have->bytes, want.bytes);
  return grew;
}

// A buffer for a run. A fixed arena hands out all it has, even when that is less than asked
// (the stage's own check then reports the shortfall with the bytes it needs); a growing one
// hands out at least the bytes asked, or nothing when it cannot.
struct StageBuffer {
  void* data = nullptr;
  size_t bytes = 0;
};
struct StageMemory {
  StageBuffer (*get)(void* context, size_t bytes);
  void* context;
  bool fixed;  // hands out the same buffer whatever is asked: run_sized() skips the stage's query
};

// The controller's memory: one fixed buffer.
struct FixedMemory {
  void* data;
  size_t bytes;
  static StageBuffer get(void* context, size_t) {
    auto* self = static_cast<FixedMemory*>(context);
    return StageBuffer{self->data, self->bytes};
  }
  StageMemory memory() { return StageMemory{&FixedMemory::get, this, true}; }
};

// Rounds a sized run may take: the first guess, then one raise per need a run can report
// (records, incidences, segments, bytes) and one spare. A run whose report raises nothing ends
// the loop at once, so this bound is a backstop, not the usual exit.
constexpr int kSizedRounds = 6;

// Runs `stage` until it fits. Stage has
//   size_t bytes(const StageNeeds&);   the buffer these needs take (0 when the query failed:
//                                      run() then reports why; not asked of fixed memory)
//   Status run(const StageNeeds&, void* buffer, size_t bytes, StageNeeds* want);
//                                      on a shortfall, *want (entered equal to the needs)
//                                      says what a run needs
// *needs enters as the first guess and leaves as the last needs asked (what a caller records
// to size the same scene again); *rounds says how many runs it took.
template <typename Stage>
Status run_sized(Stage& stage, StageMemory memory, StageNeeds* needs, int* rounds = nullptr) {
  for (int round = 1;; ++round) {
    if (rounds != nullptr) *rounds = round;
    size_t bytes = memory.fixed ? 0 : stage.bytes(*needs);
    if (bytes < needs->bytes) bytes = needs->bytes;
    const StageBuffer buffer = memory.get(memory.context, bytes);
    // No buffer, or a fixed one below what an earlier run reported: no run can fit.
    if (buffer.data == nullptr || buffer.bytes < needs->bytes) {
      if (needs->bytes < bytes) needs->bytes = bytes;
      return Status::kWorkspaceTooSmall;
    }
    StageNeeds want = *needs;
    const Status s = stage.run(*needs, buffer.data, buffer.bytes, &want);
    if (!is_shortfall(s) || round == kSizedRounds || !raise_needs(needs, want)) return s;
  }
}

// A stage whose sink keeps what it is given: `reset` runs before each run, so the output of a
// short run is dropped and the run that fits gives everything again.
template <typename Stage, typename Reset>
struct Restarting {
  Stage* stage;
  Reset reset;
  size_t bytes(const StageNeeds& needs) const { return stage->bytes(needs); }
  Status run(const StageNeeds& needs, void* buffer, size_t bytes, StageNeeds* want) {
    reset();
    return stage->run(needs, buffer, bytes, want);
  }
};
template <typename Stage, typename Reset>
Restarting<Stage, Reset> restarting(Stage* stage, Reset reset) {
  return Restarting<Stage, Reset>{stage, reset};
}

}  // namespace haloplot
