#include "cli/stage_progress.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace haloplot::host {
namespace {

// How long a stage runs before it is announced: a second, or HALOPLOT_PROGRESS_AFTER_MS.
std::chrono::milliseconds announce_after() {
  const char* v = std::getenv("HALOPLOT_PROGRESS_AFTER_MS");
  return std::chrono::milliseconds(v != nullptr && *v != '\0' ? std::atol(v) : 1000);
}

}  // namespace

StageProgress::StageProgress(std::string name) : name_(std::move(name)) {
  if (!isatty(2)) return;
  if (announce_after().count() == 0)  // every stage, said at once (tests: no race with the clock)
    std::fprintf(stderr, "haloplot: %s ...\n", name_.c_str());
  else
    watcher_ = std::thread([this] { watch(); });
}

StageProgress::~StageProgress() {
  if (!watcher_.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  done_signal_.notify_one();
  watcher_.join();
}

void StageProgress::watch() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (done_signal_.wait_for(lock, announce_after(), [this] { return done_; }) && done_) return;
  // A whole line: whatever else the stage says on stderr (a warning, the summary) stays apart.
  std::fprintf(stderr, "haloplot: %s ...\n", name_.c_str());
}

}  // namespace haloplot::host
