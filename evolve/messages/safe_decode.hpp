#pragma once
// Decoding untrusted bytes (logs, the bus) into robozoo's LCM types safely.
//
// lcm-gen's decoders resize vectors to the counts they read before checking
// that the bytes are there, so a corrupt count can make them allocate
// gigabytes or throw. safe_decode first walks the wire layout of the type:
// every count must be >= 0 and every array must fit in the bytes left, and the
// message must end exactly at the end of the buffer; only then does it decode.
// An LCM callback uses this and never throws.
#include <cstddef>
#include <cstdint>
#include <string>

#include "robozoo/eval_result_t.hpp"
#include "robozoo/generation_t.hpp"
#include "robozoo/cppn_genome_t.hpp"
#include "robozoo/genome_t.hpp"
#include "robozoo/morphology_t.hpp"
#include "robozoo/pose_t.hpp"
#include "robozoo/bus_status_t.hpp"
#include "robozoo/run_t.hpp"

namespace robozoo {

/// The wire size the layout walk finds for a message of each type, or -1 with
/// `why` set when the bytes cannot be one (wrong fingerprint, bad count,
/// truncated, trailing bytes).
int64_t wire_size(const run_t*, const uint8_t* data, size_t len, std::string* why);
int64_t wire_size(const generation_t*, const uint8_t* data, size_t len, std::string* why);
int64_t wire_size(const cppn_genome_t*, const uint8_t* data, size_t len, std::string* why);
int64_t wire_size(const morphology_t*, const uint8_t* data, size_t len, std::string* why);
int64_t wire_size(const pose_t*, const uint8_t* data, size_t len, std::string* why);
int64_t wire_size(const eval_result_t*, const uint8_t* data, size_t len, std::string* why);
int64_t wire_size(const bus_status_t*, const uint8_t* data, size_t len, std::string* why);

/// Decodes `len` bytes into `out` when they are exactly one message of type T.
/// Returns false (with `why`) otherwise; never throws, never over-allocates.
template <class T>
bool safe_decode(const void* data, size_t len, T& out, std::string* why = nullptr) {
  const auto* bytes = static_cast<const uint8_t*>(data);
  if (wire_size(static_cast<const T*>(nullptr), bytes, len, why) != static_cast<int64_t>(len)) return false;
  try {
    if (out.decode(bytes, 0, static_cast<int>(len)) != static_cast<int>(len)) {
      if (why) *why = "the decoder rejected the message";
      return false;
    }
  } catch (const std::exception& e) {
    if (why) *why = std::string("the decoder failed: ") + e.what();
    return false;
  }
  return true;
}

}  // namespace robozoo
