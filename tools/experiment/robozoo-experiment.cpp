// robozoo-experiment: the paper's experiment. Runs N seeds of each
// regime (feed-forward and recurrent CPPNs) with robozoo-evolve, one log per
// trial in --out, one trial after the other, each locally (--workers) or as an
// MPI job (--mpi N: mpirun -np N robozoo-evolve --mpi). It can be stopped (Ctrl-C, SIGTERM)
// and started again at any time: finished trials are skipped, a stopped one is
// resumed from its checkpoint, the others are started; --generations above the
// trials' own extends them from their checkpoints. Each finished trial leaves its
// compact result (evolve/record/run_results.hpp) in --results. Trials in
// progress travel to another machine as portable checkpoints
// (study/experiment/portable_checkpoint.hpp): --save-checkpoints DIR writes them,
// --checkpoints DIR continues from them. Prints progress across the whole
// experiment with an estimated finish time. Then: robozoo-stats DIR.
#include <unistd.h>

#include <CLI/CLI.hpp>

#include <csignal>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

#include "evolve/config/run_config.hpp"
#include "evolve/core/version.hpp"
#include "evolve/record/checkpoint.hpp"
#include "study/analysis/read/continued_results.hpp"
#include "evolve/record/run_results.hpp"
#include "study/experiment/child_process.hpp"
#include "study/experiment/portable_checkpoint.hpp"
#include "study/experiment/progress_estimate.hpp"
#include "study/experiment/trial_plan.hpp"
#include "study/experiment/trial_status.hpp"
#include "util/program_path.hpp"
#include "util/parse_options.hpp"

using namespace robozoo;

namespace {

struct Experiment {
  ExperimentParams params;
  std::vector<Trial> trials;
  std::vector<TrialStatus> status;

  ProgressTotals totals() const {
    ProgressTotals t;
    t.generations_total = static_cast<int64_t>(trials.size()) * params.generations;
    for (const auto& s : status) {
      t.generations_done += s.generations_done;
      if (s.time_known)
        t.seconds_spent += s.elapsed_seconds;
      else
        t.generations_untimed += s.generations_done;
    }
    return t;
  }
};

std::string progress_line(const Experiment& e, size_t current) {
  const ProgressTotals t = e.totals();
  const ProgressEstimate est = estimate_progress(t);
  std::ostringstream s;
  char pct[32];
  std::snprintf(pct, sizeof pct, "%5.1f%%", 100.0 * est.fraction);
  s << "experiment " << pct << " (" << t.generations_done << "/" << t.generations_total << " generations)  trial "
    << current + 1 << "/" << e.trials.size() << " " << e.trials[current].name() << " gen "
    << e.status[current].generations_done << "/" << e.params.generations << "  spent "
    << format_duration(t.seconds_spent);
  if (est.known && t.generations_done < t.generations_total) {
    const std::time_t now = std::time(nullptr);
    s << "  remaining ~" << format_duration(est.remaining_seconds) << "  finish ~"
      << format_clock(now + static_cast<std::time_t>(est.remaining_seconds), now);
  } else if (!est.known) {
    s << "  remaining: estimated after the first generation";
  }
  return s.str();
}

/// The last `n` lines of a trial's output file, each indented, for an error message.
std::string last_lines(const std::string& path, size_t n) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string l; std::getline(in, l);) {
    if (l.empty()) continue;
    lines.push_back(l);
    if (lines.size() > n) lines.erase(lines.begin());
  }
  std::string out;
  for (const auto& l : lines) out += "    " + l + "\n";
  return out;
}

std::string results_path(const std::string& dir, const Trial& t) { return dir + "/" + t.name() + kRunResultsExtension; }

