// A bad-input report: which file, which line (0 when the problem is not on one line), and
// what is wrong. Every reader returns one instead of throwing or guessing.
#pragma once
#include <string>

namespace haloplot::host {

struct InputError {
  std::string file;
  int line = 0;
  std::string what;

  bool failed() const { return !what.empty(); }
  std::string message() const {
    return line > 0 ? file + ":" + std::to_string(line) + ": " + what : file + ": " + what;
  }
};

}  // namespace haloplot::host
