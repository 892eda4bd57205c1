#pragma once
// CRC-32 (IEEE 802.3, reflected polynomial 0xEDB88320, the one zlib and MCAP
// use), computed incrementally: crc32_update(crc32_update(0, a), b) equals the
// CRC of a followed by b.
#include <cstddef>
#include <cstdint>

namespace robozoo::mcap {

/// The CRC of the bytes seen so far (`crc`, 0 for none) extended by `data`.
uint32_t crc32_update(uint32_t crc, const void* data, size_t size);

}  // namespace robozoo::mcap
