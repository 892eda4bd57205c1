#pragma once
// The trials of an experiment (issue 7): N seeds of each regime, run one after
// the other by robozoo-experiment, one log per trial in the experiment's folder.
// The paper's experiment is 30 trials per regime, population 150, 500 generations.
#include <cstdint>
#include <string>
#include <vector>

#include "evolve/neat/params.hpp"

namespace robozoo {

struct ExperimentParams {
  int trials = 30;          ///< seeds per regime, 1..trials (count)
  int generations = 500;    ///< generations per trial (count)
  int population = 150;     ///< genomes per generation (count)
  int steps = 0;            ///< physics steps per evaluation (count); 0: robozoo-evolve's default (2,500)
  int workers = 0;          ///< robozoo-evolve's --workers (count); 0: one per core
  int mpi_ranks = 0;        ///< ranks of each trial's MPI job (count, >= 2); 0: local worker processes
  std::vector<std::string> mpirun = {"mpirun"};  ///< the MPI launcher and its own options, before -np
  std::string out_dir;      ///< folder of the trials' logs
};

struct Trial {
  Regime regime = Regime::FeedForward;
  int64_t seed = 1;
  std::string log_path;     ///< <out_dir>/<regime>-s<seed>.lcmlog
  std::string output_path;  ///< <out_dir>/<regime>-s<seed>.out: robozoo-evolve's messages, appended
  std::string name() const; ///< "<regime>-s<seed>"
};

/// Throws std::invalid_argument naming the parameter when one is out of range.
void validate_experiment(const ExperimentParams& p);

/// The trials in the order they run: seed 1 of both regimes, then seed 2, ...,
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