/// Writes the compact result of the finished trial `t` when `path` lacks it or
/// holds an older end; says so. Returns false (with the reason) on failure.
bool write_trial_results(const Trial& t, const std::string& path, int generations, bool force) {
  try {
    if (!force && std::filesystem::exists(path)) {
      const RunResults old = read_run_results(path);
      if (old.run.complete() && old.run.generations_requested == generations) return true;
    }
    const RunResults r = run_results_of_log(t.log_path);
    if (!r.run.complete()) {
      std::cerr << "robozoo-experiment: " << t.log_path << " lacks generations (" << r.run.generations.size() << " of "
                << r.run.generations_requested << "): no compact result written\n";
      return false;
    }
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    write_run_results(path, r);
    std::cerr << "  compact result " << path << " (" << std::filesystem::file_size(path) << " bytes)" << std::endl;
    return true;
  } catch (const std::exception& ex) {
    std::cerr << "robozoo-experiment: cannot write the compact result of " << t.name() << ": " << ex.what() << "\n";
    return false;
  }
}

void print_status(const Experiment& e) {
  std::cout << "trial                 state        generations  time\n";
  for (size_t i = 0; i < e.trials.size(); ++i) {
    char line[200];
    std::snprintf(line, sizeof line, "%-21s %-12s %5d/%-6d %s\n", e.trials[i].name().c_str(),
                  state_name(e.status[i].state).c_str(), e.status[i].generations_done, e.params.generations,
                  e.status[i].time_known ? format_duration(e.status[i].elapsed_seconds).c_str() : "?");
    std::cout << line;
  }
  const ProgressEstimate est = estimate_progress(e.totals());
  std::cout << "experiment " << static_cast<int>(100.0 * est.fraction) << "% done";
  if (est.known && est.fraction < 1.0) std::cout << ", about " << format_duration(est.remaining_seconds) << " left";
  std::cout << "\n";
}

/// What the command line asks for, besides the experiment's parameters.
struct Options {
  ExperimentParams params;
  std::string evolve;                ///< the robozoo-evolve program; empty: the one beside this program
  std::string results_dir;           ///< the trials' compact results; empty: OUT/results
  std::string mpirun = "mpirun";     ///< the MPI launcher with its options, split at spaces
  std::string checkpoints_dir;       ///< portable checkpoints to continue trials from; empty: none
  std::string save_checkpoints_dir;  ///< write the portable checkpoints of trials in progress here, and exit
  bool status_only = false;
  bool force = false;
  double progress_interval = 5.0;  ///< seconds between progress lines
};

