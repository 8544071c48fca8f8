// Work in parts (memory/parts.h) for the solid stages (the topology's build and stars, the
// face grid, the incidences, the edges' fill, the QI's emission): whether a build runs parts
// at all, how many, their ranges, and running them.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/memory/parts.h"

namespace haloplot {

// A 64-bit host runs parts; a 32-bit chip has no runner, so its image leaves their code out.
constexpr bool kRunsParts = UINTPTR_MAX > 0xffffffffu;

// The most parts a stage splits into, whatever the runner's count: enough for a host's cores,
// few enough that the parts' bookkeeping (a few counts each) fits a stack. One on a chip: its
// stack keeps no room for theirs.
constexpr uint32_t kMaxBuildParts = kRunsParts ? 16 : 1;

// Parts for `work` items (about one lookup each): fewer where each would get less than
// Parts::min_work, one without a runner.
inline uint32_t build_part_count(const Parts* p, uint64_t work) {
  if (!kRunsParts || p == nullptr) return 1;  // a constant on a chip: no parts code there
  uint32_t n = p->split();
  if (n > kMaxBuildParts) n = kMaxBuildParts;
  const uint64_t worth = p->min_work == 0 ? n : work / p->min_work;
  if (worth < n) n = worth < 1 ? 1 : uint32_t(worth);
  return n;
}

// Part i of k over [0, n): [part_begin(n, k, i), part_begin(n, k, i + 1)).
inline uint32_t part_begin(uint32_t n, uint32_t k, uint32_t i) {
  return uint32_t(uint64_t{n} * i / k);
}

// f(i) for every part i < k, by the runner when p has one (any order, perhaps at once).
template <typename F>
void each_part(const Parts* p, uint32_t k, F& f) {
  if (kMaxBuildParts == 1) {  // a chip: no runner to hand the parts to
    for (uint32_t i = 0; i < k; ++i) f(i);
    return;
  }
  const Parts none;
  run_parts(
      p != nullptr ? *p : none, k, [](void* a, uint32_t i) { (*static_cast<F*>(a))(i); }, &f);
}

}  // namespace haloplot
