// The host's StageMemory (core/memory/sized_stage.h): a buffer that grows to what a sized run
// asks for, zeroed each time so no run sees the last one's bytes.
#pragma once
#include <cstdint>
#include <vector>

#include "haloplot/memory/sized_stage.h"

namespace haloplot::host {

struct HostMemory {
  std::vector<uint64_t> words;
  static StageBuffer get(void* context, size_t bytes) {
    auto* self = static_cast<HostMemory*>(context);
    self->words.assign(bytes / 8 + 1, 0);
    return StageBuffer{self->words.data(), self->words.size() * 8};
  }
  StageMemory memory() { return StageMemory{&HostMemory::get, this, false}; }
};

}  // namespace haloplot::host
