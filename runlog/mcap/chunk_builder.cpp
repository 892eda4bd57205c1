#include "runlog/mcap/chunk_builder.hpp"

#include <algorithm>

#include "evolve/io/crc32.hpp"

namespace robozoo::mcap {

void ChunkBuilder::add(const Message& m) {
  if (records_.empty()) {
    start_ = end_ = m.log_time;
  } else {
    start_ = std::min(start_, m.log_time);
    end_ = std::max(end_, m.log_time);
  }
  MessageIndex& index = indexes_[m.channel_id];
  index.channel_id = m.channel_id;
  index.records.emplace_back(m.log_time, records_.size());
  append(records_, m);
}

Chunk ChunkBuilder::finish(Compression c, std::map<uint16_t, MessageIndex>& indexes) {
  Chunk chunk;
  chunk.message_start_time = start_;
  chunk.message_end_time = end_;
  chunk.uncompressed_size = records_.size();
  chunk.uncompressed_crc = crc32(records_.data(), records_.size(), 0);
  chunk.compression = compression_name(c);
  chunk.records = compress(c, records_);
  indexes = std::move(indexes_);
  indexes_.clear();
  records_.clear();
  start_ = end_ = 0;
  return chunk;
}

}  // namespace robozoo::mcap
