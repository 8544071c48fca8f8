// The memory contract on the host (firmware/selftest/misaligned_checks.h): every public entry that
// takes a caller buffer, the buffer at offsets 0 to 8 from an 8-byte boundary. x86 would run a
// misaligned buffer without complaint, so what is checked here is the named status and the
// untouched buffer; the same checks under QEMU show that no Cortex-M access faults.
#include <cstdio>

#include "selftest/misaligned_checks.h"

int main() {
  using namespace haloplot;
  uint32_t checks = 0;
  misaligned::Report report{
      [](void* ctx, const char* entry, uint32_t offset, Status got, bool pass) {
        ++*static_cast<uint32_t*>(ctx);
        if (!pass) std::printf("FAILED: %s at offset %u: %s\n", entry, offset, status_name(got));
      },
      &checks};
  const uint32_t failures = misaligned::check_all(report);
  std::printf("misaligned_buffers: %u checks, %u failed\n", checks, failures);
  return failures == 0 && checks > 0 ? 0 : 1;
}
