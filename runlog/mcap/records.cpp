#include "runlog/mcap/records.hpp"

#include <cstring>
#include <stdexcept>

namespace robozoo::mcap {

namespace {

template <class T>
void put(Bytes& out, T value) {
  for (size_t i = 0; i < sizeof(T); ++i) out.push_back(static_cast<uint8_t>(static_cast<uint64_t>(value) >> (8 * i)));
}

void put_u32_at(Bytes& out, size_t at, uint64_t value) {
  if (value > 0xFFFFFFFFull) throw std::length_error("mcap: a field is longer than 4 GiB");
  for (size_t i = 0; i < 4; ++i) out[at + i] = static_cast<uint8_t>(value >> (8 * i));
}

void put_string(Bytes& out, const std::string& s) {
  if (s.size() > 0xFFFFFFFFull) throw std::length_error("mcap: a string is longer than 4 GiB");
  put<uint32_t>(out, static_cast<uint32_t>(s.size()));
  out.insert(out.end(), s.begin(), s.end());
}

/// Opens a uint32 byte-length prefix (maps, arrays); close_prefix fills it in.
size_t open_prefix(Bytes& out) {
  const size_t at = out.size();
  put<uint32_t>(out, 0);
  return at;
}
void close_prefix(Bytes& out, size_t at) { put_u32_at(out, at, out.size() - at - 4); }

/// Writes the opcode and a length placeholder; returns where the content starts.
size_t open_record(Bytes& out, Opcode op) {
  out.push_back(static_cast<uint8_t>(op));
  put<uint64_t>(out, 0);
  return out.size();
}
void close_record(Bytes& out, size_t content_start) {
  const uint64_t length = out.size() - content_start;
  for (size_t i = 0; i < 8; ++i) out[content_start - 8 + i] = static_cast<uint8_t>(length >> (8 * i));
}

}  // namespace

void append(Bytes& out, const Header& r) {
  const size_t c = open_record(out, Opcode::Header);
  put_string(out, r.profile);
  put_string(out, r.library);
  close_record(out, c);
}

void append(Bytes& out, const Footer& r) {
  const size_t c = open_record(out, Opcode::Footer);
  put<uint64_t>(out, r.summary_start);
  put<uint64_t>(out, r.summary_offset_start);
  put<uint32_t>(out, r.summary_crc);
  close_record(out, c);
}

void append(Bytes& out, const Schema& r) {
  const size_t c = open_record(out, Opcode::Schema);
  put<uint16_t>(out, r.id);
  put_string(out, r.name);
  put_string(out, r.encoding);
  put_string(out, r.data);
  close_record(out, c);
}

void append(Bytes& out, const Channel& r) {
  const size_t c = open_record(out, Opcode::Channel);
  put<uint16_t>(out, r.id);
  put<uint16_t>(out, r.schema_id);
  put_string(out, r.topic);
  put_string(out, r.message_encoding);
  const size_t m = open_prefix(out);
  for (const auto& [key, value] : r.metadata) {
    put_string(out, key);
    put_string(out, value);
  }
  close_prefix(out, m);
  close_record(out, c);
}

void append(Bytes& out, const Message& r) {
  const size_t c = open_record(out, Opcode::Message);
  put<uint16_t>(out, r.channel_id);
  put<uint32_t>(out, r.sequence);
  put<uint64_t>(out, r.log_time);
  put<uint64_t>(out, r.publish_time);
  out.insert(out.end(), r.data.begin(), r.data.end());
  close_record(out, c);
}

void append(Bytes& out, const Chunk& r) {
  const size_t c = open_record(out, Opcode::Chunk);
  put<uint64_t>(out, r.message_start_time);
  put<uint64_t>(out, r.message_end_time);
  put<uint64_t>(out, r.uncompressed_size);
  put<uint32_t>(out, r.uncompressed_crc);
  put_string(out, r.compression);
  put<uint64_t>(out, r.records.size());
  out.insert(out.end(), r.records.begin(), r.records.end());
  close_record(out, c);
}

void append(Bytes& out, const MessageIndex& r) {
  const size_t c = open_record(out, Opcode::MessageIndex);
  put<uint16_t>(out, r.channel_id);
  const size_t a = open_prefix(out);
  for (const auto& [time, offset] : r.records) {
    put<uint64_t>(out, time);
    put<uint64_t>(out, offset);
  }
  close_prefix(out, a);
  close_record(out, c);
}

void append(Bytes& out, const ChunkIndex& r) {
  const size_t c = open_record(out, Opcode::ChunkIndex);
  put<uint64_t>(out, r.message_start_time);
  put<uint64_t>(out, r.message_end_time);
  put<uint64_t>(out, r.chunk_start_offset);
  put<uint64_t>(out, r.chunk_length);
  const size_t m = open_prefix(out);
  for (const auto& [channel, offset] : r.message_index_offsets) {
    put<uint16_t>(out, channel);
    put<uint64_t>(out, offset);
  }
  close_prefix(out, m);
  put<uint64_t>(out, r.message_index_length);
  put_string(out, r.compression);
  put<uint64_t>(out, r.compressed_size);
  put<uint64_t>(out, r.uncompressed_size);
  close_record(out, c);
}

void append(Bytes& out, const Statistics& r) {
  const size_t c = open_record(out, Opcode::Statistics);
  put<uint64_t>(out, r.message_count);
  put<uint16_t>(out, r.schema_count);
  put<uint32_t>(out, r.channel_count);
  put<uint32_t>(out, r.attachment_count);
  put<uint32_t>(out, r.metadata_count);
  put<uint32_t>(out, r.chunk_count);
  put<uint64_t>(out, r.message_start_time);
  put<uint64_t>(out, r.message_end_time);
  const size_t m = open_prefix(out);
  for (const auto& [channel, count] : r.channel_message_counts) {
    put<uint16_t>(out, channel);
    put<uint64_t>(out, count);
  }
  close_prefix(out, m);
  close_record(out, c);
}

void append(Bytes& out, const SummaryOffset& r) {
  const size_t c = open_record(out, Opcode::SummaryOffset);
  out.push_back(static_cast<uint8_t>(r.group_opcode));
  put<uint64_t>(out, r.group_start);
  put<uint64_t>(out, r.group_length);
  close_record(out, c);
}

void append(Bytes& out, const DataEnd& r) {
  const size_t c = open_record(out, Opcode::DataEnd);
  put<uint32_t>(out, r.data_section_crc);
  close_record(out, c);
}

}  // namespace robozoo::mcap
