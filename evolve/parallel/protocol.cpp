#include "evolve/parallel/protocol.hpp"

#include <algorithm>
#include <array>
#include <limits>

namespace robozoo {
namespace {

constexpr uint8_t kMagic[4] = {0x52, 0x5A, 0x57, 0x50};  // "RZWP"

void put_u32(uint8_t* p, uint32_t v) {
  for (int i = 0; i < 4; ++i) p[i] = static_cast<uint8_t>(v >> (8 * i));
}
void put_u64(uint8_t* p, uint64_t v) {
  for (int i = 0; i < 8; ++i) p[i] = static_cast<uint8_t>(v >> (8 * i));
}
uint32_t get_u32(const uint8_t* p) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= static_cast<uint32_t>(p[i]) << (8 * i);
  return v;
}
uint64_t get_u64(const uint8_t* p) {
  uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v |= static_cast<uint64_t>(p[i]) << (8 * i);
  return v;
}

bool known_kind(uint8_t k) {
  return k >= static_cast<uint8_t>(FrameKind::Job) && k <= static_cast<uint8_t>(FrameKind::Shutdown);
}

const char* kind_name(FrameKind k) {
  switch (k) {
    case FrameKind::Job: return "Job";
    case FrameKind::Result: return "Result";
    case FrameKind::Failure: return "Failure";
    case FrameKind::Shutdown: return "Shutdown";
  }
  return "unknown";
}

/// Checks a complete header; returns the body length.
uint32_t check_header(const uint8_t* h, uint32_t max_body_bytes) {
  for (int i = 0; i < 4; ++i)
    if (h[i] != kMagic[i]) throw ProtocolError("worker protocol: bad magic (stream out of sync)");
  if (h[4] != kProtocolVersion)
    throw ProtocolError("worker protocol: version " + std::to_string(h[4]) + ", expected " +
                        std::to_string(kProtocolVersion));
  if (!known_kind(h[5])) throw ProtocolError("worker protocol: unknown frame kind " + std::to_string(h[5]));
  if (h[6] != 0 || h[7] != 0) throw ProtocolError("worker protocol: reserved bytes not zero");
  const uint32_t n = get_u32(h + 16);
  if (get_u32(h + 20) != ~n) throw ProtocolError("worker protocol: body length and its complement disagree");
  if (n > max_body_bytes)
    throw ProtocolError("worker protocol: body of " + std::to_string(n) + " bytes exceeds the limit of " +
                        std::to_string(max_body_bytes));
  if (static_cast<FrameKind>(h[5]) == FrameKind::Shutdown && (n != 0 || get_u64(h + 8) != 0))
    throw ProtocolError("worker protocol: Shutdown frame with a body or an index");
  return n;
}

}  // namespace

Bytes encode_frame(const Frame& frame) {
  if (!known_kind(static_cast<uint8_t>(frame.kind))) throw std::invalid_argument("encode_frame: unknown frame kind");
  if (frame.body.size() > std::numeric_limits<uint32_t>::max())
    throw std::invalid_argument("encode_frame: body of " + std::to_string(frame.body.size()) +
                                " bytes does not fit the 32-bit length field");
  if (frame.kind == FrameKind::Shutdown && (!frame.body.empty() || frame.index != 0))
    throw std::invalid_argument("encode_frame: a Shutdown frame carries no body and no index");
  const uint32_t n = static_cast<uint32_t>(frame.body.size());
  Bytes out(kFrameHeaderBytes + n + kFrameTrailerBytes);
  uint8_t* p = out.data();
  for (int i = 0; i < 4; ++i) p[i] = kMagic[i];
  p[4] = kProtocolVersion;
  p[5] = static_cast<uint8_t>(frame.kind);
  p[6] = p[7] = 0;
  put_u64(p + 8, frame.index);
  put_u32(p + 16, n);
  put_u32(p + 20, ~n);
  if (n) std::copy(frame.body.begin(), frame.body.end(), p + kFrameHeaderBytes);
  put_u32(p + kFrameHeaderBytes + n, crc32(p, kFrameHeaderBytes + n));
  return out;
}