/// Reads the command line into `o`; the exit status when the program ends here
/// (--help, --version, a bad option), nothing when it goes on.
std::optional<int> parse_command_line(int argc, char** argv, Options& o) {
  ExperimentParams& p = o.params;
  std::string& evolve = o.evolve;
  std::string& results_dir = o.results_dir;
  std::string& mpirun = o.mpirun;
  bool& status_only = o.status_only;
  bool& force = o.force;
  double& progress_interval = o.progress_interval;
  CLI::App app{
      "robozoo-experiment: run the paper's experiment, --trials trials of each arm (feed-forward and\n"
      "recurrent CPPNs; optionally recurrent CPPNs from the control's sparse start, or from the recurrent\n"
      "start with its recurrent links at weight 0) with robozoo-evolve, one log per trial in --out\n"
      "(<arm>-s<seed>.lcmlog). No two trials share a seed: trial k of arm a (0 feedforward, 1 recurrent,\n"
      "2 recurrent-sparse, 3 recurrent-zero) uses seed 4(k-1)+a+1. Stop it at any time (Ctrl-C)\n"
      "and run the same command again: finished trials are skipped, a stopped one is resumed, the others\n"
      "are started. Run it again with more --generations (and any --arms) to extend finished trials from\n"
      "their checkpoints. Each finished trial leaves a compact result (<trial>.results.json, a few\n"
      "tens of kB, to commit) in --results. The paper's sizes are the defaults (30 trials, population\n"
      "150, 500 generations). Afterwards: robozoo-stats DIR (or robozoo-stats RESULTS_DIR)."};
  app.add_option("--out", p.out_dir, "folder of the experiment's logs (created if missing)")->required();
  app.add_option("--results", results_dir,
                 "folder of the trials' compact results (default: OUT/results); a trial whose log and checkpoint "
                 "are not in --out but whose result here reached --generations is done");
  app.add_option("--trials", p.trials, "trials per arm (paper: 30)")->check(CLI::Range(1, 100000));
  std::vector<std::string> arm_names = {"feedforward", "recurrent"};
  app.add_option("--arms", arm_names,
                 "the arms, comma-separated: feedforward (control), recurrent (experimental, HyperNEAT's fully "
                 "recurrent start), recurrent-sparse (recurrence allowed, the control's 99-link start), recurrent-zero "
                 "(the recurrent start, its 110 output-to-output links at weight 0)")
      ->delimiter(',')
      ->check(CLI::IsMember({"feedforward", "recurrent", "recurrent-sparse", "recurrent-zero"}))
      ->capture_default_str();
  app.add_option("--generations", p.generations, "generations per trial (paper: 500)")
      ->check(CLI::Range(1, 1000000000));
  app.add_option("--population", p.population, "genomes per generation (paper: 150)")->check(CLI::Range(2, 1000000));
  app.add_option("--workers", p.workers, "robozoo-evolve worker processes per trial (default: one per core)")
      ->check(CLI::Range(1, 4096));
  app.add_option("--steps", p.steps, "physics steps per evaluation, passed to robozoo-evolve (default: its own, 2500)")
      ->check(CLI::Range(1, 1000000000));
  app.add_option("--mpi", p.mpi_ranks,
                 "run each trial as an MPI job of this many ranks: <mpirun> -np RANKS robozoo-evolve --mpi ... "
                 "(rank 0 evolves, logs and checkpoints; ranks 1.. evaluate; >= 2; excludes --workers)")
      ->check(CLI::Range(2, 1000000));
  app.add_option("--mpirun", mpirun,
                 "the MPI launcher with its options, split at spaces, before -np (e.g. \"mpirun --hostfile hosts\" "
                 "or \"srun --mpi=pmix\"); only with --mpi")
      ->capture_default_str();
  app.add_option("--set", p.sets,
                 "KEY=VALUE: a configuration change for every trial, passed to robozoo-evolve --set (repeatable; "
                 "e.g. growth.bias_input=1.0); checkpoints and compact results must hold it");
  app.add_option("--evolve", evolve, "the robozoo-evolve program (default: the one next to this program)");
  app.add_option("--progress-interval", progress_interval,
                 "seconds between progress lines (at most one per generation)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--checkpoints", o.checkpoints_dir,
                 "folder of portable checkpoints (<trial>.portable-checkpoint, from --save-checkpoints on another "
                 "machine): a trial with neither log nor checkpoint in --out, and no compact result that reached "
                 "--generations, continues from its portable checkpoint there, in a new log that begins at its "
                 "generation (a missing folder holds none)");
  app.add_option("--save-checkpoints", o.save_checkpoints_dir,
                 "write the portable checkpoint of each trial in progress in --out into this folder "
                 "(<trial>.portable-checkpoint: its checkpoint and its compact result so far, compressed, to commit), "
                 "remove those of finished trials, and exit; safe while the experiment runs");
  app.add_flag("--status", status_only, "print where each trial stands and exit");
  app.add_flag("--force", force,
               "resume or extend trials whose checkpoints another robozoo version wrote (robozoo-evolve --resume "
               "--force: that version may grow, simulate or breed differently); not a portable checkpoint's, whose "
               "result must be one version's run");
  app.set_version_flag("--version", robozoo::version_line());
  if (const auto stop = robozoo::parse_options(app, argc, argv, "robozoo-experiment")) return *stop;
  {
    std::istringstream words(mpirun);
    p.mpirun.clear();
    for (std::string w; words >> w;) p.mpirun.push_back(w);
  }
  p.arms.clear();
  for (const auto& a : arm_names) p.arms.push_back(robozoo::arm_from_name(a));
  if (p.mpi_ranks == 0 && app.count("--mpirun") > 0) {
    std::cerr << "robozoo-experiment: --mpirun only applies with --mpi RANKS\n";
    return 2;
  }
  if (results_dir.empty()) results_dir = p.out_dir + "/results";
  if (status_only && !o.save_checkpoints_dir.empty()) {
    std::cerr << "robozoo-experiment: --status and --save-checkpoints are two actions; give one\n";
    return 2;
  }
  return std::nullopt;
}

