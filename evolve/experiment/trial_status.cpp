#include "evolve/experiment/trial_status.hpp"

#include <filesystem>
#include <stdexcept>

#include "evolve/config/run_config.hpp"

namespace robozoo {

int32_t generations_done(const Checkpoint& c) {
  // After generation g the population holds generation g + 1, except after the last one.
  if (c.finished) return c.config.value("generations", c.population.generation + 1);
  return c.population.generation;
}

std::string trial_mismatch(const Checkpoint& c, const Trial& t, const ExperimentParams& p) {
  RunConfig saved;
  try {
    saved = config_from_json(c.config);
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
  differ("generations", std::to_string(saved.generations), std::to_string(p.generations));
  const int steps = p.steps > 0 ? p.steps : RunConfig{}.eval.sim.steps;
  differ("steps", std::to_string(saved.eval.sim.steps), std::to_string(steps));
  return why.empty() ? why : "it was started with " + why;
}

TrialStatus trial_status(const Trial& t, const ExperimentParams& p) {
  TrialStatus s;
  const std::string cp = t.log_path + ".checkpoint";
  if (!std::filesystem::exists(cp)) return s;
  const Checkpoint c = read_checkpoint(cp);
  const std::string why = trial_mismatch(c, t, p);
  if (!why.empty())
    throw std::invalid_argument(t.log_path + " belongs to another experiment: " + why +
                                " (use another --out folder, or the sizes it was started with)");
  s.state = c.finished ? TrialState::Finished : TrialState::Partial;
  s.generations_done = generations_done(c);
  s.elapsed_seconds = c.elapsed_seconds;
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
