#include "evolve/io/crc32.hpp"

#include <zlib.h>

namespace robozoo {

uint32_t crc32(const void* data, size_t size, uint32_t crc) {
  if (size == 0) return crc;  // zlib answers 0 for a null buffer, whatever `crc` was
  // crc32_z takes a z_size_t length, so sizes beyond 4 GiB need no splitting.
  return static_cast<uint32_t>(::crc32_z(crc, static_cast<const Bytef*>(data), static_cast<z_size_t>(size)));
}

}  // namespace robozoo
