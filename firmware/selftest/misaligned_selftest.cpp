// The memory contract on the chip, booted under QEMU by `firmware_misaligned` (and on the M3,
// `firmware_mps2_misaligned`): every public entry that takes a caller buffer, the buffer at
// offsets 0 to 8 from an 8-byte boundary (firmware/selftest/misaligned_checks.h, the host test's
// checks). A misaligned access on a Cortex-M faults and hangs the image in its fault handler,
// which the test's timeout turns into a failure; every check that ends prints nothing but a
// failure, then one "fw misaligned" summary line.
#include "platform/semihosting.h"
#include "selftest/misaligned_checks.h"

using namespace haloplot;
using namespace haloplot::fw;

int main() {
  uint32_t checks = 0;
  misaligned::Report report{
      [](void* ctx, const char* entry, uint32_t offset, Status got, bool pass) {
        ++*static_cast<uint32_t*>(ctx);
        if (pass) return;
        char line[160];
        char* p = append(line, "fw FAILED: ");
        p = append(p, entry);
        p = append(p, " at offset ");
        p = append_u64(p, offset);
        p = append(p, ": ");
        p = append(p, status_name(got));
        append(p, "\n");
        semihost_print(line);
      },
      &checks};
  const uint32_t failures = misaligned::check_all(report);
  char line[96];
  char* p = append(line, "fw misaligned checks=");
  p = append_u64(p, checks);
  p = append(p, " failed=");
  p = append_u64(p, failures);
  append(p, "\n");
  semihost_print(line);
  semihost_exit(failures == 0 && checks > 0 ? 0 : 1);
}
