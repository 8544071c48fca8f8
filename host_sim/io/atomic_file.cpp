#include "io/atomic_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>

namespace haloplot::host {
namespace {

OutputSet* current = nullptr;

enum class Kind { kRegular, kThrough, kRefused };

// Where PATH's bytes go, and how (see atomic_file.h); *why says what is wrong when refused.
Kind classify(const std::string& path, std::string* target, std::string* why) {
  *target = path;
  if (path == "-") return Kind::kThrough;
  struct stat st;
  if (lstat(path.c_str(), &st) != 0) {
    if (errno == ENOENT) return Kind::kRegular;  // a new file
    *why = std::strerror(errno);
    return Kind::kRefused;
  }
  if (S_ISLNK(st.st_mode)) {
    char* real = realpath(path.c_str(), nullptr);
    if (real == nullptr) {
      *why = "a symbolic link to nowhere";
      return Kind::kRefused;
    }
    *target = real;
    std::free(real);
    if (stat(target->c_str(), &st) != 0) {
      *why = std::strerror(errno);
      return Kind::kRefused;
    }
  }
  if (S_ISREG(st.st_mode)) return Kind::kRegular;
  if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode)) return Kind::kThrough;
  *why = S_ISDIR(st.st_mode) ? "is a directory" : "not a file, device or FIFO";
  return Kind::kRefused;
}

// A temporary file for an output that is written through on commit.
std::string through_tmp() {
  const char* dir = std::getenv("TMPDIR");
  std::string name = std::string(dir && *dir ? dir : "/tmp") + "/haloplot-out-XXXXXX";
  std::vector<char> buf(name.begin(), name.end());
  buf.push_back('\0');
  const int fd = mkstemp(buf.data());
  if (fd < 0) return "";
  close(fd);
  return buf.data();
}

bool copy_into(const std::string& tmp, std::ostream& out) {
  std::ifstream in(tmp, std::ios::binary);
  if (!in) return false;
  out << in.rdbuf();
  out.flush();
  return bool(out);
}

}  // namespace

OutputSet::OutputSet() : previous_(current) { current = this; }

OutputSet::~OutputSet() {
  for (const Staged& s : staged_) std::remove(s.tmp.c_str());
  current = previous_;
}

std::string OutputSet::stage(const std::string& path,
                             const std::function<bool(std::ostream&)>& write) {
  Staged s;
  s.path = path;
  std::string why;
  const Kind kind = classify(path, &s.target, &why);
  if (kind == Kind::kRefused) return path + ": cannot write there (" + why + ")";
  s.through = kind == Kind::kThrough;
  s.tmp = s.through ? through_tmp() : s.target + ".tmp";
  if (s.tmp.empty()) return path + ": cannot create a temporary file";
  {
    std::ofstream out(s.tmp, std::ios::binary);
    if (!out) return path + ": cannot open for writing";
    const bool fine = write(out);
    out.flush();
    if (!fine || !out) {
      out.close();
      std::remove(s.tmp.c_str());
      return path + ": write failed";
    }
  }
  staged_.push_back(s);
  return "";
}

std::string OutputSet::commit() {
  std::string error;
  for (const Staged& s : staged_) {
    if (!error.empty()) break;  // the rest are removed with the set
    if (!s.through) {
      if (std::rename(s.tmp.c_str(), s.target.c_str()) != 0)
        error = s.path + ": cannot rename the finished file into place";
      continue;
    }
    bool fine;
    if (s.path == "-") {
      fine = copy_into(s.tmp, std::cout);
    } else {
      std::ofstream out(s.target, std::ios::binary | std::ios::app);
      fine = out && copy_into(s.tmp, out);
    }
    if (!fine) error = s.path + ": write failed";
  }
  for (const Staged& s : staged_) std::remove(s.tmp.c_str());  // renamed ones are gone already
  staged_.clear();
  return error;
}

std::string write_atomically(const std::string& path,
                             const std::function<bool(std::ostream&)>& write) {
  if (current != nullptr) return current->stage(path, write);
  OutputSet once;
  const std::string e = once.stage(path, write);
  return e.empty() ? once.commit() : e;
}

}  // namespace haloplot::host
