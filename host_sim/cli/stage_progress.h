// A line on stderr for each stage of a command that takes over a second, when stderr is a
// terminal: "haloplot: hidden lines ..." once the second has passed, so a long plot is never
// silent. Once per stage; nothing for a quick stage, and nothing at all when stderr is a file
// or a pipe (scripts and tests read stderr). HALOPLOT_PROGRESS_AFTER_MS sets the second to another
// wait (tests: 0 announces every stage).
#pragma once
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace haloplot::host {

class StageProgress {
 public:
  explicit StageProgress(std::string name);
  ~StageProgress();
  StageProgress(const StageProgress&) = delete;
  StageProgress& operator=(const StageProgress&) = delete;

 private:
  void watch();

  std::string name_;
  std::mutex mutex_;
  std::condition_variable done_signal_;
  bool done_ = false;
  std::thread watcher_;
};

}  // namespace haloplot::host
