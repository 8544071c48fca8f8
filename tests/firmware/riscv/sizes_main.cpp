// The size queries are bounds on RV32 (tests/firmware/qemu_riscv_test.sh): the checks of
// tests/unit/size_bound_checks.h, as the host's CTest size_bounds runs them, on the chip. Prints
// "fw size QUERY | SCENE asked=A used=U ok|FAILED" per check, then exits 0 if every one passed.
#include "platform/semihosting.h"
#include "unit/size_bound_checks.h"

using namespace haloplot;

int main() {
  const size_bounds::Report report{
      [](void*, const char* query, const char* scene, uint64_t asked, uint64_t used, bool pass) {
        char line[128];
        char* p = fw::append(line, "fw size ");
        p = fw::append(p, query);
        p = fw::append(p, " | ");
        p = fw::append(p, scene);
        p = fw::append(p, " asked=");
        p = fw::append_u64(p, asked);
        p = fw::append(p, " used=");
        p = fw::append_u64(p, used);
        p = fw::append(p, pass ? " ok\n" : " FAILED\n");
        fw::semihost_write(line, uint32_t(p - line));
      },
      nullptr};
  uint32_t checks = 0;
  const uint32_t failures = size_bounds::check_all(report, 1000, &checks);
  return failures == 0 && checks > 0 ? 0 : 1;
}