/// The trials of the experiment and where each stands: from its log and
/// checkpoint in --out, or, with neither there, from its compact result in
/// --results (`from_results`: done according to that result alone). Throws
/// std::invalid_argument for a result that cannot stand for its trial.
Experiment plan_experiment(const Options& o, std::vector<bool>& from_results, std::vector<std::string>& from_portable) {
  const ExperimentParams& p = o.params;
  const std::string& results_dir = o.results_dir;
  Experiment e;
  e.params = p;
  e.trials = plan_trials(p);
  from_results.clear();
  from_portable.clear();
  for (const auto& t : e.trials) {
    e.status.push_back(trial_status(t, p));
    from_results.push_back(false);
    from_portable.emplace_back();
    const std::string rp = results_path(results_dir, t);
    if (e.status.back().state != TrialState::NotStarted) continue;
    const bool has_results = std::filesystem::exists(rp);
    const std::string pp = o.checkpoints_dir.empty() ? "" : portable_checkpoint_path(o.checkpoints_dir, t);
    const bool has_portable = !pp.empty() && std::filesystem::exists(pp);
    if (!has_results && !has_portable) continue;
    std::optional<RunResults> r;
    // No log, no checkpoint, but a compact result (e.g. an experiment continued on another machine).
    if (has_results) r = read_run_results(rp);
    if (r && (r->run.run_id != t.name() || r->run.population != p.population))
      throw std::invalid_argument(rp + " is the result of run " + r->run.run_id + " with population " +
                                  std::to_string(r->run.population) + ", not of trial " + t.name() +
                                  " with population " + std::to_string(p.population));
    const bool result_done = r && r->run.complete() && r->run.generations_requested >= p.generations;
    if (!result_done && has_portable) {
      // In progress on another machine: continued from its portable checkpoint.
      const PortableCheckpoint pc = read_portable_checkpoint(pp);
      const std::string why = portable_refusal(pc, pp, t, p);
      if (!why.empty()) throw std::invalid_argument(why);
      const int32_t planned = pc.checkpoint.config.value("generations", 0);
      if (planned > p.generations)
        throw std::invalid_argument(pp + " holds " + t.name() + " started for " + std::to_string(planned) +
                                    " generations; continue it with --generations " + std::to_string(planned));
      TrialStatus& s = e.status.back();
      s.state = TrialState::Partial;
      s.generations_done = pc.generation;
      s.elapsed_seconds = pc.checkpoint.elapsed_seconds;
      from_portable.back() = pp;
      continue;
    }
    if (!r) continue;
    const std::string sets = sets_mismatch(nlohmann::json::parse(r->run.config_json, nullptr, false), p.sets);
    if (!sets.empty())
      throw std::invalid_argument(rp + " belongs to another experiment: it was run with " + sets +
                                  " (use another --results folder, or the --set it was run with)");
    if (!result_done)
      throw std::invalid_argument(
          rp + " holds " + t.name() + " at " + std::to_string(r->run.generations.size()) +
          " generations, but its log and checkpoint are not in " + p.out_dir + ": it cannot be extended to " +
          std::to_string(p.generations) +
          " (copy <trial>.lcmlog and its .checkpoint there, or its portable checkpoint into --checkpoints)");
    TrialStatus& s = e.status.back();
    s.state = TrialState::Finished;
    s.generations_done = p.generations;
    // Its time, for the estimate: the run's, pro rata when it ran further than asked.
    s.time_known = r->has_evolve_seconds && !r->run.generations.empty();
    if (s.time_known)
      s.elapsed_seconds = r->evolve_seconds * p.generations / static_cast<double>(r->run.generations.size());
    from_results.back() = true;
  }
  return e;
}

