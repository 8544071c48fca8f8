// The core's in-place sorts against std::sort: every array shape a quicksort can trip on
// (sorted, reversed, all equal, organ pipes, few distinct values, random), each sorted by
// sort_total, by heap_sort and by sort_in_place, and sort_total's heapsort fallback forced.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "../check.h"
#include "sort/in_place_sort.h"

using namespace haloplot;

namespace {

// Values with a payload that takes no part in the order: a sort that loses or duplicates
// one, or orders by less than the key, is seen.
struct Item {
  uint32_t key, index;
};
bool key_then_index(const Item& a, const Item& b) {
  return a.key != b.key ? a.key < b.key : a.index < b.index;
}

uint64_t next_random(uint64_t* s) {
  *s = *s * 6364136223846793005ull + 1442695040888963407ull;
  return *s >> 33;
}

std::vector<std::vector<uint32_t>> shapes(size_t n, uint64_t seed) {
  std::vector<std::vector<uint32_t>> out(7, std::vector<uint32_t>(n));
  for (size_t i = 0; i < n; ++i) {
    out[0][i] = uint32_t(i);                             // sorted
    out[1][i] = uint32_t(n - i);                         // reversed
    out[2][i] = 7;                                       // all equal
    out[3][i] = uint32_t(i < n / 2 ? i : n - i);         // organ pipes
    out[4][i] = uint32_t(next_random(&seed) % 3);        // few distinct values
    out[5][i] = uint32_t(next_random(&seed));            // random
    out[6][i] = uint32_t(i % 2 == 0 ? i : n + (n - i));  // interleaved runs
  }
  return out;
}

bool same(const std::vector<Item>& a, const std::vector<Item>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].key != b[i].key || a[i].index != b[i].index) return false;
  return true;
}

void sorts_agree_with_std_sort() {
  for (size_t n : {0, 1, 2, 3, 24, 25, 100, 1000, 20000})
    for (const std::vector<uint32_t>& keys : shapes(n, n + 1)) {
      std::vector<Item> items(n);
      for (size_t i = 0; i < n; ++i) items[i] = Item{keys[i], uint32_t(i)};
      std::vector<Item> want = items;
      std::sort(want.begin(), want.end(), key_then_index);
      std::vector<Item> total = items, heap = items, in_place = items, shallow = items;
      sort_total(total.data(), total.size(), key_then_index);
      heap_sort(heap.data(), heap.size(), key_then_index);
      sort_in_place(in_place.data(), in_place.size(), key_then_index);
      // Depth 1: one partition, then heapsort on each part.
      sort_detail::intro_sort(shallow.data(), shallow.size(), 1, key_then_index);
      CHECK(same(total, want));
      CHECK(same(heap, want));
      CHECK(same(in_place, want));
      CHECK(same(shallow, want));
      // Plain values with ties (equal values are the same bits: any sort gives one array).
      std::vector<uint32_t> plain = keys, plain_want = keys;
      std::sort(plain_want.begin(), plain_want.end());
      sort_total(plain.data(), plain.size(), [](uint32_t a, uint32_t b) { return a < b; });
      CHECK(plain == plain_want);
    }
}

}  // namespace

int main() {
  sorts_agree_with_std_sort();
  return check::finish("sort");
}
