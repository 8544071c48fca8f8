#include "pipeline/thread_parts.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace haloplot::host {
namespace {

// The parts on `threads` threads (the calling one and threads started for this run), which take
// them by a shared counter: the runner when the pool below is busy (a part that itself runs
// parts). Where the system refuses a thread, the others take its parts.
void run_on_new_threads(uint32_t n, uint32_t threads, PartFn work, void* arg) {
  std::atomic<uint32_t> next{0};
  const auto take = [&] {
    for (uint32_t i; (i = next.fetch_add(1)) < n;) work(arg, i);
  };
  std::vector<std::thread> others;
  others.reserve(threads);
  for (uint32_t t = 1; t < threads && t < n; ++t) {
    try {
      others.emplace_back(take);
    } catch (const std::system_error&) {
      break;
    }
  }
  take();
  for (std::thread& t : others) t.join();
}

// Spins until done() or kSpin has passed; true when done. Waking a sleeping thread costs tens
// of microseconds on a virtual machine, once to start a run and once more to tell the caller
// it ended; CUT's runs on 50,000 edges follow each other a few hundred microseconds apart, so
// a thread that spins that long before it sleeps finds the next run without being woken. The
// spin is bounded, so a thread between stages (or a loaded machine) still sleeps.
constexpr std::chrono::microseconds kSpin{300};

inline void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#elif defined(__aarch64__)
  asm volatile("yield");
#endif
}

template <class Done>
bool spin_until(Done done) {
  const auto until = std::chrono::steady_clock::now() + kSpin;
  for (uint32_t i = 1;; ++i) {
    if (done()) return true;
    cpu_relax();
    if (i % 64 == 0 && std::chrono::steady_clock::now() > until) return done();
  }
}

// Threads kept between runs, spinning a moment and then asleep in between: starting a thread
// costs about 20 us, and a stage calls the runner several times (CUT six times, in a few ms on
// 50,000 edges). The caller and the woken workers take the parts by a shared counter, so a
// worker that wakes late leaves its parts to the others rather than keeping them waiting.
// A stage may split into more parts than there are threads (so that a thread that starts late,
// or is slowed by another program, leaves its share to the others): the workers are as many as
// the caller's threads, less the caller (workers started for a run with more threads stay
// out of it).
class Pool {
 public:
  // One run at a time: false when another is under way.
  bool run(uint32_t n, uint32_t threads, PartFn work, void* arg) {
    std::unique_lock<std::mutex> mine(busy_, std::try_to_lock);
    if (!mine.owns_lock()) return false;
    const uint32_t helpers = (n < threads ? n : threads) - 1;
    grow(helpers);
    {
      std::unique_lock<std::mutex> lock(m_);
      // A worker that took the last run late may still be about to claim from its counter.
      settled_.wait(lock, [&] { return taking_ == 0; });
      work_ = work;
      arg_ = arg;
      n_ = n;
      helpers_ = helpers;
      next_.store(0);
      done_.store(0);
      job_.fetch_add(1);
    }
    wake_.notify_all();
    const uint32_t ran = take(work, arg, n);
    {
      std::lock_guard<std::mutex> lock(m_);
      done_.fetch_add(ran);
    }
    if (spin_until([&] { return done_.load() == n; })) return true;
    std::unique_lock<std::mutex> lock(m_);
    settled_.wait(lock, [&] { return done_.load() == n_; });
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
        workers_.emplace_back(&Pool::serve, this, uint32_t(workers_.size()));
      } catch (const std::system_error&) {
        return;
      }
    }
  }

  [[noreturn]] void serve(uint32_t index) {
    uint64_t seen = 0;
    for (;;) {
      spin_until([&] { return job_.load() != seen; });
      std::unique_lock<std::mutex> lock(m_);
      wake_.wait(lock, [&] { return job_.load() != seen; });
      seen = job_.load();
      if (index >= helpers_) continue;
      const PartFn work = work_;
      void* const arg = arg_;
      const uint32_t n = n_;
      ++taking_;
      lock.unlock();
      const uint32_t ran = take(work, arg, n);
      lock.lock();
      --taking_;
      done_.fetch_add(ran);
      lock.unlock();
      settled_.notify_all();
    }
  }

  std::mutex busy_;  // held for a whole run
  std::mutex m_;     // guards the fields below but next_; job_ and done_ change only under it,
                     // and are atomic so that a spinning thread may read them without it
  std::condition_variable wake_, settled_;
  std::vector<std::thread> workers_;
  std::atomic<uint64_t> job_{0};
  PartFn work_ = nullptr;
  void* arg_ = nullptr;
  uint32_t n_ = 0, helpers_ = 0, taking_ = 0;
  std::atomic<uint32_t> done_{0}, next_{0};
};

// The context is the thread count (thread_parts).
void run_on_threads(void* context, uint32_t n, PartFn work, void* arg) {
  const uint32_t threads = uint32_t(reinterpret_cast<uintptr_t>(context));
  // Never destroyed: its workers sleep until the process ends, and a static destroyed after it
  // may still run parts.
  static Pool* const pool = new Pool;
  if (!pool->run(n, threads, work, arg)) run_on_new_threads(n, threads, work, arg);
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
      all[n].context = reinterpret_cast<void*>(uintptr_t{n});
      all[n].count = n;
    }
    return all;
  }();
  return threads <= 1 ? nullptr : &each[threads < kMaxThreads ? threads : kMaxThreads];
}

}  // namespace haloplot::host
