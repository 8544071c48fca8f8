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

Parts thread_parts(uint32_t threads) {
  Parts p;
  if (threads <= 1) return p;
  p.run = &run_on_threads;
  p.count = threads;
  return p;
}

}  // namespace haloplot::host
