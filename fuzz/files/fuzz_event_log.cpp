// libFuzzer target: the event-log reader (parse_event_log, which
// read_event_log runs on a mapped file) and the log comparison on what it reads.
#include "evolve/io/log_compare.hpp"
#include "fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace robozoo;
  const LogContents log = parse_event_log(data, size);
  int64_t bytes = 0;
  for (const auto& r : log.records) bytes += 28 + int64_t(r.channel.size()) + int64_t(r.data.size());
  if (bytes != log.event_bytes || log.event_bytes > log.file_bytes || log.file_bytes != int64_t(size) ||
      log.truncated != (log.event_bytes != log.file_bytes))
    fuzz::violated("the log's byte counts do not add up");
  // A log equals itself exactly when every message on a known robozoo channel decodes.
  bool all_decode = true;
  for (const auto& r : log.records) {
    std::vector<uint8_t> norm;
    if (is_known_channel(r.channel) && !normalize_message(r.channel, r.data, norm)) all_decode = false;
  }
  if (first_log_difference(log, log).empty() != all_decode)
    fuzz::violated("a log compares equal to itself although a message does not decode, or the reverse");
  return 0;
}
