#pragma once
// Where two recorded run configurations differ, key by key: what the
// sensitivity study checks before it compares a factor's runs with the
// reference's (one factor changed, everything else the same).
//
// Both configurations are read as a run reads a recorded one (config_from_record:
// a key an older robozoo did not write takes the value that robozoo ran with)
// and written out in full (config_to_json), so a missing key and its legacy
// value are the same. Keys are dotted paths ("growth.bias_input"); arrays are
// compared as whole values.
#include <string>
#include <vector>

namespace robozoo {

struct ConfigChange {
  std::string key;   ///< dotted path, e.g. "growth.bias_input"
  std::string from;  ///< its value in the first configuration (JSON text)
  std::string to;    ///< its value in the second (JSON text)
};

/// The keys whose values differ between the recorded configurations `a` and `b`
/// (JSON text), sorted by key, leaving out the keys in `ignore`. Throws
/// std::invalid_argument naming `what` when either is not a configuration.
std::vector<ConfigChange> config_difference(const std::string& a, const std::string& b,
                                            const std::vector<std::string>& ignore, const std::string& what);

/// "growth.bias_input 0.3 -> 1.0; sim.steps 2500 -> 100" ("none" when empty).
std::string describe_changes(const std::vector<ConfigChange>& changes);

}  // namespace robozoo
