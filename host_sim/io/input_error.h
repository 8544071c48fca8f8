// A bad-input report: which file, which line (0 when the problem is not on one line), and
// what is wrong. Every reader returns one instead of throwing or guessing.
#pragma once
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
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

// Why an input file cannot be read, or no error when `in` opened it and it is a file: missing,
// a directory (which opens, then fails to read), no permission, or the system's reason.
inline InputError open_problem(const std::string& path, const std::ifstream& in) {
  struct stat st;
  const int saved = errno;
  if (::stat(path.c_str(), &st) != 0)
    return {path, 0,
            errno == ENOENT ? std::string("cannot open: no such file")
                            : "cannot open: " + std::string(std::strerror(errno))};
  if (S_ISDIR(st.st_mode)) return {path, 0, "cannot open: a directory, not a file"};
  if (in.is_open() && in.good()) return {};
  if (::access(path.c_str(), R_OK) != 0) return {path, 0, "cannot open: permission denied"};
  return {path, 0, "cannot open: " + std::string(std::strerror(saved != 0 ? saved : EIO))};
}

}  // namespace haloplot::host
