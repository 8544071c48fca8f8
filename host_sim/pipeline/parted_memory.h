// CUT's StageMemory on the host's threads: like HostMemory (host_memory.h), a buffer that grows
// to what a sized run asks for, zero each time; but with a runner of several parts, a buffer
// that calloc would clear on one thread (from the heap, ZeroedAllocator's middle sizes) is
// cleared in parts (memory/parts.h), each thread a slice, instead of one thread clearing all
// of it while the others wait. Otherwise (one part, or fresh pages): HostMemory's allocation.
#pragma once
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <utility>

#include "haloplot/memory/parts.h"
#include "pipeline/host_memory.h"

namespace haloplot::host {

// Words that are zero when handed out: from ZeroedAllocator, or malloc cleared in parts.
class PartedWords {
 public:
  PartedWords() = default;
  PartedWords(size_t words, const Parts* parts) : size_(words) {
    const uint32_t n = parts == nullptr ? 1 : parts->split();
    // Fresh pages (ZeroedAllocator::fresh) are zero already, and fault in where a part first
    // writes them: clearing them would touch pages a run never uses.
    if (n == 1 || ZeroedAllocator<uint64_t>::fresh(words * sizeof(uint64_t))) {
      data_ = ZeroedAllocator<uint64_t>().allocate(words);
      return;
    }
    data_ = static_cast<uint64_t*>(std::malloc(words * sizeof(uint64_t)));
    if (data_ == nullptr) throw std::bad_alloc();
    parted_ = true;
    Clear clear{data_, words, n};
    run_parts(*parts, n, &Clear::slice, &clear);
  }
  PartedWords(PartedWords&& o) noexcept { swap(o); }
  PartedWords& operator=(PartedWords&& o) noexcept {
    PartedWords gone(std::move(*this));
    swap(o);
    return *this;
  }
  PartedWords(const PartedWords&) = delete;
  PartedWords& operator=(const PartedWords&) = delete;
  ~PartedWords() {
    if (data_ == nullptr) return;
    if (parted_)
      std::free(data_);
    else
      ZeroedAllocator<uint64_t>().deallocate(data_, size_);
  }
  uint64_t* data() const { return data_; }
  size_t size() const { return size_; }

 private:
  struct Clear {
    uint64_t* data;
    size_t words;
    uint32_t n;
    static void slice(void* arg, uint32_t j) {
      const Clear* c = static_cast<const Clear*>(arg);
      const size_t lo = c->words * j / c->n, hi = c->words * (j + 1) / c->n;
      std::memset(c->data + lo, 0, (hi - lo) * sizeof(uint64_t));
    }
  };
  void swap(PartedWords& o) noexcept {
    std::swap(data_, o.data_);
    std::swap(size_, o.size_);
    std::swap(parted_, o.parted_);
  }
  uint64_t* data_ = nullptr;
  size_t size_ = 0;
  bool parted_ = false;
};

struct PartedMemory {
  const Parts* parts = nullptr;
  PartedWords words;
  static StageBuffer get(void* context, size_t bytes) {
    auto* self = static_cast<PartedMemory*>(context);
    self->words = PartedWords();  // the last run's buffer back first
    self->words = PartedWords(bytes / 8 + 1, self->parts);
    return StageBuffer{self->words.data(), self->words.size() * 8};
  }
  StageMemory memory() { return StageMemory{&PartedMemory::get, this, false}; }
};

}  // namespace haloplot::host
