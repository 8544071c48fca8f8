#include "pipeline/thread_parts.h"

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace haloplot::host {
namespace {

// Each part on a thread started for it, the calling thread running the first: the runner when
// the pool below is busy (a part that itself runs parts).
void run_on_new_threads(uint32_t n, PartFn work, void* arg) {
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

// Threads kept between runs, asleep in between: starting a thread costs about 20 us, and a
// stage calls the runner several times (CUT six times, in a few ms on 50,000 edges). The
// caller and the woken workers take the parts by a shared counter, so a worker that wakes late
// leaves its parts to the others rather than keeping them waiting.
class Pool {
 public:
  // One run at a time: false when another is under way.
  bool run(uint32_t n, PartFn work, void* arg) {
    std::unique_lock<std::mutex> mine(busy_, std::try_to_lock);
    if (!mine.owns_lock()) return false;
    grow(n - 1);
    {
      std::unique_lock<std::mutex> lock(m_);
      // A worker that took the last run late may still be about to claim from its counter.
      settled_.wait(lock, [&] { return taking_ == 0; });
      work_ = work;
      arg_ = arg;
      n_ = n;
      next_.store(0);
      done_ = 0;
      ++job_;
    }
    wake_.notify_all();
    const uint32_t ran = take(work, arg, n);
    std::unique_lock<std::mutex> lock(m_);
    done_ += ran;
    settled_.wait(lock, [&] { return done_ == n_; });
    return true;
  }

 private:
  uint32_t take(PartFn work, void* arg, uint32_t n) {
    uint32_t ran = 0;
    for (uint32_t i; (i = next_.fetch_add(1)) < n; ++ran) work(arg, i);
    return ran;
  }

  // Starts workers up to `count`; where the system refuses one, the parts still all run (the
  // caller takes what no worker does).
  void grow(uint32_t count) {
    while (workers_.size() < count) {
      try {
        workers_.emplace_back(&Pool::serve, this);
      } catch (const std::system_error&) {
        return;
      }
    }
  }

  [[noreturn]] void serve() {
    uint64_t seen = 0;
    std::unique_lock<std::mutex> lock(m_);
    for (;;) {
      wake_.wait(lock, [&] { return job_ != seen; });
      seen = job_;
      const PartFn work = work_;
      void* const arg = arg_;
      const uint32_t n = n_;
      ++taking_;
      lock.unlock();
      const uint32_t ran = take(work, arg, n);
      lock.lock();
      --taking_;
      done_ += ran;
      settled_.notify_all();
    }
  }

  std::mutex busy_;  // held for a whole run
  std::mutex m_;     // guards the fields below but next_
  std::condition_variable wake_, settled_;
  std::vector<std::thread> workers_;
  uint64_t job_ = 0;
  PartFn work_ = nullptr;
  void* arg_ = nullptr;
  uint32_t n_ = 0, done_ = 0, taking_ = 0;
  std::atomic<uint32_t> next_{0};
};

void run_on_threads(void*, uint32_t n, PartFn work, void* arg) {
  // Never destroyed: its workers sleep until the process ends, and a static destroyed after it
  // may still run parts.
  static Pool* const pool = new Pool;
  if (!pool->run(n, work, arg)) run_on_new_threads(n, work, arg);
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
