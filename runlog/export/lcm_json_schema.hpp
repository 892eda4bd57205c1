#pragma once
// JSON Schemas (draft 2020-12 subset) of the ROBOZOO_* messages as
// message_json writes them, derived from the .lcm files of lcmtypes/ (embedded
// at build time): every field required, nothing else allowed; integers with
// their type's range, doubles as numbers, booleans as booleans, nested types
// inline, arrays of fixed size with that size.
#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace robozoo {

/// lcmtypes/NAME.lcm's text by NAME (e.g. "pose_t"); generated at build time.
const std::map<std::string, std::string>& lcm_sources();

/// The JSON Schema of the LCM type `name` (e.g. "cppn_genome_t") from `sources`.
/// Throws std::invalid_argument for an unknown type or a declaration it cannot read.
nlohmann::json lcm_json_schema(const std::string& name,
                               const std::map<std::string, std::string>& sources = lcm_sources());

/// The LCM type message_json decodes a robozoo channel as ("" for other channels).
std::string lcm_type_of_channel(const std::string& channel);

}  // namespace robozoo
