#pragma once
// Writing an indexed, chunked MCAP file (https://mcap.dev/spec): magic,
// header, schemas and channels as they are added, messages in chunks of about
// `chunk_bytes` (each followed by its message indexes), data end with the CRC
// of the data section, then the summary (schemas, channels, statistics, chunk
// indexes), the summary offsets, the footer with the summary's CRC, magic.
// Memory stays bounded by one chunk plus the indexes. The file is written as
// PATH.partial and renamed to PATH by close(), so a failure never leaves a
// complete-looking file; a writer destroyed before close() removes it.
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "runlog/mcap/chunk_builder.hpp"
#include "runlog/mcap/compression.hpp"
#include "runlog/mcap/records.hpp"

namespace robozoo::mcap {

struct WriterOptions {
  Compression compression = Compression::Zstd;
  size_t chunk_bytes = 1 << 20;     ///< a chunk is closed once its uncompressed records reach this (bytes)
  std::string library = "robozoo";  ///< the header's library field
};

class Writer {
 public:
  /// Opens PATH.partial; throws std::runtime_error naming it when it cannot be created.
  Writer(const std::string& path, const WriterOptions& options);
  ~Writer();
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  /// Returns the new schema's id (1, 2, ...).
  uint16_t add_schema(const std::string& name, const std::string& encoding, const std::string& data);
  /// Returns the new channel's id (0, 1, ...).
  uint16_t add_channel(const std::string& topic, const std::string& message_encoding, uint16_t schema_id);
  /// Appends a message to the open chunk (sequence numbers count per channel).
  void write(uint16_t channel_id, uint64_t log_time_ns, uint64_t publish_time_ns, const std::string& data);
  /// Finishes the file and renames it to PATH. Throws std::runtime_error on a write error.
  void close();

  const Statistics& statistics() const { return stats_; }

 private:
  void emit(const Bytes& bytes);  // to the file, counting offset and data CRC
  void flush_chunk();

  std::string path_, partial_;
  WriterOptions options_;
  std::FILE* file_ = nullptr;
  uint64_t offset_ = 0;
  uint32_t data_crc_ = 0;
  bool in_data_ = true;
  std::vector<Schema> schemas_;
  std::vector<Channel> channels_;
  std::map<uint16_t, uint32_t> sequence_;
  std::vector<ChunkIndex> chunk_indexes_;
  ChunkBuilder chunk_;
  Statistics stats_;
};

}  // namespace robozoo::mcap
