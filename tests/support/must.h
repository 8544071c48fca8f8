// A core call a benchmark or a test's set-up relies on: a status other than kOk ends the run
// with its name, so a failed stage is never timed or measured as if it had worked.
#pragma once
#include <cstdio>
#include <cstdlib>

#include "haloplot/status/status.h"

inline void must(haloplot::Status s, const char* what = "a core call") {
  if (s == haloplot::Status::kOk) return;
  std::fprintf(stderr, "%s failed: %s\n", what, haloplot::status_name(s));
  std::abort();
}
