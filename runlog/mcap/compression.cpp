#include "runlog/mcap/compression.hpp"

#include <lz4frame.h>
#include <zstd.h>

#include <stdexcept>

namespace robozoo::mcap {

namespace {

constexpr int kZstdLevel = 3;  // libzstd's default level

}  // namespace

std::string compression_name(Compression c) {
  switch (c) {
    case Compression::Zstd: return "zstd";
    case Compression::Lz4: return "lz4";
    case Compression::None: break;
  }
  return "";
}

Compression parse_compression(const std::string& value) {
  if (value == "none") return Compression::None;
  if (value == "zstd") return Compression::Zstd;
  if (value == "lz4") return Compression::Lz4;
  throw std::invalid_argument("unknown compression '" + value + "' (zstd, lz4 or none)");
}

Bytes compress(Compression c, const Bytes& data) {
  if (c == Compression::None) return data;
  Bytes out;
  if (c == Compression::Zstd) {
    out.resize(ZSTD_compressBound(data.size()));
    const size_t n = ZSTD_compress(out.data(), out.size(), data.data(), data.size(), kZstdLevel);
    if (ZSTD_isError(n)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(n));
    out.resize(n);
    return out;
  }
  LZ4F_preferences_t prefs{};
  prefs.frameInfo.contentSize = data.size();
  out.resize(LZ4F_compressFrameBound(data.size(), &prefs));
  const size_t n = LZ4F_compressFrame(out.data(), out.size(), data.data(), data.size(), &prefs);
  if (LZ4F_isError(n)) throw std::runtime_error(std::string("lz4: ") + LZ4F_getErrorName(n));
  out.resize(n);
  return out;
}

Bytes decompress(Compression c, const Bytes& data, size_t uncompressed_size) {
  if (c == Compression::None) {
    if (data.size() != uncompressed_size) throw std::runtime_error("uncompressed chunk of the wrong size");
    return data;
  }
  Bytes out(uncompressed_size);
  if (c == Compression::Zstd) {
    const size_t n = ZSTD_decompress(out.data(), out.size(), data.data(), data.size());
    if (ZSTD_isError(n)) throw std::runtime_error(std::string("zstd: ") + ZSTD_getErrorName(n));
    if (n != uncompressed_size) throw std::runtime_error("zstd: chunk of the wrong size");
    return out;
  }
  LZ4F_dctx* ctx = nullptr;
  if (LZ4F_isError(LZ4F_createDecompressionContext(&ctx, LZ4F_VERSION))) throw std::runtime_error("lz4: no context");
  size_t written = 0, read = 0;
  size_t status = 1;
  while (status != 0 && read < data.size()) {
    size_t dst = out.size() - written, src = data.size() - read;
    status = LZ4F_decompress(ctx, out.data() + written, &dst, data.data() + read, &src, nullptr);
    if (LZ4F_isError(status)) {
      LZ4F_freeDecompressionContext(ctx);
      throw std::runtime_error(std::string("lz4: ") + LZ4F_getErrorName(status));
    }
    written += dst;
    read += src;
    if (dst == 0 && src == 0) break;
  }
  LZ4F_freeDecompressionContext(ctx);
  if (status != 0 || written != uncompressed_size) throw std::runtime_error("lz4: chunk of the wrong size");
  return out;
}

}  // namespace robozoo::mcap
