#pragma once
// Comparing two robozoo logs message by message: the oracle of the
// determinism, resume, worker-count and MPI tests.
//
// Only events on robozoo's own channels (names starting with "ROBOZOO_") are
// compared, in order; others (such as LCM_SELF_TEST, which every udpm instance
// sends) are skipped. Each message of a known channel is decoded safely
// (safe_decode: counts and sizes checked), its wall-clock fields are zeroed,
// and it is re-encoded; the two results must be equal byte for byte. The
// fields zeroed (the only ones left out) are:
//   - utime of every message (publication time);
//   - generation_t.eval_seconds and generation_t.generation_seconds (timings).
// Everything else counts bit for bit: a double that differs by one ulp is a
// difference, and a NaN equals only a NaN with the same bits.
// A message that does not decode as its channel's type never equals anything,
// not even the same bytes in the other log. A ROBOZOO_ channel this code does
// not know is compared as raw bytes, unnormalised. ROBOZOO_BUS (bus_status_t,
// sent on the bus only, describing one transmission) is never compared.
#include <string>

#include "evolve/io/event_log.hpp"

namespace robozoo {

/// Normalises one robozoo message: decodes it safely, zeroes the clock fields,
/// re-encodes it. Returns false for a channel robozoo does not own or bytes
/// that are not exactly one message of that channel's type (`why` says which).
bool normalize_message(const std::string& channel, const std::vector<uint8_t>& data, std::vector<uint8_t>& out,
                       std::string* why = nullptr);

/// True for the channels normalize_message knows (ROBOZOO_RUN, _GENERATION,
/// _GENOME, _MORPHOLOGY, _POSE).
bool is_known_channel(const std::string& channel);

/// Empty when the robozoo events of `a` and `b` are equal in order after
/// normalisation; otherwise a sentence naming the first difference: the event
/// (its index among robozoo events and its event number in each log), the
/// channel, and the first differing byte of the normalised messages, or the
/// reason a message does not decode, or the counts when one log has more events.
std::string first_log_difference(const LogContents& a, const LogContents& b);

/// A recording of the bus (lcm-logger's) against the log of what was sent.
struct BusRecording {
  size_t sent = 0;      ///< robozoo events sent (count)
  size_t received = 0;  ///< robozoo events recorded (count)
  size_t missing = 0;   ///< sent events not recorded (count): loss on the way, not a defect
  /// Empty when the recording is what was sent with events missing at most: every
  /// recorded event equal (after normalisation) to a sent one, each at most once, in
  /// the order sent. Otherwise names the first recorded event that was changed,
  /// added, repeated or reordered, or does not decode.
  std::string defect;
};
BusRecording compare_bus_recording(const LogContents& sent, const LogContents& received);

}  // namespace robozoo
