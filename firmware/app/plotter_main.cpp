// The plotter controller, for every board: boots the board (board/board.h, from the board's
// folder), then serves the job protocol on its serial link forever
// (core/include/haloplot/protocol/job_server.h), plotting through the step timer
// (core/include/haloplot/controller/motion_runner.h, on this board: app/board_motion.h).
//
// Memory: one arena for the scene and the job buffer (HALOPLOT_FW_ARENA_KB, the board's
// setting), and the small fixed parts (frame buffer, serial ring, step queue, planner window).
// The stack has 16 KB at the top of RAM (the board's linker script).
//
// Test images (HALOPLOT_FW_TEST_HOOKS, booted under QEMU) also stream the step trace over
// semihosting, answer the test-only request kTestExit with their counters, and exit through
// SYS_EXIT_EXTENDED. The flashed image has none of that: semihosting would fault without a
// debugger attached.
#include "app/board_motion.h"
#include "board/board.h"
#include "haloplot/protocol/job_server.h"
#include "platform/console.h"
#include "platform/instruction_counter.h"

#ifdef HALOPLOT_FW_TEST_HOOKS
#include "platform/semihosting.h"
#include "platform/trace_digest.h"
#endif

using namespace haloplot;
using namespace haloplot::fw;

namespace {

constexpr uint8_t kTestExitType = 0x7F;  // test images only: print the counters and exit
// Test images only: "close" limit switch 0 (Board::test_close_limit: QEMU models no switch
// pin, so the board sets the switch's interrupt pending and the real handler and stop path run).
constexpr uint8_t kTestLimitType = 0x7E;
// Test images only: from the next plot on, sum each step trace to its CRC-32 and length and
// print those ("fw trace_crc32=", "fw trace_bytes=") instead of the trace: a 45 MB trace over
// semihosting takes minutes under QEMU, its digest nothing.
constexpr uint8_t kTestDigestType = 0x7D;
#ifndef HALOPLOT_FW_ARENA_KB
#error "the board's board.cmake sets HALOPLOT_BOARD_ARENA_KB"
#endif
alignas(8) uint8_t arena[HALOPLOT_FW_ARENA_KB * 1024];
uint8_t rx_frame[JobServer::kMaxPayload + kFrameOverhead];
fw::MotionRunner motion;  // this board's (app/board_motion.h), not the template

// Quiet time that ends a frame in progress, in counter ticks (the board's, about 2 ms on the
// chip: 23 byte times at 115200 baud, a sender never pauses that long inside a frame). Under
// QEMU bytes arrive with no baud pacing, whenever its I/O thread runs, and on a loaded machine
// that thread can stall for milliseconds of virtual time while the CPU spins: the test image
// waits 100 ms of virtual time (Board::kTestFrameIdleTicks).
#ifdef HALOPLOT_FW_TEST_HOOKS
constexpr uint64_t kIdleTicks = Board::kTestFrameIdleTicks;
#else
constexpr uint64_t kIdleTicks = Board::kFrameIdleTicks;
#endif

#ifdef HALOPLOT_FW_TEST_HOOKS
Console console;
void stat(const char* key, uint64_t value) { console.stat(key, value); }

TraceDigest digest;
bool digesting = false;
#endif

}  // namespace

// The step interrupt: the board's vector table puts it on its step clock's interrupt.
extern "C" void step_timer_irq() { motion.on_timer(); }

extern "C" uint32_t stack_unused_bytes();

namespace {

#ifdef HALOPLOT_FW_TEST_HOOKS
// The test-only requests: close limit switch 0, digest the traces from the next plot on, and
// exit (once the plot is over: *exit_requested).
JobServer::Extension test_requests(bool* exit_requested) {
  return JobServer::Extension{exit_requested, [](void* c, const Frame& f) {
                                if (f.type == kTestLimitType) {
                                  Board::test_close_limit(0);
                                  return Status::kOk;
                                }
                                if (f.type == kTestDigestType) {
                                  digesting = true;
                                  motion.set_trace(digest.sink());
                                  return Status::kOk;
                                }
                                if (f.type != kTestExitType) return Status::kMalformedRequest;
                                *static_cast<bool*>(c) = true;
                                return Status::kOk;
                              }};
}

// Between plots: each plot's trace whole (or its digest) before the next, and on kTestExit
// the session's counters, then the exit.
void test_image_between_plots(const JobServer& server, bool exit_requested) {
  if (!motion.running()) console.flush();
  if (!motion.running() && digesting && digest.bytes > 0) {
    stat("trace_crc32", digest.crc);
    stat("trace_bytes", digest.bytes);
    console.flush();
    digest.crc = 0;
    digest.bytes = 0;
  }
  if (!exit_requested || motion.running()) return;
  stat("edges", server.edges());
  stat("prepare_instructions", ticks_to_instructions(server.prepare_ticks()));
  stat("replot_instructions", ticks_to_instructions(server.redraw_ticks()));
  stat("underruns", motion.underruns());
  if (motion.hold_exact()) stat("hold_events", motion.hold_events());
  stat("usart_overruns", Board::serial_overruns());
  stat("stack_used_bytes", 16 * 1024 - stack_unused_bytes());
  stat("arena_bytes", sizeof arena);
  console.flush();
  semihost_exit(0);
}
#endif

}  // namespace

int main() {
  Board::init();
  Board::pen_init();
  Board::serial_init(Board::kSerialBaud);
  Board::limits_init([](uint8_t m) { motion.on_limit(m); });
  counter_start();
  Board::watchdog_start();
#ifdef HALOPLOT_FW_TEST_HOOKS
  motion.set_trace(console.sink());
  // The step clock runs Board::kTestTimeScale times fast: QEMU needs no real-time pacing,
  // the trace's ticks are the same, and a plot of minutes takes seconds.
  motion.set_time_scale(Board::kTestTimeScale);
  bool exit_requested = false;
#endif
  JobServer server(
      arena, sizeof arena, rx_frame, sizeof rx_frame,
      ByteOutput{nullptr, [](void*, const uint8_t* b, uint32_t n) { Board::serial_write(b, n); }},
      motion.port());
#ifdef HALOPLOT_FW_TEST_HOOKS
  server.set_extension(test_requests(&exit_requested));
#endif
  server.set_clock(&counter_ticks);
  uint64_t last_byte = counter_ticks();
  bool quiet = true;
  for (;;) {
    Board::watchdog_kick();
    uint8_t b;
    while (Board::serial_read(&b)) {
      server.push(b);
      last_byte = counter_ticks();
      quiet = false;
    }
    if (!quiet && counter_ticks() - last_byte > kIdleTicks) {
      server.idle();
      quiet = true;
    }
    motion.service();
    server.service();
    // While plotting, sleep until the next interrupt (a step, a received byte); QEMU with
    // -icount sleep=off then skips the idle virtual time at no cost. Idle, the loop polls,
    // so the frame idle timeout keeps counting.
    // Interrupts are masked across the check, so one that stops the timer in between still
    // wakes the WFI (a pending interrupt ends it even while masked) and runs on cpsie.
    __asm__ volatile("cpsid i" ::: "memory");
    if (motion.stepping()) __asm__ volatile("wfi");
    __asm__ volatile("cpsie i" ::: "memory");
#ifdef HALOPLOT_FW_TEST_HOOKS
    test_image_between_plots(server, exit_requested);
#endif
  }
}
