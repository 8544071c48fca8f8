// The size queries are bounds (tests/unit/size_bound_checks.h) on the host: every query on
// every test scene at least what its run used and at most 1.5 times it. `size_bounds control`
// is the same check with each answer scaled to 90 %, and must fail (CTest size_bounds_control):
// the checker refuses a query short of its run.
#include <cstdio>
#include <cstring>

#include "unit/size_bound_checks.h"

int main(int argc, char** argv) {
  const bool control = argc > 1 && std::strcmp(argv[1], "control") == 0;
  const haloplot::size_bounds::Report report{
      [](void*, const char* query, const char* scene, uint64_t asked, uint64_t used, bool pass) {
        std::printf("%-4s %-24s %-16s asked=%-8llu used=%-8llu ratio=%.3f\n", pass ? "ok" : "FAIL",
                    query, scene, (unsigned long long)asked, (unsigned long long)used,
                    used ? double(asked) / double(used) : 0.0);
      },
      nullptr};
  uint32_t checks = 0;
  const uint32_t failures = haloplot::size_bounds::check_all(report, control ? 900 : 1000, &checks);
  std::printf("size bounds: %u checks, %u failed%s\n", checks, failures,
              control ? " (control: every query 10 % short)" : "");
  return failures == 0 && checks > 0 ? 0 : 1;
}