/// Finds robozoo-evolve and, with --mpi, the MPI launcher (put in e.params);
/// says why and returns false when one cannot be run.
bool find_programs(Options& o, Experiment& e) {
  const ExperimentParams& p = o.params;
  std::string& evolve = o.evolve;
  try {
    if (evolve.empty()) evolve = program_dir() + "/robozoo-evolve";
  } catch (const std::exception& ex) {
    std::cerr << "robozoo-experiment: " << ex.what() << "\n";
    return false;
  }
  if (!is_executable(evolve)) {
    std::cerr << "robozoo-experiment: cannot run " << evolve << " (build robozoo-evolve, or give --evolve)\n";
    return false;
  }
  if (p.mpi_ranks > 0) {
    const char* path = std::getenv("PATH");
    const std::string launcher = find_program(p.mpirun.front(), path ? path : "/usr/bin:/bin");
    if (launcher.empty() || !is_executable(launcher)) {
      std::cerr << "robozoo-experiment: cannot run the MPI launcher " << p.mpirun.front()
                << " (install Open MPI: tools/setup.sh, or give --mpirun)\n";
      return false;
    }
    e.params.mpirun.front() = launcher;
  }
  return true;
}

/// The line that says what the experiment will do.
void print_plan(const Experiment& e) {
  const ExperimentParams& p = e.params;
  int finished = 0, partial = 0;
  for (const auto& s : e.status) {
    finished += s.state == TrialState::Finished;
    partial += s.state == TrialState::Partial;
  }
  std::cerr << "robozoo-experiment: " << e.trials.size() << " trials (" << p.trials << " per regime), population "
            << p.population << ", " << p.generations << " generations"
            << (p.steps > 0 ? ", " + std::to_string(p.steps) + " steps" : std::string()) << ", "
            << (p.mpi_ranks > 0 ? "MPI jobs of " + std::to_string(p.mpi_ranks) + " ranks"
                                : (p.workers > 0 ? std::to_string(p.workers) : std::string("all")) + " workers")
            << ", in " << p.out_dir << "\n  " << finished << " finished (skipped), " << partial << " to resume, "
            << e.trials.size() - static_cast<size_t>(finished + partial) << " to start" << std::endl;
}

/// Trials finished before (or before compact results existed) get theirs now.
/// Returns false when one could not be written; throws when a trial's
/// checkpoint cannot be read.
bool write_missing_results(const Experiment& e, const std::vector<bool>& from_results, const std::string& results_dir) {
  bool results_ok = true;
  for (size_t i = 0; i < e.trials.size(); ++i) {
    if (e.status[i].state != TrialState::Finished || from_results[i]) continue;
    const int planned = read_checkpoint(checkpoint_path_for(e.trials[i].log_path)).config.value("generations", 0);
    results_ok &= write_trial_results(e.trials[i], results_path(results_dir, e.trials[i]), planned, false);
  }
  return results_ok;
}

