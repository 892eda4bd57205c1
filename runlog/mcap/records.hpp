#pragma once
// MCAP records (https://mcap.dev/spec, version 0) and their bytes: every
// record is an opcode (uint8), the content's length (uint64) and the content,
// all integers little-endian; strings and byte blobs carry a uint32 length,
// maps and arrays a uint32 length in bytes of their entries.
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace robozoo::mcap {

/// The 8 bytes that open and close every MCAP file.
inline constexpr uint8_t kMagic[8] = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};

enum class Opcode : uint8_t {
  Header = 0x01,
  Footer = 0x02,
  Schema = 0x03,
  Channel = 0x04,
  Message = 0x05,
  Chunk = 0x06,
  MessageIndex = 0x07,
  ChunkIndex = 0x08,
  Statistics = 0x0B,
  SummaryOffset = 0x0E,
  DataEnd = 0x0F,
};

using Bytes = std::vector<uint8_t>;

struct Header {
  std::string profile;  ///< "" : no ROS profile
  std::string library;  ///< who wrote the file
};

struct Footer {
  uint64_t summary_start = 0;         ///< byte offset of the summary section (0: none)
  uint64_t summary_offset_start = 0;  ///< byte offset of the summary offset section (0: none)
  uint32_t summary_crc = 0;           ///< CRC of summary start .. summary_offset_start field
};

struct Schema {
  uint16_t id = 0;  ///< 1.. (0 means "no schema")
  std::string name;
  std::string encoding;  ///< "jsonschema" here
  std::string data;      ///< the schema text
};

struct Channel {
  uint16_t id = 0;
  uint16_t schema_id = 0;
  std::string topic;
  std::string message_encoding;  ///< "json" here
  std::map<std::string, std::string> metadata;
};

struct Message {
  uint16_t channel_id = 0;
  uint32_t sequence = 0;
  uint64_t log_time = 0;      ///< ns
  uint64_t publish_time = 0;  ///< ns
  std::string data;
};

struct Chunk {
  uint64_t message_start_time = 0;  ///< ns, earliest log_time in the chunk
  uint64_t message_end_time = 0;    ///< ns, latest log_time in the chunk
  uint64_t uncompressed_size = 0;   ///< bytes of the records before compression
  uint32_t uncompressed_crc = 0;    ///< CRC of the records before compression
  std::string compression;          ///< "zstd", "lz4" or "" (none)
  Bytes records;                    ///< the records, compressed
};

struct MessageIndex {
  uint16_t channel_id = 0;
  /// (log_time ns, offset of the message record inside the uncompressed chunk records)
  std::vector<std::pair<uint64_t, uint64_t>> records;
};

struct ChunkIndex {
  uint64_t message_start_time = 0;
  uint64_t message_end_time = 0;
  uint64_t chunk_start_offset = 0;                     ///< file offset of the chunk record's opcode
  uint64_t chunk_length = 0;                           ///< bytes of the whole chunk record
  std::map<uint16_t, uint64_t> message_index_offsets;  ///< channel -> file offset of its message index
  uint64_t message_index_length = 0;                   ///< bytes of the message index records after the chunk
  std::string compression;
  uint64_t compressed_size = 0;
  uint64_t uncompressed_size = 0;
};

struct Statistics {
  uint64_t message_count = 0;
  uint16_t schema_count = 0;
  uint32_t channel_count = 0;
  uint32_t attachment_count = 0;
  uint32_t metadata_count = 0;
  uint32_t chunk_count = 0;
  uint64_t message_start_time = 0;
  uint64_t message_end_time = 0;
  std::map<uint16_t, uint64_t> channel_message_counts;
};

struct SummaryOffset {
  Opcode group_opcode = Opcode::Schema;
  uint64_t group_start = 0;   ///< file offset of the group's first record
  uint64_t group_length = 0;  ///< bytes of the group
};

struct DataEnd {
  uint32_t data_section_crc = 0;  ///< CRC of the file from its first byte up to this record
};

/// Each appends the whole record (opcode, length, content) to `out`.
void append(Bytes& out, const Header& r);
void append(Bytes& out, const Footer& r);
void append(Bytes& out, const Schema& r);
void append(Bytes& out, const Channel& r);
void append(Bytes& out, const Message& r);
void append(Bytes& out, const Chunk& r);
void append(Bytes& out, const MessageIndex& r);
void append(Bytes& out, const ChunkIndex& r);
void append(Bytes& out, const Statistics& r);
void append(Bytes& out, const SummaryOffset& r);
void append(Bytes& out, const DataEnd& r);

/// Bytes a Footer record takes (opcode + length + 20 content bytes).
inline constexpr uint64_t kFooterRecordBytes = 1 + 8 + 8 + 8 + 4;

}  // namespace robozoo::mcap
