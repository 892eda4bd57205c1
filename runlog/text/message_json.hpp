#pragma once
// Every field of a ROBOZOO_* message as JSON (names as in lcmtypes/*.lcm;
// doubles print so that they read back bit for bit), for robozoo-log cat.
#include <string>

#include <nlohmann/json.hpp>

namespace robozoo {

/// Decodes `data` as the type of `channel` (safe_decode) and returns its
/// fields. Returns false, with `why`, when the bytes are not such a message or
/// the channel is not a robozoo one (then `why` is empty).
bool message_to_json(const std::string& channel, const void* data, size_t size, nlohmann::json& out, std::string& why);

}  // namespace robozoo
