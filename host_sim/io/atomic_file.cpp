#include "io/atomic_file.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <csignal>
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

// The temporary files that exist now, for the signal handler: fixed slots it can read at any
// moment (no allocation, no container that may be moving), each a path and a flag set last.
constexpr int kTmpSlots = 64;
char tmp_path[kTmpSlots][PATH_MAX];
volatile sig_atomic_t tmp_used[kTmpSlots];

void note_tmp(const std::string& path) {
  if (path.size() >= PATH_MAX) return;
  for (int i = 0; i < kTmpSlots; ++i)
    if (!tmp_used[i]) {
      std::memcpy(tmp_path[i], path.c_str(), path.size() + 1);
      tmp_used[i] = 1;
      return;
    }
}

void forget_tmp(const std::string& path) {
  for (int i = 0; i < kTmpSlots; ++i)
    if (tmp_used[i] && path == tmp_path[i]) tmp_used[i] = 0;
}

extern "C" void remove_tmp_and_die(int sig) {
  for (int i = 0; i < kTmpSlots; ++i)
    if (tmp_used[i]) unlink(tmp_path[i]);  // async-signal-safe
  signal(sig, SIG_DFL);
  raise(sig);
}

}  // namespace

void remove_staged_on_signal() {
  static bool installed = false;
  if (installed) return;
  installed = true;
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction was = {};
    if (sigaction(sig, nullptr, &was) == 0 && was.sa_handler == SIG_IGN) continue;  // nohup
    struct sigaction sa = {};
    sa.sa_handler = remove_tmp_and_die;
    sigemptyset(&sa.sa_mask);
    sigaction(sig, &sa, nullptr);
  }
}

std::string output_problem(const std::string& path) {
  std::string target, why;
  const Kind kind = classify(path, &target, &why);
  if (kind == Kind::kRefused) return path + ": cannot write there (" + why + ")";
  if (kind == Kind::kThrough) return "";
  const size_t slash = target.rfind('/');
  const std::string folder = slash == std::string::npos ? "." : target.substr(0, slash + 1);
  struct stat st;
  if (stat(folder.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    return path + ": cannot write there (no folder '" + folder + "')";
  if (access(folder.c_str(), W_OK) != 0)
    return path + ": cannot write there (folder '" + folder + "' is not writable)";
  return "";
}

OutputSet::OutputSet() : previous_(current) {
  current = this;
  remove_staged_on_signal();
}

OutputSet::~OutputSet() {
  for (const Staged& s : staged_) {
    std::remove(s.tmp.c_str());
    forget_tmp(s.tmp);
  }
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
  note_tmp(s.tmp);
  {
    std::ofstream out(s.tmp, std::ios::binary);
    if (!out) return path + ": cannot open for writing";
    const bool fine = write(out);
    out.flush();
    if (!fine || !out) {
      out.close();
      std::remove(s.tmp.c_str());
      forget_tmp(s.tmp);
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
  for (const Staged& s : staged_) {
    std::remove(s.tmp.c_str());  // renamed ones are gone already
    forget_tmp(s.tmp);
  }
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
