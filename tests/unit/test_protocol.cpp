// The host-link framing: CRC-32 against the standard check value and a bitwise reference;
// frames round-trip; damaged, truncated, oversized and interleaved-garbage streams never
// deliver a frame that was not sent, report the damage, and recover for the frames after it.
#include <deque>
#include <string>
#include <vector>

#include "../check.h"
#include "../support/scenes.h"
#include "haloplot/protocol/crc32.h"
#include "haloplot/protocol/frame.h"
#include "haloplot/protocol/messages.h"

using namespace haloplot;

static uint32_t crc_bitwise(const std::vector<uint8_t>& d) {  // the textbook loop, for reference
  uint32_t c = 0xFFFFFFFFu;
  for (uint8_t b : d) {
    c ^= b;
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
  }
  return ~c;
}

struct Sent {
  uint8_t type, seq;
  std::vector<uint8_t> payload;
  bool operator==(const Sent& o) const {
    return type == o.type && seq == o.seq && payload == o.payload;
  }
};

// Feed a stream; collect delivered frames and the number of bad-frame events.
static std::vector<Sent> receive(const std::vector<uint8_t>& stream, uint32_t* bad) {
  std::vector<uint8_t> buf(512 + kFrameOverhead);
  FrameDecoder dec(buf.data(), buf.size(), 512);
  std::vector<Sent> got;
  *bad = 0;
  auto take = [&](FrameDecoder::Event ev) {
    if (ev == FrameDecoder::Event::kFrame)
      got.push_back(
          {dec.frame().type, dec.frame().seq,
           std::vector<uint8_t>(dec.frame().payload, dec.frame().payload + dec.frame().length)});
    if (ev == FrameDecoder::Event::kBadFrame) ++*bad;
    return ev != FrameDecoder::Event::kNone;
  };
  for (uint8_t b : stream) {
    take(dec.push(b));
    while (take(dec.poll())) {
    }
  }
  // The line goes quiet: the link's idle timeout lets a damaged length give up its claim.
  for (FrameDecoder::Event ev; (ev = dec.idle()) != FrameDecoder::Event::kNone;) {
    take(ev);
    while (take(dec.poll())) {
    }
  }
  return got;
}

int main() {
  const std::string check = "123456789";
  CHECK_EQ(crc32(reinterpret_cast<const uint8_t*>(check.data()), check.size()), 0xCBF43926u);
  scenes::Rng r(99);
  for (int i = 0; i < 2000; ++i) {
    std::vector<uint8_t> d(r.uniform(0, 300));
    for (auto& b : d) b = uint8_t(r.next());
    CHECK_EQ(crc32(d.data(), d.size()), crc_bitwise(d));
  }
  // A stream of frames with random payloads, including start bytes inside payloads.
  std::vector<Sent> sent;
  std::vector<uint8_t> stream;
  for (int i = 0; i < 300; ++i) {
    Sent s{uint8_t(r.uniform(1, 0x3F)), uint8_t(i), std::vector<uint8_t>(r.uniform(0, 200))};
    for (auto& b : s.payload) b = (r.next() % 5 == 0) ? kFrameStart : uint8_t(r.next());
    std::vector<uint8_t> f(s.payload.size() + kFrameOverhead);
    CHECK_EQ(encode_frame(s.type, s.seq, s.payload.data(), uint16_t(s.payload.size()), f.data(),
                          f.size()),
             f.size());
    stream.insert(stream.end(), f.begin(), f.end());
    sent.push_back(s);
  }
  uint32_t bad = 0;
  CHECK(receive(stream, &bad) == sent);
  CHECK_EQ(bad, 0u);
  // Corruption: flip a bit inside some frames. Every delivered frame was sent, every intact
  // frame is delivered, and the damaged ones are reported.
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<uint8_t> damaged = stream;
    std::vector<bool> hit(sent.size(), false);
    size_t offset = 0;
    for (size_t k = 0; k < sent.size(); ++k) {
      const size_t len = sent[k].payload.size() + kFrameOverhead;
      if (r.next() % 7 == 0) {
        damaged[offset + r.uniform(0, int64_t(len) - 1)] ^= uint8_t(1u << r.uniform(0, 7));
        hit[k] = true;
      }
      offset += len;
    }
    const auto got = receive(damaged, &bad);
    size_t intact = 0, delivered_intact = 0;
    for (size_t k = 0; k < sent.size(); ++k) intact += !hit[k];
    bool all_sent = true;
    for (const Sent& g : got) {
      bool found = false;
      for (size_t k = 0; k < sent.size(); ++k) found = found || (g == sent[k]);
      all_sent = all_sent && found;
    }
    for (size_t k = 0; k < sent.size(); ++k)
      if (!hit[k])
        for (const Sent& g : got) delivered_intact += g == sent[k];
    CHECK_MSG(all_sent, "a damaged frame was delivered");
    CHECK_MSG(delivered_intact == intact,
              "an intact frame was lost: " + std::to_string(delivered_intact) + " of " +
                  std::to_string(intact));
    CHECK(bad > 0);
  }
  // Truncation: a frame cut short, then the rest of the stream.
  {
    std::vector<uint8_t> cut(stream.begin(), stream.begin() + 20);  // part of frame 0
    const size_t first = sent[0].payload.size() + kFrameOverhead;
    cut.insert(cut.end(), stream.begin() + long(first), stream.end());
    const auto got = receive(cut, &bad);
    std::vector<Sent> rest(sent.begin() + 1, sent.end());  // frame 0 is lost, nothing else
    CHECK(got == rest);
  }
  // Garbage between frames, and an oversized length, are skipped.
  {
    std::vector<uint8_t> noisy = {0x00, kFrameStart, 0xFF, 0xFF, 0x13, 0x7E, 0x7E};
    noisy.insert(noisy.end(), stream.begin(), stream.end());
    const auto got = receive(noisy, &bad);
    CHECK(got == sent);
    CHECK(bad > 0);
  }
  // A frame that does not fit the caller's buffer is refused by the encoder.
  uint8_t small[8];
  CHECK_EQ(encode_frame(1, 0, nullptr, 0, small, sizeof small), size_t{0});
  // The machine's pen start is a plot position: one outside the coordinate range is refused
  // (the fuzzer's INT32_MIN start overflowed the path planner's grid span before).
  {
    haloplot::JobSpec spec;
    uint8_t buf[haloplot::kMachineBytes];
    haloplot::JobSpec got;
    for (const int32_t outside : {-1, INT32_MIN, haloplot::kCoordLimit}) {
      spec.start_x = outside;
      haloplot::encode_machine(spec, buf);
      CHECK(haloplot::decode_machine(buf, sizeof buf, &got) ==
            haloplot::Status::kCoordinateOutOfRange);
    }
    spec.start_x = 400;
    spec.start_y = haloplot::kCoordLimit - 1;
    haloplot::encode_machine(spec, buf);
    CHECK(ok(haloplot::decode_machine(buf, sizeof buf, &got)) && got.start_x == 400 &&
          got.start_y == haloplot::kCoordLimit - 1);
  }
  return check::finish("protocol");
}
