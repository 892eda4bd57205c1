#include "study/experiment/trial_status.hpp"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "evolve/config/run_config.hpp"
#include "evolve/record/checkpoint.hpp"

namespace robozoo {

int32_t generations_done(const Checkpoint& c) {
  // After generation g the population holds generation g + 1, except after the last one.
  if (c.finished) return c.config.value("generations", c.population.generation + 1);
  return c.population.generation;
}

std::string sets_mismatch(const nlohmann::json& config, const std::vector<std::string>& sets) {
  std::string why;
  nlohmann::json recorded;
  try {
    recorded = config_to_json(config_from_record(config));
  } catch (const std::exception& e) {
    return std::string("its configuration is invalid: ") + e.what();
  }
  for (const auto& kv : sets) {
    const nlohmann::json want = config_to_json(config_from_json(config_assignment(kv)));
    const std::string key = kv.substr(0, kv.find('='));
    std::string pointer;
    for (size_t start = 0; start <= key.size();) {
      const size_t dot = std::min(key.find('.', start), key.size());
      pointer += "/" + key.substr(start, dot - start);
      start = dot + 1;
    }
    const nlohmann::json::json_pointer at(pointer);
    const nlohmann::json was = recorded.contains(at) ? recorded.at(at) : nlohmann::json();
    if (was == want.at(at)) continue;
    if (!why.empty()) why += ", ";
    why += key + " " + was.dump() + ", not " + want.at(at).dump();
  }
  return why;
}

std::string trial_mismatch(const Checkpoint& c, const Trial& t, const ExperimentParams& p) {
  RunConfig saved;
  try {
    saved = config_from_record(c.config);
  } catch (const std::exception& e) {
    return std::string("its configuration is invalid: ") + e.what();
  }
  std::string why;
  auto differ = [&why](const std::string& what, const std::string& was, const std::string& want) {
    if (was == want) return;
    if (!why.empty()) why += ", ";
    why += what + " " + was + ", not " + want;
  };
  differ("regime", regime_name(saved.regime), regime_name(t.regime));
  differ("seed", std::to_string(saved.seed), std::to_string(t.seed));
  const InitialLinks want_start = arm_initial_links(t.arm);
  differ("initial links", initial_links_name(saved.neat.initial_links), initial_links_name(want_start));
  differ("population", std::to_string(saved.neat.population), std::to_string(p.population));
  const int steps = p.steps > 0 ? p.steps : RunConfig{}.eval.sim.steps;
  differ("steps", std::to_string(saved.eval.sim.steps), std::to_string(steps));
  const std::string sets = sets_mismatch(c.config, p.sets);
  if (!sets.empty()) why += (why.empty() ? "" : ", ") + sets;
  return why.empty() ? why : "it was started with " + why;
}

TrialStatus trial_status(const Trial& t, const ExperimentParams& p) {
  TrialStatus s;
  const std::string cp = checkpoint_path_for(t.log_path);
  if (!std::filesystem::exists(cp)) {
    // Starting afresh would replace the log: a log without its checkpoint can be neither resumed nor extended.
    if (std::filesystem::exists(t.log_path))
      throw std::invalid_argument(t.log_path + " has no checkpoint (" + cp +
                                  "), so it can be neither resumed nor extended; restore the checkpoint, or move "
                                  "the log away to run the trial again");
    return s;
  }
  const Checkpoint c = read_checkpoint(cp);
  const std::string why = trial_mismatch(c, t, p);
  if (!why.empty())
    throw std::invalid_argument(t.log_path + " belongs to another experiment: " + why +
                                " (use another --out folder, or the sizes it was started with)");
  const int32_t planned = c.config.value("generations", 0);
  s.generations_done = generations_done(c);
  s.elapsed_seconds = c.elapsed_seconds;
  if (planned > p.generations) {
    // Run further than asked (an arm extended before): done once it has p.generations.
    if (s.generations_done < p.generations)
      throw std::invalid_argument(t.log_path + " was started for " + std::to_string(planned) + " generations and has " +
                                  std::to_string(s.generations_done) + "; continue it with --generations " +
                                  std::to_string(planned));
    s.state = TrialState::Finished;
    s.generations_done = p.generations;
    return s;
  }
  // Fewer planned than asked: resuming extends it (robozoo-evolve --resume --generations).
  s.state = c.finished && planned == p.generations ? TrialState::Finished : TrialState::Partial;
  return s;
}

std::string state_name(TrialState s) {
  switch (s) {
    case TrialState::NotStarted: return "not started";
    case TrialState::Partial: return "partial";
    case TrialState::Finished: return "finished";
  }
  return "?";
}

}  // namespace robozoo
