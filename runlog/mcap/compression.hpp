#pragma once
// Compression of MCAP chunks: zstd (libzstd) or lz4 frames (liblz4), as the
// MCAP spec names them, or none.
#include <string>

#include "runlog/mcap/records.hpp"

namespace robozoo::mcap {

enum class Compression { None, Zstd, Lz4 };

/// The spec's name of a compression: "", "zstd", "lz4".
std::string compression_name(Compression c);

/// "none", "zstd" or "lz4" (command-line values); throws std::invalid_argument otherwise.
Compression parse_compression(const std::string& value);

/// `data` compressed (a copy when None). Throws std::runtime_error if the library fails.
Bytes compress(Compression c, const Bytes& data);

/// The inverse of compress, given the size before compression (tests, readers).
/// Throws std::runtime_error on damaged input or a size that does not match.
Bytes decompress(Compression c, const Bytes& data, size_t uncompressed_size);

}  // namespace robozoo::mcap
