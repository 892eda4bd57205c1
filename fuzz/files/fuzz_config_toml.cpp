// libFuzzer target: a Toml configuration file's text (robozoo-evolve --config FILE).
#include "fuzz/files/config_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  robozoo::fuzz::check_config_text(data, size, robozoo::ConfigFormat::Toml);
  return 0;
}
