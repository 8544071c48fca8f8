#include "platform/semihosting.h"

namespace haloplot::fw {
namespace {

// The operation in the first argument register, its parameter block in the second, the result
// back in the first. Arm (M profile): BKPT 0xAB. RISC-V: EBREAK between the two marker
// instructions the semihosting spec names, all three uncompressed, so the debugger can tell it
// from a breakpoint.
int32_t call(uint32_t op, const void* arg) {
#if defined(__riscv)
  register uintptr_t a0 __asm__("a0") = op;
  register const void* a1 __asm__("a1") = arg;
  __asm__ volatile(
      ".option push\n.option norvc\n.balign 16\n"
      "slli zero, zero, 0x1f\nebreak\nsrai zero, zero, 7\n.option pop"
      : "+r"(a0)
      : "r"(a1)
      : "memory");
  return static_cast<int32_t>(a0);
#else
  register uint32_t r0 __asm__("r0") = op;
  register const void* r1 __asm__("r1") = arg;
  __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
  return static_cast<int32_t>(r0);
#endif
}

constexpr uint32_t kOpen = 0x01, kWrite = 0x05, kExit = 0x18, kExitExtended = 0x20, kElapsed = 0x30,
                   kTickFreq = 0x31;

// The console is the special file ":tt", opened for writing (mode 4, "w"): writes to an
// unopened handle go nowhere.
int32_t console_handle() {
  static int32_t handle = -1;
  if (handle < 0) {
    static const char name[] = ":tt";
    const uintptr_t args[3] = {reinterpret_cast<uintptr_t>(name), 4, 3};
    handle = call(kOpen, args);
  }
  return handle;
}
constexpr uint32_t kApplicationExit = 0x20026;  // ADP_Stopped_ApplicationExit

}  // namespace

void semihost_write(const char* text, uint32_t length) {
  const uintptr_t args[3] = {static_cast<uintptr_t>(console_handle()),
                             reinterpret_cast<uintptr_t>(text), length};
  call(kWrite, args);
}

void semihost_print(const char* text) {
  uint32_t n = 0;
  while (text[n]) ++n;
  semihost_write(text, n);
}

void semihost_exit(int status) {
  const uintptr_t args[2] = {kApplicationExit, static_cast<uintptr_t>(status)};
  call(kExitExtended, args);
  call(kExit, reinterpret_cast<const void*>(kApplicationExit));  // older hosts
  for (;;) {
  }
}

uint64_t semihost_elapsed() {
  uint32_t ticks[2] = {0, 0};
  if (call(kElapsed, ticks) != 0) return 0;
  return (uint64_t{ticks[1]} << 32) | ticks[0];
}

uint32_t semihost_tick_hz() { return static_cast<uint32_t>(call(kTickFreq, nullptr)); }

char* append(char* out, const char* text) {
  while (*text) *out++ = *text++;
  *out = 0;
  return out;
}

char* append_u64(char* out, uint64_t v) {
  char digits[21];
  int n = 0;
  do {
    digits[n++] = static_cast<char>('0' + v % 10);
    v /= 10;
  } while (v);
  while (n) *out++ = digits[--n];
  *out = 0;
  return out;
}

char* append_i64(char* out, int64_t v) {
  if (v < 0) {
    *out++ = '-';
    return append_u64(out, uint64_t(0) - uint64_t(v));
  }
  return append_u64(out, uint64_t(v));
}

}  // namespace haloplot::fw
