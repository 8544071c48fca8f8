// A set of unordered vertex pairs (edges) for the model readers and the mesh cleaning: open
// addressing in one array, no node per pair (a std::unordered_set allocated one for each of a
// large model's hundreds of thousands of edges).
#pragma once
#include <algorithm>
#include <cstdint>
#include <vector>

namespace haloplot::host {

// The pair {a, b} as one key, the smaller index first.
inline uint64_t pair_key(uint32_t a, uint32_t b) {
  return uint64_t(std::min(a, b)) << 32 | std::max(a, b);
}

// A key's slot in an open-addressed table of 2^k slots.
inline size_t pair_hash(uint64_t key) {
  key ^= key >> 29;
  key *= 0xbf58476d1ce4e5b9ull;
  return size_t(key ^ (key >> 32));
}

class PairSet {
 public:
  // True when the key was not in the set (it is now).
  bool insert(uint64_t key) {
    if (key == kEmpty) {  // the mark of an empty slot, kept aside (a == b == 0xffffffff)
      const bool added = !has_all_ones_;
      has_all_ones_ = true;
      return added;
    }
    if (4 * (count_ + 1) > 3 * slots_.size()) grow();  // at most 3/4 full
    const size_t mask = slots_.size() - 1;
    for (size_t i = pair_hash(key) & mask;; i = (i + 1) & mask) {
      if (slots_[i] == key) return false;
      if (slots_[i] == kEmpty) {
        slots_[i] = key;
        ++count_;
        return true;
      }
    }
  }

 private:
  static constexpr uint64_t kEmpty = ~uint64_t{0};
  void grow() {
    std::vector<uint64_t> old;
    old.swap(slots_);
    slots_.assign(old.empty() ? 64 : 2 * old.size(), kEmpty);
    count_ = 0;
    for (uint64_t k : old)
      if (k != kEmpty) insert(k);
  }
  std::vector<uint64_t> slots_;
  size_t count_ = 0;
  bool has_all_ones_ = false;
};

}  // namespace haloplot::host
