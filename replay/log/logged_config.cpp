#include "replay/log/logged_config.hpp"

#include <cstring>
#include <stdexcept>

#include "evolve/messages/build.hpp"
#include "evolve/messages/log_continuation.hpp"

namespace robozoo::replay {

namespace {

/// The first key of `reference` (recursively) that `j` lacks, as a dotted path; empty if none.
std::string missing_key(const nlohmann::json& reference, const nlohmann::json& j, const std::string& prefix) {
  for (auto it = reference.begin(); it != reference.end(); ++it) {
    const std::string path = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (!j.is_object() || !j.contains(it.key())) return path;
    if (it.value().is_object()) {
      const std::string deeper = missing_key(it.value(), j.at(it.key()), path);
      if (!deeper.empty()) return deeper;
    }
  }
  return "";
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

RunConfig config_from_run_message(const run_t& m) {
  const std::string run = "run " + m.run_id + ": ";
  nlohmann::json j;
  try {
    // A log continued from a portable checkpoint: its configuration without the continuation.
    j = nlohmann::json::parse(split_run_config(m.config_json).config_json);
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument(run + "its configuration (run_t.config_json) is not JSON: " + e.what());
  }
  if (!j.is_object()) throw std::invalid_argument(run + "its configuration (run_t.config_json) is not a JSON object");
  const std::string missing = missing_key(config_to_json(RunConfig{}), j, "");
  if (!missing.empty())
    throw std::invalid_argument(run + "its configuration lacks the key '" + missing +
                                "'; replay takes no value from its own defaults");
  RunConfig c;
  try {
    c = config_from_record(j);
  } catch (const ConfigError& e) {
    throw std::invalid_argument(run + "its configuration is invalid: " + e.what());
  }
  auto disagree = [&](const std::string& field, const std::string& in_run, const std::string& in_config) {
    throw std::invalid_argument(run + "run_t." + field + " is " + in_run + " but its configuration says " + in_config);
  };
  if (m.seed != c.seed) disagree("seed", std::to_string(m.seed), std::to_string(c.seed));
  if (m.regime != static_cast<int8_t>(c.regime)) disagree("regime", std::to_string(m.regime), regime_name(c.regime));
  if (m.population != c.neat.population)
    disagree("population", std::to_string(m.population), std::to_string(c.neat.population));
  if (m.generations != c.generations)
    disagree("generations", std::to_string(m.generations), std::to_string(c.generations));
  if (m.steps != c.eval.sim.steps) disagree("steps", std::to_string(m.steps), std::to_string(c.eval.sim.steps));
  if (!same_bits(m.dt, c.eval.sim.dt)) disagree("dt", std::to_string(m.dt), std::to_string(c.eval.sim.dt));
  return c;
}

std::string version_refusal(const run_t& m) {
  if (m.software_version == software_version()) return "";
  return "run " + m.run_id + " was written by robozoo " + m.software_version + " and this is robozoo " +
         software_version() + "; another version may grow or simulate differently (--force checks it anyway)";
}

}  // namespace robozoo::replay
