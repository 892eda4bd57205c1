#pragma once
// CRC-32 (IEEE 802.3: reflected polynomial 0xEDB88320, initial and final xor
// 0xFFFFFFFF), the checksum of the worker protocol's frames and of MCAP files.
// zlib computes it; this header keeps zlib out of the callers.
#include <cstddef>
#include <cstdint>

namespace robozoo {

/// The CRC of the bytes seen so far (`crc`, 0 for none) extended by `size` bytes
/// at `data`: crc32(b, nb, crc32(a, na)) is the CRC of a followed by b.
uint32_t crc32(const void* data, size_t size, uint32_t crc = 0);

}  // namespace robozoo
