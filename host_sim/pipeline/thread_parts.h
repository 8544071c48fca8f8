// The host's runner for the core's parts (memory/parts.h): the calling thread and threads kept
// asleep between runs take the parts between them. The core splits a stage into as many parts
// as it is told threads; it never starts one itself.
#pragma once
#include <cstdint>

#include "haloplot/memory/parts.h"

namespace haloplot::host {

// The machine's cores (std::thread::hardware_concurrency), at least one: --threads' default.
uint32_t machine_threads();

// The most threads --threads takes.
inline constexpr uint32_t kMaxThreads = 256;

// Parts for `threads` threads (at most kMaxThreads), alive as long as the program; one thread
// gives none (null), so a stage runs exactly as the controller's does.
const Parts* thread_parts(uint32_t threads);

}  // namespace haloplot::host
