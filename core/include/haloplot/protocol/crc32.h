// CRC-32 (IEEE 802.3: reflected, polynomial 0xEDB88320, initial and final XOR 0xFFFFFFFF), as
// zlib and Ethernet compute it. A 16-entry nibble table: 64 bytes of flash, two lookups a byte.
#pragma once
#include <stddef.h>
#include <stdint.h>

namespace haloplot {

uint32_t crc32_update(uint32_t crc, const uint8_t* data, size_t n);  // start with 0
inline uint32_t crc32(const uint8_t* data, size_t n) { return crc32_update(0, data, n); }

}  // namespace haloplot
