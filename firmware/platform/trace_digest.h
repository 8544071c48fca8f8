// Test images: a step trace summed to its CRC-32 and length instead of sent. A 45 MB trace over
// semihosting takes minutes under QEMU; the host compares the digest with its own trace's.
#pragma once
#include <stdint.h>

#include "haloplot/protocol/crc32.h"
#include "haloplot/trace/trace_encoder.h"

namespace haloplot::fw {

struct TraceDigest {
  uint32_t crc = 0;
  uint64_t bytes = 0;
  static void write(void* ctx, const char* text, uint32_t n) {
    auto* self = static_cast<TraceDigest*>(ctx);
    self->crc = crc32_update(self->crc, reinterpret_cast<const uint8_t*>(text), n);
    self->bytes += n;
  }
  CharSink sink() { return CharSink{&TraceDigest::write, this}; }
};

}  // namespace haloplot::fw
