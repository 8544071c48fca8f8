// The controller's job server under arbitrary requests: the input is a list of
// (type, length, payload) requests, each wrapped in a valid frame with the seq the server
// expects, so the fuzzer reaches the request handlers rather than the CRC check (the frame
// decoder has its own target). Every request must get exactly one reply, never a crash, and
// the server's counts must stay within what was declared.
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "haloplot/protocol/job_server.h"
#include "support/virtual_motion.h"

using namespace haloplot;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static std::vector<uint8_t> arena(64 * 1024), rx(JobServer::kMaxPayload + kFrameOverhead);
  size_t replies = 0;
  test::VirtualMotion motion;
  JobServer server(
      arena.data(), arena.size(), rx.data(), rx.size(),
      ByteOutput{&replies, [](void* c, const uint8_t*, uint32_t) { ++*static_cast<size_t*>(c); }},
      motion.port());
  uint8_t seq = 0;
  std::vector<uint8_t> frame(256 + kFrameOverhead);
  size_t at = 0;
  while (at + 2 <= size) {
    const uint8_t type = data[at];
    const size_t len = std::min<size_t>(data[at + 1], size - at - 2);
    const size_t n =
        encode_frame(type, seq, data + at + 2, uint16_t(len), frame.data(), frame.size());
    at += 2 + len;
    const size_t before = replies;
    for (size_t i = 0; i < n; ++i) server.push(frame[i]);
    server.service();
    if (replies != before + 1) std::abort();  // one reply per request, whatever it was
    ++seq;
  }
  return 0;
}
