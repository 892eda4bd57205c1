#pragma once
// Where a trial stands, from its checkpoint (<log>.checkpoint, written
// atomically by robozoo-evolve after every generation): not started, stopped
// part way (resumable), or finished.
#include <cstdint>
#include <string>

#include "evolve/experiment/trial_plan.hpp"
#include "evolve/run/checkpoint.hpp"

namespace robozoo {

enum class TrialState { NotStarted, Partial, Finished };

struct TrialStatus {
  TrialState state = TrialState::NotStarted;
  int32_t generations_done = 0;  ///< finished generations (count)
  double elapsed_seconds = 0;    ///< robozoo-evolve's wall time on the trial so far (s)
};

/// The status of `t`. Throws std::runtime_error for a checkpoint that cannot be
/// read, and std::invalid_argument when it belongs to another configuration
/// (see trial_mismatch).
TrialStatus trial_status(const Trial& t, const ExperimentParams& p);

/// Empty when the checkpoint `c` was written for trial `t` of experiment `p`
/// (regime, seed, population, generations, steps: robozoo-evolve's default
/// when p.steps is 0); otherwise
/// what differs, e.g. "it was started with population 60, not 150".
std::string trial_mismatch(const Checkpoint& c, const Trial& t, const ExperimentParams& p);

/// Finished generations recorded in a checkpoint.
int32_t generations_done(const Checkpoint& c);

std::string state_name(TrialState s);  ///< "not started", "partial", "finished"

}  // namespace robozoo