Bytes encode_job(const Job& job) { return encode_frame({FrameKind::Job, job.index, job.payload}); }

Bytes encode_result(const Result& result) {
  if (result.ok) return encode_frame({FrameKind::Result, result.index, result.payload});
  return encode_frame({FrameKind::Failure, result.index, Bytes(result.error.begin(), result.error.end())});
}

Bytes encode_shutdown() { return encode_frame({FrameKind::Shutdown, 0, {}}); }

DecodeStep decode_frame(const uint8_t* data, size_t size, uint32_t max_body_bytes) {
  DecodeStep step;
  if (size < kFrameHeaderBytes) {
    // Check what has arrived of the magic already: a stream out of sync fails early.
    for (size_t i = 0; i < size && i < 4; ++i)
      if (data[i] != kMagic[i]) throw ProtocolError("worker protocol: bad magic (stream out of sync)");
    return step;
  }
  const uint32_t n = check_header(data, max_body_bytes);
  const size_t total = kFrameHeaderBytes + static_cast<size_t>(n) + kFrameTrailerBytes;
  if (size < total) return step;
  const uint32_t want = get_u32(data + kFrameHeaderBytes + n);
  if (crc32(data, kFrameHeaderBytes + n) != want) throw ProtocolError("worker protocol: CRC mismatch");
  Frame f;
  f.kind = static_cast<FrameKind>(data[5]);
  f.index = get_u64(data + 8);
  f.body.assign(data + kFrameHeaderBytes, data + kFrameHeaderBytes + n);
  step.frame = std::move(f);
  step.consumed = total;
  return step;
}

Frame decode_message(const Bytes& message, uint32_t max_body_bytes) {
  DecodeStep step = decode_frame(message.data(), message.size(), max_body_bytes);
  if (!step.frame)
    throw ProtocolError("worker protocol: truncated message (" + std::to_string(message.size()) + " bytes)");
  if (step.consumed != message.size())
    throw ProtocolError("worker protocol: " + std::to_string(message.size() - step.consumed) +
                        " bytes after the frame");
  return std::move(*step.frame);
}

Job job_from_frame(Frame frame) {
  if (frame.kind != FrameKind::Job)
    throw ProtocolError(std::string("worker protocol: expected a Job frame, got ") + kind_name(frame.kind));
  return Job{frame.index, std::move(frame.body)};
}

Result result_from_frame(Frame frame) {
  Result r;
  r.index = frame.index;
  if (frame.kind == FrameKind::Result) {
    r.ok = true;
    r.payload = std::move(frame.body);
  } else if (frame.kind == FrameKind::Failure) {
    r.ok = false;
    r.error.assign(frame.body.begin(), frame.body.end());
  } else {
    throw ProtocolError(std::string("worker protocol: expected a Result or Failure frame, got ") +
                        kind_name(frame.kind));
  }
  return r;
}

void FrameReader::feed(const uint8_t* data, size_t size) {
  if (start_ > 0 && start_ >= buffer_.size() / 2) {  // compact: drop consumed bytes
    buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(start_));
    start_ = 0;
  }
  buffer_.insert(buffer_.end(), data, data + size);
}

std::optional<Frame> FrameReader::next() {
  if (failed_) throw ProtocolError("worker protocol: stream already failed");
  DecodeStep step;
  try {
    step = decode_frame(buffer_.data() + start_, buffer_.size() - start_, max_body_bytes_);
  } catch (const ProtocolError&) {
    failed_ = true;
    throw;
  }
  if (!step.frame) return std::nullopt;
  start_ += step.consumed;
  if (start_ == buffer_.size()) {
    buffer_.clear();
    start_ = 0;
  }
  return std::move(step.frame);
}

}  // namespace robozoo
