// The host's StageMemory (core/include/haloplot/memory/sized_stage.h): a buffer that grows to what
// a sized run asks for, zeroed each time so no run sees the last one's bytes.
#pragma once
#include <cstdint>
#include <cstdlib>
#include <new>
#include <utility>
#include <vector>

#include "haloplot/memory/sized_stage.h"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace haloplot::host {

// Returns the heap's free pages to the system when there are many of them (a large model's,
// more than 32 MB: glibc's malloc_trim; nothing elsewhere).
void give_back_freed_memory();

// Allocates with calloc and value-initialises nothing: a vector of words from it starts zero
// without a pass that writes them. A large buffer comes straight from the system's fresh
// pages, which are zero already; clearing it again cost a whole pass over the 100 MB a big
// model's hidden lines ask for, and a page fault for every page a run never touches. So does
// a small one (16 to 512 KB, a small model's stage, mostly first-guess slack): calloc from
// the heap clears all of it, faulting in pages the run never uses (a 24-triangle plot's
// stage took half as long again). Between the two, calloc's heap is the cheaper: it reuses
// the pages reading the model touched and freed (give_back_freed_memory() keeps them).
template <typename T>
struct ZeroedAllocator {
  using value_type = T;
  ZeroedAllocator() = default;
  template <typename U>
  ZeroedAllocator(const ZeroedAllocator<U>&) {}
  T* allocate(size_t n) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (fresh(n * sizeof(T))) {
      void* p =
          mmap(nullptr, n * sizeof(T), PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if (p == MAP_FAILED) throw std::bad_alloc();
      if (n * sizeof(T) >= kLarge) madvise(p, n * sizeof(T), MADV_HUGEPAGE);
      return static_cast<T*>(p);
    }
#endif
    void* p = std::calloc(n, sizeof(T));
    if (p == nullptr) throw std::bad_alloc();
    return static_cast<T*>(p);
  }
  void deallocate(T* p, size_t n) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (fresh(n * sizeof(T))) {
      munmap(p, n * sizeof(T));
      return;
    }
#endif
    (void)n;
    std::free(p);
  }
  static constexpr size_t kLarge = size_t{8} << 20;
  static constexpr size_t kSmall = size_t{16} << 10, kReused = size_t{512} << 10;
  static bool fresh(size_t bytes) {
    return bytes >= kLarge || (bytes >= kSmall && bytes < kReused);
  }
  // Value-initialisation of a word is its zero bytes, which calloc gave.
  template <typename U>
  void construct(U*) {}
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <typename U>
  bool operator==(const ZeroedAllocator<U>&) const {
    return true;
  }
  template <typename U>
  bool operator!=(const ZeroedAllocator<U>&) const {
    return false;
  }
};

using ZeroedWords = std::vector<uint64_t, ZeroedAllocator<uint64_t>>;

struct HostMemory {
  ZeroedWords words;
  static StageBuffer get(void* context, size_t bytes) {
    auto* self = static_cast<HostMemory*>(context);
    self->words = ZeroedWords();  // the last run's buffer back first
    self->words = ZeroedWords(bytes / 8 + 1);
    return StageBuffer{self->words.data(), self->words.size() * 8};
  }
  StageMemory memory() { return StageMemory{&HostMemory::get, this, false}; }
};

}  // namespace haloplot::host
