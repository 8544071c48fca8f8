#include "pipeline/thread_parts.h"

#include <system_error>
#include <thread>
#include <vector>

namespace haloplot::host {
namespace {

void run_on_threads(void*, uint32_t n, PartFn work, void* arg) {
  std::vector<std::thread> others;
  others.reserve(n);
  uint32_t here_from = n;  // the parts no thread could be started for run here
  for (uint32_t i = 1; i < n; ++i) {
    try {
      others.emplace_back(work, arg, i);
    } catch (const std::system_error&) {
      here_from = i;
      break;
    }
  }
  work(arg, 0);
  for (uint32_t i = here_from; i < n; ++i) work(arg, i);
  for (std::thread& t : others) t.join();
}

}  // namespace

uint32_t machine_threads() {
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 1 : uint32_t(n);
}

const Parts* thread_parts(uint32_t threads) {
  static const std::vector<Parts> each = [] {
    std::vector<Parts> all(kMaxThreads + 1);
    for (uint32_t n = 0; n <= kMaxThreads; ++n) {
      all[n].run = &run_on_threads;
      all[n].count = n;
    }
    return all;
  }();
  return threads <= 1 ? nullptr : &each[threads < kMaxThreads ? threads : kMaxThreads];
}

}  // namespace haloplot::host
