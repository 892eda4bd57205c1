#pragma once
// The arms of an experiment, and the arm a run's configuration belongs to: a
// regime and its generation-0 topology. "feedforward" (the paper's control),
// "recurrent" (its experimental regime, fully recurrent from generation 0 by
// HyperNEAT's start), "recurrent-sparse" (recurrence allowed, the control's
// 99-link start) and "recurrent-zero" (the recurrent start's 209 links with its
// 110 output -> output links at weight 0). Here, below the experiment
// (study/experiment/trial_plan.hpp), because a compact result's reader
// (record/run_summary.hpp) names the arm of the run it reads.
#include <cstdint>
#include <string>

#include "evolve/neat/params.hpp"

namespace robozoo {

/// One arm of an experiment: a regime and its generation-0 topology.
enum class Arm : int8_t { FeedForward = 0, Recurrent = 1, RecurrentSparse = 2, RecurrentZero = 3 };
constexpr int kNumArms = 4;
/// "feedforward", "recurrent", "recurrent-sparse", "recurrent-zero"
std::string arm_name(Arm a);
Arm arm_from_name(const std::string& name);  ///< throws std::invalid_argument listing the names
Regime arm_regime(Arm a);                    ///< the regime the arm evolves in
/// The generation-0 topology of the arm's runs: inputs_to_outputs for
/// recurrent-sparse, all_allowed_recurrent_zero for recurrent-zero, the default
/// (all_allowed) otherwise.
InitialLinks arm_initial_links(Arm a);
/// The arm a run's configuration belongs to: feedforward for the feed-forward
/// regime; in the recurrent regime recurrent-sparse for the inputs-to-outputs
/// start, recurrent-zero for the all_allowed_recurrent_zero start, recurrent
/// for all_allowed.
Arm arm_of(Regime regime, InitialLinks initial_links);

}  // namespace robozoo