/// Runs trial i (starts or resumes it) until it finishes, fails or a signal
/// stops the experiment, printing progress. Nothing when it finished (its
/// compact result written, `results_ok` cleared if that failed), else the
/// program's exit status.
std::optional<int> run_trial(Experiment& e, size_t i, const Options& o, const std::string& portable,
                             const SignalBlock& block, bool& results_ok) {
  const ExperimentParams& p = o.params;
  const Trial& t = e.trials[i];
  const bool resume = e.status[i].state == TrialState::Partial;
  if (!portable.empty()) {
    // Read again (it was checked when planning): its checkpoint and earlier result go beside the new log.
    try {
      const PortableCheckpoint pc = read_portable_checkpoint(portable);
      const std::string why = portable_refusal(pc, portable, t, p);
      if (!why.empty()) throw std::invalid_argument(why);
      unpack_portable_checkpoint(pc, t.log_path);
    } catch (const std::exception& ex) {
      std::cerr << "robozoo-experiment: " << ex.what() << "\n";
      return 2;
    }
    std::cerr << "[" << i + 1 << "/" << e.trials.size() << "] " << t.name()
              << ": continues from the portable checkpoint " << portable << " (generations 0-"
              << e.status[i].generations_done - 1 << " in its compact result, a new log from generation "
              << e.status[i].generations_done << ")" << std::endl;
  }
  std::cerr << "[" << i + 1 << "/" << e.trials.size() << "] " << t.name() << ": "
            << (resume ? "resuming after generation " + std::to_string(e.status[i].generations_done) + " (to " +
                             std::to_string(p.generations) + ")"
                       : std::string("starting"))
            << " (log " << t.log_path << ")" << std::endl;
  std::vector<std::string> args = trial_command(t, e.params, o.evolve, resume);
  if (resume && o.force) args.push_back("--force");
  if (p.mpi_ranks > 0) {
    std::cerr << " ";
    for (const auto& a : args) std::cerr << " " << a;
    std::cerr << std::endl;
  }
  pid_t pid;
  try {
    pid = spawn_child(args, t.output_path);
  } catch (const std::exception& ex) {
    std::cerr << "robozoo-experiment: " << ex.what() << "\n";
    return 1;
  }
  const std::string cp = checkpoint_path_for(t.log_path);
  std::filesystem::file_time_type seen{};
  auto last_line = std::chrono::steady_clock::now() - std::chrono::hours(1);
  int32_t last_gen = e.status[i].generations_done;
  for (;;) {
    const ChildEvent ev = wait_child(block, pid, 1.0);
    if (ev.kind == ChildEvent::Signalled) {
      std::cerr << "\nrobozoo-experiment: " << strsignal(ev.signal) << ": stopping " << t.name() << " ..." << std::endl;
      stop_child(pid);
      try {
        e.status[i] = trial_status(t, p);
      } catch (const std::exception&) {
      }
      std::cerr << "robozoo-experiment: stopped; " << t.name() << " kept " << e.status[i].generations_done
                << " finished generations. Run the same command again to resume." << std::endl;
      return 128 + ev.signal;
    }
    if (ev.kind == ChildEvent::Exited) {
      try {
        e.status[i] = trial_status(t, p);
      } catch (const std::exception& ex) {
        std::cerr << "robozoo-experiment: " << ex.what() << "\n";
        return 1;
      }
      if (ev.status != 0 || e.status[i].state != TrialState::Finished) {
        std::cerr << "robozoo-experiment: " << (p.mpi_ranks > 0 ? "the MPI job of robozoo-evolve" : "robozoo-evolve")
                  << " failed on " << t.name() << " (exit status " << ev.status << "); it ended with:\n"
                  << last_lines(t.output_path, 8) << "  (all its messages are in " << t.output_path << ")"
                  << (e.status[i].generations_done > 0 ? ". Its checkpoint is kept: run the same command again to "
                                                         "resume it"
                                                       : "")
                  << "\n";
        return 1;
      }
      std::cerr << "[" << i + 1 << "/" << e.trials.size() << "] " << t.name() << ": finished ("
                << format_duration(e.status[i].elapsed_seconds) << ")\n  " << progress_line(e, i) << std::endl;
      results_ok &= write_trial_results(t, results_path(o.results_dir, t), p.generations, true);
      return std::nullopt;
    }
    // Timeout: look at the checkpoint when it changed.
    std::error_code ec;
    const auto mtime = std::filesystem::last_write_time(cp, ec);
    if (ec || mtime == seen) continue;
    seen = mtime;
    try {
      e.status[i] = trial_status(t, p);
    } catch (const std::exception&) {
      continue;  // being replaced right now; the next look will do
    }
    const auto now = std::chrono::steady_clock::now();
    if (e.status[i].generations_done != last_gen &&
        std::chrono::duration<double>(now - last_line).count() >= o.progress_interval) {
      last_gen = e.status[i].generations_done;
      last_line = now;
      std::cerr << "  " << progress_line(e, i) << std::endl;
    }
  }
}

