#pragma once
// Where a trial stands, from its checkpoint (<log>.checkpoint, written
// atomically by robozoo-evolve after every generation): not started, stopped
// part way (resumable), or finished.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/experiment/trial_plan.hpp"
#include "evolve/record/checkpoint.hpp"

namespace robozoo {

enum class TrialState { NotStarted, Partial, Finished };

struct TrialStatus {
  TrialState state = TrialState::NotStarted;
  int32_t generations_done = 0;  ///< finished generations (count)
  double elapsed_seconds = 0;    ///< robozoo-evolve's wall time on the trial so far (s)
  bool time_known = true;        ///< false: elapsed_seconds is unknown (a compact result without it)
};

/// The status of `t` in an experiment of p.generations generations. A trial
/// started for fewer generations is Partial (resuming extends it); one started
/// for more is Finished once it has p.generations. Throws std::runtime_error
/// for a checkpoint that cannot be read, and std::invalid_argument when it
/// belongs to another configuration (see trial_mismatch), when a trial started
/// for more generations has fewer than p.generations, or when its log exists
/// without its checkpoint (it could be neither resumed nor extended).
TrialStatus trial_status(const Trial& t, const ExperimentParams& p);

/// Empty when the checkpoint `c` was written for trial `t` of experiment `p`
/// (regime, seed, start topology, population, steps: robozoo-evolve's default
/// when p.steps is 0; every key of p.sets; not generations, which an experiment
/// may raise); otherwise
/// what differs, e.g. "it was started with population 60, not 150".
std::string trial_mismatch(const Checkpoint& c, const Trial& t, const ExperimentParams& p);

/// Empty when the recorded configuration `config` (a checkpoint's or a compact
/// result's) holds the value every one of `sets` ("KEY=VALUE", ExperimentParams::sets)
/// gives its key; otherwise what differs, e.g. "growth.bias_input 0.3, not 1.0".
std::string sets_mismatch(const nlohmann::json& config, const std::vector<std::string>& sets);

/// Finished generations recorded in a checkpoint.
int32_t generations_done(const Checkpoint& c);

std::string state_name(TrialState s);  ///< "not started", "partial", "finished"

}  // namespace robozoo
