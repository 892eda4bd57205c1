#pragma once
// The configuration targets' shared body (JSON and TOML differ only in format):
// accepted text must give a configuration without NaN or Inf that writes and
// reads back to itself; refused text a ConfigError with a message.
#include "evolve/config/run_config.hpp"
#include "fuzz/fuzz_check.hpp"

namespace robozoo::fuzz {

inline void check_config_text(const uint8_t* data, size_t size, ConfigFormat format) {
  RunConfig c;
  try {
    c = config_from_text(std::string(reinterpret_cast<const char*>(data), size), format, "fuzz input");
  } catch (const ConfigError& e) {
    if (std::string(e.what()).rfind("fuzz input", 0) != 0) violated("configuration error without the file's name");
    return;
  }
  const nlohmann::json j = config_to_json(c);
  require_finite(j, "config");
  if (config_to_json(config_from_json(j)) != j) violated("an accepted configuration does not read back");
}

}  // namespace robozoo::fuzz
