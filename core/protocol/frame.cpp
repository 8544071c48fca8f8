#include "haloplot/protocol/frame.h"

#include "haloplot/protocol/crc32.h"

namespace haloplot {

size_t encode_frame(uint8_t type, uint8_t seq, const uint8_t* payload, uint16_t n, uint8_t* out,
                    size_t capacity) {
  const size_t total = size_t{n} + kFrameOverhead;
  if (capacity < total) return 0;
  out[0] = kFrameStart;
  out[1] = static_cast<uint8_t>(n & 0xFF);
  out[2] = static_cast<uint8_t>(n >> 8);
  out[3] = type;
  out[4] = seq;
  for (uint16_t i = 0; i < n; ++i) out[5 + i] = payload[i];
  const uint32_t crc = crc32(out + 3, size_t{n} + 2);
  for (int k = 0; k < 4; ++k) out[5 + n + k] = static_cast<uint8_t>(crc >> (8 * k));
  return total;
}

FrameDecoder::FrameDecoder(uint8_t* buffer, size_t capacity, uint16_t max_payload)
    : buf_(buffer), capacity_(capacity), max_payload_(max_payload) {
  if (capacity_ < size_t{max_payload_} + kFrameOverhead)
    max_payload_ =
        capacity_ > kFrameOverhead ? static_cast<uint16_t>(capacity_ - kFrameOverhead) : 0;
}

void FrameDecoder::compact() {
  size_t drop = consumed_;
  consumed_ = 0;
  while (drop < have_ && buf_[drop] != kFrameStart) ++drop;
  for (size_t i = drop; i < have_; ++i) buf_[i - drop] = buf_[i];
  have_ -= drop;
}

FrameDecoder::Event FrameDecoder::push(uint8_t byte) {
  compact();
  if (have_ == 0 && byte != kFrameStart) return Event::kNone;  // hunting for a start byte
  buf_[have_++] = byte;
  return scan();
}

FrameDecoder::Event FrameDecoder::poll() {
  compact();
  return scan();
}

FrameDecoder::Event FrameDecoder::scan() {
  {
    if (have_ < 3) return Event::kNone;
    const uint16_t n = static_cast<uint16_t>(buf_[1] | (buf_[2] << 8));
    bool bad = n > max_payload_;
    if (!bad) {
      const size_t total = size_t{n} + kFrameOverhead;
      if (have_ < total) return Event::kNone;
      uint32_t got = 0;
      for (int k = 0; k < 4; ++k) got |= uint32_t{buf_[5 + n + k]} << (8 * k);
      if (crc32(buf_ + 3, size_t{n} + 2) == got) {
        frame_ = Frame{buf_[3], buf_[4], buf_ + 5, n};
        consumed_ = total;  // dropped on the next call, so the payload stays valid until then
        return Event::kFrame;
      }
      bad = true;
    }
    return reject();
  }
}

FrameDecoder::Event FrameDecoder::reject() {
  // A false or damaged start: drop it and rescan what we have from the next start byte.
  ++bad_frames_;
  size_t next = 1;
  while (next < have_ && buf_[next] != kFrameStart) ++next;
  for (size_t i = next; i < have_; ++i) buf_[i - next] = buf_[i];
  have_ -= next;
  if (scan() == Event::kFrame) return Event::kFrame;  // a real frame was hiding inside
  return Event::kBadFrame;
}

FrameDecoder::Event FrameDecoder::idle() {
  compact();
  if (have_ == 0) return Event::kNone;
  return reject();
}

}  // namespace haloplot
