#pragma once
// robozoo-log cat: one JSON object per message of a log, on its own line (for
// jq or pandas.read_json(lines=True)):
//   {"event":N,"timestamp":US,"channel":"ROBOZOO_GENERATION","message":{...every field...}}
// A message that does not decode has "error" instead of "message"; a channel
// robozoo does not own has "bytes" (its size) instead.
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>

#include "runlog/read/log_reader.hpp"

namespace robozoo {

struct CatFilter {
  std::string channel;                ///< only this channel ("" = all); "GENERATION" means ROBOZOO_GENERATION
  std::optional<int32_t> generation;  ///< only messages of this generation (those without one, ROBOZOO_RUN
                                      ///< and foreign channels, are left out)
};

/// The channel a --channel value names: itself, or ROBOZOO_<VALUE> for a short
/// robozoo name ("pose", "POSE").
std::string channel_name(const std::string& value);

/// Writes the selected messages; returns how many.
int64_t cat_log(const ScannedLog& log, const CatFilter& filter, std::ostream& out);

}  // namespace robozoo