/// --save-checkpoints: the portable checkpoint of each trial in progress in
/// --out into `dir`, none for finished trials (their compact results count).
/// A file there that holds more generations than the trial here is kept.
/// Returns the exit status.
int save_portable_checkpoints(const Experiment& e, const std::vector<std::string>& from_portable,
                              const std::string& dir) {
  int status = 0, written = 0, removed = 0;
  for (size_t i = 0; i < e.trials.size(); ++i) {
    const Trial& t = e.trials[i];
    const TrialStatus& s = e.status[i];
    const std::string path = portable_checkpoint_path(dir, t);
    try {
      if (s.state == TrialState::Finished) {
        if (std::filesystem::remove(path)) {
          std::cerr << "  " << t.name() << ": finished; removed " << path << "\n";
          ++removed;
        }
        continue;
      }
      // Not started here, or known only from a portable checkpoint: nothing newer to write.
      if (s.state != TrialState::Partial || !from_portable[i].empty() || s.generations_done < 1) continue;
      const PortableCheckpoint pc = pack_portable_checkpoint(t.log_path);
      if (std::filesystem::exists(path)) {
        const PortableCheckpoint old = read_portable_checkpoint(path);
        if (old.generation > pc.generation) {
          std::cerr << "  " << t.name() << ": kept " << path << " (generation " << old.generation
                    << "; the trial here is at " << pc.generation << ")\n";
          continue;
        }
      }
      std::filesystem::create_directories(dir);
      write_portable_checkpoint(path, pc);
      ++written;
      std::cerr << "  " << t.name() << ": generation " << pc.generation << ", " << path << " ("
                << std::filesystem::file_size(path) << " bytes)\n";
    } catch (const std::exception& ex) {
      std::cerr << "robozoo-experiment: " << t.name() << ": " << ex.what() << "\n";
      status = 1;
    }
  }
  std::cerr << "robozoo-experiment: " << written << " portable checkpoints written, " << removed << " removed, in "
            << dir << std::endl;
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  if (const std::optional<int> status = parse_command_line(argc, argv, o)) return *status;
  Experiment e;
  std::vector<bool> from_results;
  std::vector<std::string> from_portable;
  try {
    e = plan_experiment(o, from_results, from_portable);
  } catch (const std::exception& ex) {
    std::cerr << "robozoo-experiment: " << ex.what() << "\n";
    return 2;
  }
  if (o.status_only) {
    print_status(e);
    return 0;
  }
  if (!o.save_checkpoints_dir.empty()) return save_portable_checkpoints(e, from_portable, o.save_checkpoints_dir);
  // Both programs are checked before the folder is made: a refused start leaves nothing behind.
  if (!find_programs(o, e)) return 2;
  try {
    std::filesystem::create_directories(o.params.out_dir);
  } catch (const std::exception& ex) {
    std::cerr << "robozoo-experiment: " << ex.what() << "\n";
    return 2;
  }
  print_plan(e);
  bool results_ok = true;
  try {
    results_ok = write_missing_results(e, from_results, o.results_dir);
  } catch (const std::exception& ex) {
    std::cerr << "robozoo-experiment: " << ex.what() << "\n";
    return 2;
  }
  SignalBlock block;
  for (size_t i = 0; i < e.trials.size(); ++i) {
    if (e.status[i].state == TrialState::Finished) continue;
    if (const std::optional<int> status = run_trial(e, i, o, from_portable[i], block, results_ok)) return *status;
  }
  std::cerr << "robozoo-experiment: all " << e.trials.size() << " trials finished (robozoo-evolve time "
            << format_duration(e.totals().seconds_spent) << "), compact results in " << o.results_dir
            << ". Next: robozoo-stats " << o.params.out_dir << std::endl;
  return results_ok ? 0 : 1;
}
