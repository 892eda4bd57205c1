#pragma once
// The worker protocol: plain byte messages between the pool (the parent, or MPI
// rank 0) and its workers, independent of the transport that carries them.
//
// A job is (job index, payload bytes); a result is (job index, payload bytes) or
// (job index, error text). Payloads are opaque to the pool. Every message travels
// as one frame, little-endian, fixed widths:
//
//   offset  size  field
//   0       4     magic "RZWP" (0x52 0x5A 0x57 0x50): detects a stream out of sync
//   4       1     protocol version (kProtocolVersion)
//   5       1     kind (FrameKind)
//   6       2     reserved, must be 0
//   8       8     job index (u64; 0 for Shutdown)
//   16      4     body length n (u32)
//   20      4     ~n, the bitwise complement of n: a damaged length is caught
//                 before anything is allocated or waited for
//   24      n     body: the payload (Job, Result) or the error text (Failure)
//   24+n    4     CRC-32 (IEEE 802.3, as zlib's crc32) of bytes [0, 24+n)
//
// A frame whose fields do not check out (magic, version, kind, reserved bits,
// length vs its complement, length above the reader's limit, a body on Shutdown,
// CRC) is a ProtocolError, never trusted. There is no resynchronisation: a stream
// that carried one bad frame is dropped (the pipe transport replaces its worker).
//
// Encoding and decoding are pure functions; FrameReader adds the buffering needed
// to cut frames out of a byte stream (pipes, sockets). A message-based transport
// (MPI) sends one encoded frame per message and decodes it with decode_message.
#include "evolve/io/crc32.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace robozoo {

using Bytes = std::vector<uint8_t>;

inline constexpr uint8_t kProtocolVersion = 1;
inline constexpr size_t kFrameHeaderBytes = 24;  ///< bytes before the body
inline constexpr size_t kFrameTrailerBytes = 4;  ///< CRC-32 after the body
/// Default cap on a body a reader accepts (bytes). Robots' genomes and results are
/// kilobytes; the cap only stops a corrupted length from allocating gigabytes.
inline constexpr uint32_t kDefaultMaxBodyBytes = 1u << 30;

/// A frame that cannot be trusted: bad magic, version, kind, sizes or checksum.
class ProtocolError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class FrameKind : uint8_t {
  Job = 1,       ///< pool -> worker: evaluate the payload
  Result = 2,    ///< worker -> pool: the job's result payload
  Failure = 3,   ///< worker -> pool: the work function threw; body = error text
  Shutdown = 4,  ///< pool -> worker: exit (a stream transport may just close instead)
};

/// One decoded frame.
struct Frame {
  FrameKind kind = FrameKind::Job;
  uint64_t index = 0;  ///< job index (0 for Shutdown)
  Bytes body;          ///< payload or error text
};

struct Job {
  uint64_t index = 0;  ///< position of the job in the pool's map() call
  Bytes payload;
};

struct Result {
  uint64_t index = 0;  ///< the job's index
  bool ok = true;      ///< false: the work function failed, see error
  Bytes payload;       ///< the work function's output when ok
  std::string error;   ///< why it failed when !ok
};

/// Encodes a frame; throws std::invalid_argument if the body exceeds 4 GiB - 1 or
/// a Shutdown frame has a body.
Bytes encode_frame(const Frame& frame);
Bytes encode_job(const Job& job);
Bytes encode_result(const Result& result);
Bytes encode_shutdown();

/// Outcome of decoding the start of a byte buffer.
struct DecodeStep {
  std::optional<Frame> frame;  ///< empty: the buffer holds only part of a frame
  size_t consumed = 0;         ///< bytes of the buffer the frame took (0 when empty)
};

/// Decodes the frame at the start of data[0, size). Returns an empty step when more
/// bytes are needed (as soon as the header is complete it is checked, so a bad
/// header fails without waiting for its body). Throws ProtocolError on a bad frame.
DecodeStep decode_frame(const uint8_t* data, size_t size, uint32_t max_body_bytes = kDefaultMaxBodyBytes);

/// Decodes a buffer that must hold exactly one frame (message-based transports).
/// Throws ProtocolError if it is bad, truncated or followed by extra bytes.
Frame decode_message(const Bytes& message, uint32_t max_body_bytes = kDefaultMaxBodyBytes);

/// Interprets a frame; throws ProtocolError if its kind is not the expected one.
Job job_from_frame(Frame frame);
Result result_from_frame(Frame frame);  ///< accepts Result and Failure

/// Cuts frames out of a byte stream fed in arbitrary pieces.
class FrameReader {
 public:
  explicit FrameReader(uint32_t max_body_bytes = kDefaultMaxBodyBytes) : max_body_bytes_(max_body_bytes) {}

  void feed(const uint8_t* data, size_t size);
  /// The next complete frame, or empty if none is buffered yet. Throws ProtocolError
  /// on a bad frame; the reader is then unusable (no resynchronisation).
  std::optional<Frame> next();
  /// Bytes buffered that do not yet form a frame.
  size_t buffered() const { return buffer_.size() - start_; }
  /// Forgets everything buffered and any earlier error.
  void clear() {
    buffer_.clear();
    start_ = 0;
    failed_ = false;
  }

 private:
  uint32_t max_body_bytes_;
  bool failed_ = false;  ///< a bad frame was seen
  Bytes buffer_;
  size_t start_ = 0;  ///< first unread byte of buffer_
};

}  // namespace robozoo
