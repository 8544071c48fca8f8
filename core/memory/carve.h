// Carving typed arrays out of one caller buffer, and counting the bytes that carving will
// take, with the same rounding, so a stage's *_bytes() query and its run can never disagree.
// Every array starts on an 8-byte boundary (enough for every type the core stores).
#pragma once
#include <stddef.h>
#include <stdint.h>

namespace haloplot {

inline size_t carve_round(size_t bytes) { return (bytes + 7) & ~size_t{7}; }

// Counts bytes: call take<T>(n) for each array in the same order the run carves them. take()
// returns nullptr like an exhausted Carver, so one template can do the carving for both.
struct ByteCounter {
  size_t total = 0;
  template <typename T>
  T* take(size_t n) {
    total += carve_round(n * sizeof(T));
    return nullptr;
  }
};

// Hands out arrays from [base, base + size). take() returns nullptr once the buffer is
// exhausted and sets `short_` so the caller reports kWorkspaceTooSmall rather than writing
// past the end.
struct Carver {
  uint8_t* next = nullptr;
  size_t left = 0;
  bool short_ = false;

  Carver(void* base, size_t size) {
    const uintptr_t p = reinterpret_cast<uintptr_t>(base);
    const uintptr_t aligned = (p + 7) & ~uintptr_t{7};
    const size_t lost = static_cast<size_t>(aligned - p);
    next = reinterpret_cast<uint8_t*>(aligned);
    left = size > lost ? size - lost : 0;
    if (base == nullptr) left = 0;
  }
  template <typename T>
  T* take(size_t n) {
    const size_t bytes = carve_round(n * sizeof(T));
    if (bytes > left || short_) {
      short_ = true;
      return nullptr;
    }
    T* out = reinterpret_cast<T*>(next);
    next += bytes;
    left -= bytes;
    return out;
  }
};

}  // namespace haloplot
