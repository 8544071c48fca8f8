// libFuzzer: the host-link frame decoder on any bytes. Every frame it delivers must carry a
// length within the limit and a CRC that checks; nothing may touch memory outside its buffer
// (ASan watches the heap copy below).
#include <cstdlib>
#include <vector>

#include "haloplot/protocol/crc32.h"
#include "haloplot/protocol/frame.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using haloplot::FrameDecoder;
  const uint16_t max_payload = 64;
  std::vector<uint8_t> buf(max_payload + haloplot::kFrameOverhead);
  FrameDecoder dec(buf.data(), buf.size(), max_payload);
  auto check = [&](FrameDecoder::Event ev) {
    if (ev != FrameDecoder::Event::kFrame) return ev != FrameDecoder::Event::kNone;
    const haloplot::Frame& f = dec.frame();
    if (f.length > max_payload) std::abort();
    // Re-encode and compare: the delivered frame must be exactly a valid encoding.
    std::vector<uint8_t> again(f.length + haloplot::kFrameOverhead);
    if (haloplot::encode_frame(f.type, f.seq, f.payload, f.length, again.data(), again.size()) !=
        again.size())
      std::abort();
    const uint8_t* crc = f.payload + f.length;  // the received CRC follows the payload
    for (int k = 0; k < 4; ++k)
      if (crc[k] != again[5 + f.length + k]) std::abort();
    return true;
  };
  for (size_t i = 0; i < size; ++i) {
    check(dec.push(data[i]));
    while (check(dec.poll())) {
    }
  }
  while (check(dec.idle())) {
    while (check(dec.poll())) {
    }
  }
  return 0;
}
