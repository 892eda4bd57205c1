#pragma once
// What each configuration key means, with its unit: robozoo-evolve --print-config --explain.
#include <map>
#include <string>

namespace robozoo {

struct RunConfig;

/// Every configuration key ("growth.bias_input", as --set names it) and its meaning, unit
/// included where it has one.
const std::map<std::string, std::string>& config_docs();

/// One line per key of `c`, in config_to_json's order: `KEY = VALUE  # meaning`.
std::string explain_config(const RunConfig& c);

}  // namespace robozoo
