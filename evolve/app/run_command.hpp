#pragma once
#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

#include "evolve/config/run_config.hpp"
#include "evolve/run/evolution.hpp"

namespace robozoo {

struct RunOptions {
  std::string regime = "feedforward";
  int64_t seed = 1;
  int population = 150;
  int generations = 500;
  int steps = 2500;
  int workers = 0;  // 0: number of cores
  std::string config_file;
  std::string preset;
  std::string log_path;
  std::string lcm_url;
  int pose_every = 4;
  double bus_rate = 1e6;         ///< --bus-rate (bytes/s)
  double bus_message_rate = 50;  ///< --bus-message-rate (messages/s)
  bool publish_all = false;
  bool resume = false;
  bool force = false;
  std::vector<std::string> sets;  ///< --set KEY=VALUE overrides, in order
  std::string run_id;
  double job_timeout = 600.0;
  bool quiet = false;
  bool print_config = false;
  bool explain = false;  ///< with print_config: every key with its meaning, not JSON
  bool mpi = false;      // evaluate on the ranks of an MPI job (mpirun); --workers is then ignored
};

void add_run_options(CLI::App& app, RunOptions& o);
/// Runs (or resumes) an evolution; returns the process exit status
/// (0 done, 2 bad configuration or unusable files, 1 failure during the run).
int run_run_command(const CLI::App& app, const RunOptions& o);

/// Resolves a run's configuration and files from the command line. Returns the
/// exit status when the program stops here (2: bad configuration or files, said in
/// one line on stderr; 0: --print-config printed), nothing when the run goes on.
std::optional<int> resolve_run(const CLI::App& app, const RunOptions& o, RunConfig& config, EvolveOptions& opts);
/// Opens (starts or resumes) the run. Returns an exit status when the program should
/// stop here: 2 when the run cannot be opened (the message is printed), 0 when it
/// is already complete; std::nullopt with `evo` set otherwise.
std::optional<int> open_evolution(const RunConfig& config, const EvolveOptions& opts, Evaluator& evaluator,
                                  std::unique_ptr<Evolution>& evo);

/// The lines printed when a run starts (log, checkpoint, live URL); `evaluators`
/// says what evaluates, e.g. "2 workers".
std::string run_banner(const Evolution& evo, const EvolveOptions& opts, const std::string& evaluators);
/// --resume: "resumed run R at generation G of N (E evaluations before)", or that
/// no checkpoint was there and the run starts at generation 0 (printed even with --quiet).
std::string resume_line(const Evolution& evo, const EvolveOptions& opts);
/// The end of a run: evaluations made in this process and in the whole run, and
/// the generations this process evolved (printed even with --quiet after --resume).
std::string session_line(const Evolution& evo);
/// "bus: N messages published, F publish failures"; empty for a run that does not publish.
std::string bus_line(const Evolution& evo);
/// The lines printed to stderr when a run has ended: the log ("done"), the
/// session line (unless --quiet, but always after --resume) and the bus line
/// (even with --quiet: a live run's subscribers need to know what was lost at the source).
void print_run_end(const Evolution& evo, const EvolveOptions& opts, bool quiet);

}  // namespace robozoo
