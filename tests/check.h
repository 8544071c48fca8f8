// A tiny check library for CTest: each test is an executable whose exit code is the verdict.
// CHECK records a failure with file and line and keeps going, so one run shows every problem.
#pragma once
#include <cstdio>
#include <sstream>
#include <string>

namespace check {

inline int& failures() {
  static int n = 0;
  return n;
}
inline int& passes() {
  static int n = 0;
  return n;
}

inline void record(bool ok, const char* file, int line, const std::string& what) {
  if (ok) {
    ++passes();
    return;
  }
  if (++failures() <= 40) std::fprintf(stderr, "%s:%d: FAILED: %s\n", file, line, what.c_str());
}

inline int finish(const char* name) {
  std::printf("%s: %d passed, %d failed\n", name, passes(), failures());
  return failures() == 0 ? 0 : 1;
}

template <typename A, typename B>
std::string describe(const char* ea, const char* eb, const A& a, const B& b) {
  std::ostringstream s;
  s << ea << " == " << eb << " (" << a << " vs " << b << ")";
  return s.str();
}

}  // namespace check

#define CHECK(cond) ::check::record(static_cast<bool>(cond), __FILE__, __LINE__, #cond)
#define CHECK_MSG(cond, msg) ::check::record(static_cast<bool>(cond), __FILE__, __LINE__, (msg))
#define CHECK_EQ(a, b)                                              \
  do {                                                              \
    const auto& check_a_ = (a);                                     \
    const auto& check_b_ = (b);                                     \
    ::check::record(check_a_ == check_b_, __FILE__, __LINE__,       \
                    ::check::describe(#a, #b, check_a_, check_b_)); \
  } while (0)
