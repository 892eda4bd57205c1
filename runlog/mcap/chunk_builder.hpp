#pragma once
// One MCAP chunk being filled: message records appended to the uncompressed
// records, with each channel's message index (log time, offset inside the
// records) and the chunk's time span, until the writer closes it.
#include <cstdint>
#include <map>

#include "runlog/mcap/compression.hpp"
#include "runlog/mcap/records.hpp"

namespace robozoo::mcap {

class ChunkBuilder {
 public:
  void add(const Message& m);
  bool empty() const { return records_.empty(); }
  size_t uncompressed_bytes() const { return records_.size(); }

  /// The chunk record (records compressed, CRC of the uncompressed ones) and
  /// its message indexes, one per channel in channel order; then empties itself.
  Chunk finish(Compression c, std::map<uint16_t, MessageIndex>& indexes);

 private:
  Bytes records_;
  std::map<uint16_t, MessageIndex> indexes_;
  uint64_t start_ = 0, end_ = 0;
};

}  // namespace robozoo::mcap
