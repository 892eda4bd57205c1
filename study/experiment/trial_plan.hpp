#pragma once
// The trials of an experiment: N trials of each arm, run one after the other by
// robozoo-experiment, one log per trial in the experiment's folder. The paper's
// experiment is 30 trials per regime, population 150, 500 generations.
//
// Arms: "feedforward" (the paper's control), "recurrent" (its experimental
// regime, fully recurrent from generation 0 by HyperNEAT's start),
// "recurrent-sparse" (recurrence allowed, but the control's 99-link start:
// it tells recurrence apart from the denser start, which the paper cannot) and
// "recurrent-zero" (the recurrent start's 209 links with its 110 output ->
// output links at weight 0: the recurrent arm's genome structure, the sparse
// arm's behaviour at generation 0; a weight mutation turns recurrence on).
//
// Seeds: no two trials of an experiment share one. Trial k (1-based) of arm
// number a (0 feedforward, 1 recurrent, 2 recurrent-sparse, 3 recurrent-zero,
// whichever arms run) uses seed 4 (k - 1) + a + 1: trial 1 seeds 1, 2, 3, 4;
// trial 2 seeds 5, 6, 7, 8; ... so a trial's seed does not depend on which arms
// run, and the samples of the arms are independent, as Student's unpaired
// t-test assumes. (Arm, its names and arm_of: evolve/neat/arm.hpp.)
#include <cstdint>
#include <string>
#include <vector>

#include "evolve/neat/arm.hpp"
#include "evolve/neat/params.hpp"

namespace robozoo {

/// Seed of trial k (1-based) of arm a: kNumArms (k - 1) + a + 1 = 4 (k - 1) + a + 1.
int64_t trial_seed(Arm a, int trial);

struct ExperimentParams {
  int trials = 30;                                             ///< trials per arm, 1..trials (count)
  std::vector<Arm> arms = {Arm::FeedForward, Arm::Recurrent};  ///< the arms, in the order trials run
  int generations = 500;                                       ///< generations per trial (count)
  int population = 150;                                        ///< genomes per generation (count)
  int steps = 0;      ///< physics steps per evaluation (count); 0: robozoo-evolve's default (2,500)
  int workers = 0;    ///< robozoo-evolve's --workers (count); 0: one per core
  int mpi_ranks = 0;  ///< ranks of each trial's MPI job (count, >= 2); 0: local worker processes
  std::vector<std::string> mpirun = {"mpirun"};  ///< the MPI launcher and its own options, before -np
  std::string out_dir;                           ///< folder of the trials' logs
  /// Configuration changes for every trial, "KEY=VALUE" as robozoo-evolve --set takes them
  /// (e.g. growth.bias_input=1.0 for one factor of a sensitivity study); none by default.
  /// Keys the experiment sets itself (regime, seed, generations, neat.population,
  /// neat.initial_links, sim.steps) are refused.
  std::vector<std::string> sets;
};

struct Trial {
  Arm arm = Arm::FeedForward;
  Regime regime = Regime::FeedForward;
  int number = 1;            ///< trial number within its arm, 1-based
  int64_t seed = 1;          ///< trial_seed(arm, number)
  std::string log_path;      ///< <out_dir>/<arm>-s<seed>.lcmlog
  std::string output_path;   ///< <out_dir>/<arm>-s<seed>.out: robozoo-evolve's messages, appended
  std::string name() const;  ///< "<arm>-s<seed>", also the run id
};

/// Throws std::invalid_argument naming the parameter when one is out of range, or
/// naming the --set assignment that is malformed, invalid or sets a key of the
/// experiment's own.
void validate_experiment(const ExperimentParams& p);

/// The trials in the order they run: trial 1 of every arm, then trial 2, ...,
/// so that an experiment stopped half way has about as many trials of each.
std::vector<Trial> plan_trials(const ExperimentParams& p);

/// robozoo-evolve's arguments (after the program name) to start or resume `t`.
std::vector<std::string> evolve_arguments(const Trial& t, const ExperimentParams& p, bool resume);

/// The whole command that starts or resumes `t` with the robozoo-evolve at
/// `evolve`: that program and evolve_arguments() for a local trial, or, with
/// mpi_ranks > 0, `<mpirun...> -np <mpi_ranks> <evolve> <arguments> --mpi` (rank 0
/// evolves, logs and checkpoints; ranks 1.. evaluate). The launcher's first word
/// is returned as given; resolving it on PATH is the caller's.
std::vector<std::string> trial_command(const Trial& t, const ExperimentParams& p, const std::string& evolve,
                                       bool resume);

}  // namespace robozoo
