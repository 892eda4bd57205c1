#include "runlog/mcap/writer.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "evolve/io/crc32.hpp"

namespace robozoo::mcap {

Writer::Writer(const std::string& path, const WriterOptions& options)
    : path_(path), partial_(path + ".partial"), options_(options) {
  file_ = std::fopen(partial_.c_str(), "wb");
  if (!file_) throw std::runtime_error(partial_ + ": cannot create: " + std::strerror(errno));
  Bytes head(std::begin(kMagic), std::end(kMagic));
  append(head, Header{"", options_.library});
  emit(head);
}

Writer::~Writer() {
  if (file_) {
    std::fclose(file_);
    std::remove(partial_.c_str());
  }
}

void Writer::emit(const Bytes& bytes) {
  if (bytes.empty()) return;
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size())
    throw std::runtime_error(partial_ + ": write failed: " + std::strerror(errno));
  if (in_data_) data_crc_ = crc32(bytes.data(), bytes.size(), data_crc_);
  offset_ += bytes.size();
}

uint16_t Writer::add_schema(const std::string& name, const std::string& encoding, const std::string& data) {
  if (schemas_.size() >= 0xFFFE) throw std::length_error("mcap: too many schemas");
  Schema s{static_cast<uint16_t>(schemas_.size() + 1), name, encoding, data};
  Bytes b;
  append(b, s);
  emit(b);
  schemas_.push_back(std::move(s));
  return schemas_.back().id;
}

uint16_t Writer::add_channel(const std::string& topic, const std::string& message_encoding, uint16_t schema_id) {
  if (channels_.size() >= 0xFFFF) throw std::length_error("mcap: too many channels");
  if (schema_id == 0 || schema_id > schemas_.size()) throw std::invalid_argument("mcap: unknown schema id");
  Channel c{static_cast<uint16_t>(channels_.size()), schema_id, topic, message_encoding, {}};
  Bytes b;
  append(b, c);
  emit(b);
  channels_.push_back(std::move(c));
  return channels_.back().id;
}

void Writer::write(uint16_t channel_id, uint64_t log_time_ns, uint64_t publish_time_ns, const std::string& data) {
  if (channel_id >= channels_.size()) throw std::invalid_argument("mcap: unknown channel id");
  Message m{channel_id, sequence_[channel_id]++, log_time_ns, publish_time_ns, data};
  chunk_.add(m);
  if (stats_.message_count == 0) {
    stats_.message_start_time = stats_.message_end_time = log_time_ns;
  } else {
    stats_.message_start_time = std::min(stats_.message_start_time, log_time_ns);
    stats_.message_end_time = std::max(stats_.message_end_time, log_time_ns);
  }
  ++stats_.message_count;
  ++stats_.channel_message_counts[channel_id];
  if (chunk_.uncompressed_bytes() >= options_.chunk_bytes) flush_chunk();
}

void Writer::flush_chunk() {
  if (chunk_.empty()) return;
  std::map<uint16_t, MessageIndex> indexes;
  const Chunk chunk = chunk_.finish(options_.compression, indexes);
  ChunkIndex ci;
  ci.message_start_time = chunk.message_start_time;
  ci.message_end_time = chunk.message_end_time;
  ci.chunk_start_offset = offset_;
  ci.compression = chunk.compression;
  ci.compressed_size = chunk.records.size();
  ci.uncompressed_size = chunk.uncompressed_size;
  Bytes b;
  append(b, chunk);
  ci.chunk_length = b.size();
  emit(b);
  const uint64_t index_start = offset_;
  for (const auto& [channel, index] : indexes) {
    ci.message_index_offsets[channel] = offset_;
    Bytes ib;
    append(ib, index);
    emit(ib);
  }
  ci.message_index_length = offset_ - index_start;
  chunk_indexes_.push_back(std::move(ci));
  ++stats_.chunk_count;
}

void Writer::close() {
  if (!file_) throw std::logic_error("mcap: writer already closed");
  flush_chunk();
  Bytes b;
  append(b, DataEnd{data_crc_});
  emit(b);
  in_data_ = false;

  // Summary: one group per record kind, each noted in the summary offsets.
  const uint64_t summary_start = offset_;
  uint32_t summary_crc = 0;
  std::vector<SummaryOffset> groups;
  auto group = [&](Opcode op, const Bytes& bytes) {
    if (bytes.empty()) return;
    groups.push_back({op, offset_, bytes.size()});
    summary_crc = crc32(bytes.data(), bytes.size(), summary_crc);
    emit(bytes);
  };
  Bytes g;
  for (const Schema& s : schemas_) append(g, s);
  group(Opcode::Schema, g);
  g.clear();
  for (const Channel& c : channels_) append(g, c);
  group(Opcode::Channel, g);
  g.clear();
  stats_.schema_count = static_cast<uint16_t>(schemas_.size());
  stats_.channel_count = static_cast<uint32_t>(channels_.size());
  append(g, stats_);
  group(Opcode::Statistics, g);
  g.clear();
  for (const ChunkIndex& ci : chunk_indexes_) append(g, ci);
  group(Opcode::ChunkIndex, g);

  const uint64_t summary_offset_start = offset_;
  Bytes offsets;
  for (const SummaryOffset& so : groups) append(offsets, so);
  summary_crc = crc32(offsets.data(), offsets.size(), summary_crc);
  emit(offsets);

  // The summary CRC runs on through the footer's opcode, length and two offsets.
  Bytes footer;
  append(footer, Footer{summary_start, summary_offset_start, 0});
  summary_crc = crc32(footer.data(), footer.size() - 4, summary_crc);
  footer.resize(footer.size() - 4);
  for (size_t i = 0; i < 4; ++i) footer.push_back(static_cast<uint8_t>(summary_crc >> (8 * i)));
  footer.insert(footer.end(), std::begin(kMagic), std::end(kMagic));
  emit(footer);

  const bool flushed = std::fflush(file_) == 0;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!flushed || !closed) {
    std::remove(partial_.c_str());
    throw std::runtime_error(partial_ + ": write failed: " + std::strerror(errno));
  }
  if (std::rename(partial_.c_str(), path_.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(partial_.c_str());
    throw std::runtime_error(path_ + ": cannot rename " + partial_ + " to it: " + why);
  }
}

}  // namespace robozoo::mcap
