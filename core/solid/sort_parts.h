// Work in parts (memory/parts.h) for the topology's build: ranges of an array, and a sort that
// sorts ranges at once and then merges them, each part writing its own range of the result.
// The sorted array does not depend on the number of parts when the order has no ties between
// values that differ (the topology's keys: a key and an index, or keys alone, where equal keys
// are equal values), so a build in parts keeps exactly what a build in one part keeps.
#pragma once
#include <stddef.h>
#include <stdint.h>

#include "haloplot/memory/parts.h"
#include "haloplot/sort/lower_bound.h"
#include "sort/in_place_sort.h"

namespace haloplot {

// The most parts the build splits into, whatever the runner's count: enough for a host's
// cores, few enough that the merge's bookkeeping (kMaxBuildParts squared cuts) fits a stack.
constexpr uint32_t kMaxBuildParts = 16;

// Parts for `work` items (about one lookup each): fewer where each would get less than
// Parts::min_work, one without a runner.
inline uint32_t build_part_count(const Parts* p, uint64_t work) {
  if (p == nullptr) return 1;
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
  const Parts none;
  run_parts(
      p != nullptr ? *p : none, k, [](void* a, uint32_t i) { (*static_cast<F*>(a))(i); }, &f);
}

// Sorts from[0, n) into to[0, n) (from is left in slices sorted): k parts each sort a slice,
// then k parts each merge one range of values from every slice. A range's bounds are values
// from the slices (non-decreasing from range to range), each slice cut at its first element not
// below them, so every range's elements are those of the values between two bounds, wherever
// they were. Equal elements from different slices are taken slice by slice.
template <typename T, typename Less>
void sort_in_parts(const Parts* p, uint32_t k, T* from, T* to, uint32_t n, Less less) {
  if (k > kMaxBuildParts) k = kMaxBuildParts;
  auto sort_slice = [&](uint32_t i) {
    const uint32_t b = part_begin(n, k, i);
    sort_total(from + b, part_begin(n, k, i + 1) - b, less);
  };
  each_part(p, k, sort_slice);
  // cut[r][j]: where range j begins in slice r; cut[r][k] the slice's end.
  uint32_t cut[kMaxBuildParts][kMaxBuildParts + 1];
  for (uint32_t j = 0; j <= k; ++j) {
    const T* bound = nullptr;  // the greatest of the slices' j/k quantiles
    for (uint32_t r = 0; r < k && j > 0 && j < k; ++r) {
      const uint32_t b = part_begin(n, k, r), len = part_begin(n, k, r + 1) - b;
      if (len == 0) continue;
      const T* q = from + b + uint32_t(uint64_t{len} * j / k);
      if (bound == nullptr || less(*bound, *q)) bound = q;
    }
    for (uint32_t r = 0; r < k; ++r) {
      const uint32_t b = part_begin(n, k, r), e = part_begin(n, k, r + 1);
      if (j == 0)
        cut[r][j] = b;
      else if (j == k || bound == nullptr)
        cut[r][j] = e;
      else
        cut[r][j] = lower_bound_index(b, e, [&](uint32_t i) { return less(from[i], *bound); });
    }
  }
  auto merge_range = [&](uint32_t j) {
    uint32_t at = 0, head[kMaxBuildParts];
    for (uint32_t r = 0; r < k; ++r) {
      at += cut[r][j] - cut[r][0];
      head[r] = cut[r][j];
    }
    for (;;) {
      uint32_t best = k;
      for (uint32_t r = 0; r < k; ++r)
        if (head[r] < cut[r][j + 1] && (best == k || less(from[head[r]], from[head[best]])))
          best = r;
      if (best == k) return;
      to[at++] = from[head[best]++];
    }
  };
  each_part(p, k, merge_range);
}

}  // namespace haloplot
