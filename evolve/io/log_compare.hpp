#pragma once
// Comparing two robozoo logs message by message, apart from the fields that
// depend on the wall clock (utime everywhere; eval_seconds and
// generation_seconds of generation_t). Channels robozoo does not own (such as
// LCM_SELF_TEST, which every udpm instance sends) are skipped.
#include <string>

#include "evolve/io/event_log.hpp"

namespace robozoo {

/// Normalises one robozoo message: decodes it, zeroes the clock fields,
/// re-encodes it. Returns false for a channel robozoo does not own or bytes
/// that do not decode as that channel's type.
bool normalize_message(const std::string& channel, const std::vector<uint8_t>& data,
                       std::vector<uint8_t>& out);

/// Empty when the robozoo events of `a` and `b` are equal in order after
/// normalisation; otherwise a sentence naming the first difference.
std::string first_log_difference(const LogContents& a, const LogContents& b);

}  // namespace robozoo
