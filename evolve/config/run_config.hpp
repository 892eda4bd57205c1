#pragma once
// The resolved configuration of one run: everything an evaluation or a replay
// needs. Serialised whole into run_t.config_json, so a run is reproducible from
// its first message alone (docs/method.md section 1).
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "evolve/fitness/evaluate.hpp"
#include "evolve/neat/params.hpp"

namespace robozoo {

struct RunConfig {
  Regime regime = Regime::FeedForward;  ///< feedforward (control) or recurrent (experimental)
  int64_t seed = 1;                     ///< seed of the run's single generator
  int generations = 500;                ///< generations to run (count)
  NeatParams neat;                      ///< CPPN-NEAT parameters (population inside)
  EvalParams eval;                      ///< growth, simulation and CPPN query parameters
  int pose_every = 4;                   ///< publish every k-th step of a champion's trajectory (count)
  bool publish_all = false;             ///< publish every genome, not only champions
};

/// Thrown for bad configuration: the message names the key.
struct ConfigError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

/// The whole configuration as JSON (every key, resolved values).
nlohmann::json config_to_json(const RunConfig& c);
/// Overlays `j` onto `base`. Unknown keys, wrong types and out-of-range values
/// throw ConfigError naming the key (e.g. "neat.population: must be >= 2, got -5").
RunConfig config_from_json(const nlohmann::json& j, RunConfig base = RunConfig{});
/// A configuration robozoo recorded (a log's run message, a checkpoint, a compact
/// result, a worker's setup): config_from_json onto the defaults, except that a key
/// added after such records were first written, when absent, means the behaviour
/// the record ran with: growth.bias_input 1.0, growth.weight_mapping proportional,
/// neat.add_node_innovations shared. Throws ConfigError as config_from_json does.
RunConfig config_from_record(const nlohmann::json& j);
/// Reads a JSON (.json) or TOML (.toml) file and overlays it onto `base`.
/// Throws ConfigError for an unreadable or malformed file, naming the file.
RunConfig load_config_file(const std::string& path, RunConfig base = RunConfig{});
enum class ConfigFormat { Json, Toml };
/// The same on the text of a file; `name` prefixes error messages.
RunConfig config_from_text(const std::string& text, ConfigFormat format, const std::string& name,
                           RunConfig base = RunConfig{});
/// One "KEY=VALUE" assignment (robozoo-evolve --set) as the JSON object to
/// overlay: a dotted KEY names nested sections ("neat.initial_links"); VALUE is
/// read as JSON (numbers, true/false, quoted strings) and otherwise taken as a
/// bare string ("inputs_to_outputs"). Throws ConfigError without "=" or a key.
nlohmann::json config_assignment(const std::string& assignment);
/// Checks cross-field constraints (r_min <= r_init <= r_max, ...); throws ConfigError.
void validate_config(const RunConfig& c);

std::string regime_name(Regime r);              ///< "feedforward" / "recurrent"
Regime regime_from_name(const std::string& s);  ///< throws ConfigError

}  // namespace robozoo
