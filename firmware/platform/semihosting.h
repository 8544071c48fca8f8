// Semihosting: the debugger (here QEMU with -semihosting-config enable=on) services BKPT 0xAB
// calls on Arm, and the marked EBREAK on RISC-V. Used only by test images: console output, the exit
// status CTest sees (SYS_EXIT_EXTENDED), and elapsed virtual time for instruction counts under
// -icount.
#pragma once
#include <stdint.h>

namespace haloplot::fw {

void semihost_write(const char* text, uint32_t length);
void semihost_print(const char* text);  // NUL-terminated
[[noreturn]] void semihost_exit(int status);
// Ticks since the program started (SYS_ELAPSED) and their frequency (SYS_TICKFREQ); under
// -icount shift=0 one instruction is one nanosecond of virtual time.
uint64_t semihost_elapsed();
uint32_t semihost_tick_hz();

// Small freestanding formatting into a caller buffer (no printf in firmware images).
char* append(char* out, const char* text);
char* append_u64(char* out, uint64_t v);
char* append_i64(char* out, int64_t v);

}  // namespace haloplot::fw
