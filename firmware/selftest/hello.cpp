// Smallest image: prints, reports virtual time, exits with status 3. Proves boot, semihosting
// and exit codes under QEMU.
#include "platform/semihosting.h"

using namespace haloplot::fw;

int main() {
  char line[96];
  char* p = append(line, "hello from the STM32F405 image; elapsed ticks ");
  p = append_u64(p, semihost_elapsed());
  p = append(p, " at ");
  p = append_u64(p, semihost_tick_hz());
  append(p, " Hz\n");
  semihost_print(line);
  semihost_exit(3);
}
