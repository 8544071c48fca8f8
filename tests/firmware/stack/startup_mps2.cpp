// Reset and the vector table of the stack probe on QEMU's mps2-an386 (any Cortex-M code that
// ARMv7E-M runs): the portable C runtime start (firmware/platform), then main(), its status the
// exit status. Any fault ends the run over semihosting with status 3, so a test fails at once.
#include <stdint.h>

#include "platform/c_runtime.h"
#include "platform/semihosting.h"

extern "C" {
int main();

[[noreturn]] void probe_reset() {
  haloplot::fw::start_c_runtime();
  haloplot::fw::run_static_constructors();
  haloplot::fw::semihost_exit(main());
}

[[noreturn]] void probe_fault() {
  haloplot::fw::semihost_print("probe: fault\n");
  haloplot::fw::semihost_exit(3);
}
}

// The initial stack pointer, reset, and the faults (NMI to UsageFault).
__attribute__((section(".vectors"), used)) void (*const probe_vectors[7])() = {
    reinterpret_cast<void (*)()>(&__stack_top),
    probe_reset,
    probe_fault,
    probe_fault,
    probe_fault,
    probe_fault,
    probe_fault};
