// Work a stage splits into parts that read shared input and write disjoint memory, so a caller
// with threads (the host tool) may run them at once. The core itself never starts a thread or
// takes a lock: it only says how to split and hands the parts to the caller's runner. Without
// a runner a stage makes one part and runs it in place, as it always did; with one, the
// stage's result does not depend on how many parts there were or in which order they ran.
#pragma once
#include <stddef.h>
#include <stdint.h>

namespace haloplot {

using PartFn = void (*)(void* arg, uint32_t part);

struct Parts {
  // Calls work(arg, i) for every i < n, in any order and possibly at the same time, and
  // returns once every call has returned. Null: no runner.
  void (*run)(void* context, uint32_t n, PartFn work, void* arg) = nullptr;
  void* context = nullptr;
  uint32_t count = 1;  // how many parts a stage should split into (the caller's threads)
  // The least work a part is worth (the stage's own measure, about a pair test): a small run (a
  // band's CUT, run again and again as the conductor tries band heights) is over before a
  // thread has started, so it takes fewer parts. Tests set 0 to split even the smallest.
  uint64_t min_work = uint64_t{1} << 16;

  // The parts to split into: one without a runner.
  uint32_t split() const { return run == nullptr || count < 1 ? 1 : count; }
};

// A stage's parts with a buffer they keep their results in until the caller takes them in
// order (8-byte aligned). Null runner or buffer: one part, in place.
struct PartsBuffer {
  const Parts* parts = nullptr;
  void* buffer = nullptr;
  size_t bytes = 0;
};

// work(arg, i) for i < n: by the runner when there is one and more than one part, otherwise in
// order on the calling thread.
inline void run_parts(const Parts& p, uint32_t n, PartFn work, void* arg) {
  if (p.run != nullptr && n > 1) {
    p.run(p.context, n, work, arg);
    return;
  }
  for (uint32_t i = 0; i < n; ++i) work(arg, i);
}

}  // namespace haloplot
