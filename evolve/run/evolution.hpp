#pragma once
// The evolution process of robozoo-evolve: CPPN-NEAT on directed
// displacement, every event written to the run's LCM log and, when live, to
// the bus; a checkpoint after every generation.
#include <functional>
#include <future>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

#include "evolve/config/run_config.hpp"
#include "evolve/core/rng.hpp"
#include "evolve/io/bus.hpp"
#include "evolve/io/bus_pacer.hpp"
#include "evolve/io/event_log.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/neat/population.hpp"
#include "evolve/record/checkpoint.hpp"
#include "evolve/record/checkpoint_writer.hpp"
#include "evolve/run/evaluator.hpp"

namespace robozoo {

struct EvolveOptions {
  std::string run_id;                    ///< empty: "<regime>-s<seed>"
  std::string log_path;                  ///< the run's LCM log
  std::string checkpoint_path;           ///< empty: checkpoint_path_for(log_path)
  std::string lcm_url;                   ///< empty: no live publishing
  BusPacing bus_pacing;                  ///< when messages go out on the bus, and so their time stamps in the
                                         ///< log, bus or not (BusPacer)
  bool resume = false;                   ///< continue from the checkpoint
  std::optional<Checkpoint> checkpoint;  ///< with resume: the checkpoint, already read by the caller
                                         ///< (empty: read from checkpoint_path when it exists)
  bool force_version = false;            ///< resume a checkpoint written by another robozoo version anyway
  int32_t generations = 0;               ///< with resume: run to this many generations, at least the checkpoint's
                                         ///< (count; 0: the checkpoint's). More extends the run, finished or not,
                                         ///< to what an uninterrupted run of that many generations logs.
  bool background_checkpoint = false;    ///< write each generation's checkpoint on a thread while the
                                         ///< next generation is evaluated (robozoo-evolve --mpi: rank 0's
                                         ///< largest serial cost); a failed write is reported one
                                         ///< generation later, the last one before run() returns
  bool overlap_trajectory = false;       ///< re-simulate a new champion for its pose stream on a thread
                                         ///< while the next generation is evaluated (robozoo-evolve --mpi:
                                         ///< rank 0 waits for the workers then); its poses, then its
                                         ///< generation's checkpoint, are written once that evaluation
                                         ///< returns. The log holds the same messages in the same order.
                                         ///< Only with an evaluator that does not simulate in this
                                         ///< process (Evaluator::simulates_in_process; else the
                                         ///< constructor throws std::invalid_argument).
};

/// Where the evolution process's time went in one generation (s): the serial part
/// of a run, which more workers (or MPI ranks) do not shorten.
struct StepTimings {
  double evaluate = 0.0;          ///< waiting for the evaluator's results (s)
  double messages = 0.0;          ///< building, logging and publishing the run, generation, genome and
                                  ///< morphology messages, growing the published genomes' robots (s)
  double trajectory = 0.0;        ///< re-simulating a new champion and logging its poses (s)
  double breeding = 0.0;          ///< selection, speciation and reproduction: Population::advance (s)
  double checkpoint = 0.0;        ///< syncing the log to disk and writing the checkpoint (s)
  double final_checkpoint = 0.0;  ///< the run's last generation only: waiting until its last checkpoint,
                                  ///< written in the background, is on disk (s; once a run)
  double total = 0.0;             ///< the whole generation, evaluation and final_checkpoint included (s)
  /// Rank 0's serial part of a generation: all but the evaluation and the
  /// once-a-run final wait (s).
  double serial() const { return total - evaluate - final_checkpoint; }
};

/// What happened in one generation (for progress output and tests).
struct ProgressReport {
  GenerationSummary summary;
  int32_t generations_total = 0;
  double evals_per_second = 0.0;
  double elapsed_seconds = 0.0;
  double remaining_seconds = 0.0;  ///< estimate
  double simulated_share = 0.0;    ///< share of robots sent to the simulator
  StepTimings timings;             ///< where this generation's time went
  /// Live publishing so far (-1 each when the run does not publish): messages
  /// LCM accepted and refused (count).
  int64_t messages_published = -1;
  int64_t publish_failures = -1;
};

/// One line of progress for a generation.
std::string format_progress(const ProgressReport& r);

/// Default run id of a configuration.
std::string default_run_id(const RunConfig& c);

class Evolution {
 public:
  /// Starts a run, or (options.resume) continues one from its checkpoint; the
  /// configuration then comes from the checkpoint and `config` must match it.
  /// Throws std::runtime_error with a clear message on unusable files.
  Evolution(const RunConfig& config, const EvolveOptions& options, Evaluator& evaluator);
  ~Evolution();

  /// Runs the remaining generations; calls `on_generation` after each.
  void run(const std::function<void(const ProgressReport&)>& on_generation = {});
  /// Runs one generation; returns false when the run is already complete.
  bool step(const std::function<void(const ProgressReport&)>& on_generation = {});

  bool finished() const { return finished_; }
  int generation() const;
  const std::string& run_id() const { return run_id_; }
  const std::string& checkpoint_path() const { return checkpoint_path_; }
  const RunConfig& config() const { return config_; }
  /// True when the constructor resumed from a checkpoint.
  bool resumed() const { return resumed_; }
  /// The generation the run started or resumed at in this process (count).
  int start_generation() const { return start_generation_; }
  /// Genome evaluations of the whole run so far, and those made in this process (count).
  int64_t evaluations() const { return evaluations_; }
  int64_t evaluations_this_process() const { return evaluations_ - start_evaluations_; }
  /// Live publishing in this process (count); -1 each without --lcm-url.
  int64_t messages_published() const;
  int64_t publish_failures() const;
  /// Finished generations held by the checkpoint on disk, written in full
  /// (thread-safe: for a signal watcher). With background_checkpoint the last
  /// generation's checkpoint may still be on its way.
  int checkpointed_generations() const { return checkpoint_writer_->generations_written(); }
  /// Waits for a checkpoint being written in the background (first writing
  /// one held back, if any); rethrows its failure. Quick, for a run that is
  /// failing: a generation whose champion's poses are still being simulated
  /// (overlap_trajectory) is left out of the checkpoint, and redone on resume.
  void wait_for_checkpoint();
  /// For a run stopped between generations on purpose: finishes what the last
  /// generation left running (its champion's poses, then its checkpoint), then
  /// waits like wait_for_checkpoint.
  void settle();

 private:
  void emit(const char* channel, const std::vector<uint8_t>& bytes, int64_t utime);
  /// Stamps `m` (utime) with its time on the bus (BusPacer), then emits it.
  template <class M>
  void emit_message(const char* channel, M m);
  void save_checkpoint();
  /// overlap_trajectory: writes the previous generation's poses once its
  /// re-simulation ends, then that generation's checkpoint (s spent waiting and writing).
  double finish_trajectory();
  /// The log synced and the run's state as a checkpoint (not written).
  Checkpoint make_checkpoint();
  /// Writes the checkpoint finish_trajectory held back, if any.
  void write_held_checkpoint();
  /// Logs and publishes a trajectory's poses.
  void emit_poses(std::vector<pose_t>& poses);
  int generations_done() const;  ///< finished generations: what a checkpoint now would hold
  /// Re-simulates a new champion (`robot`: grown from it once, for its
  /// morphology message too): its pose messages (utime 0, set when sent),
  /// after checking that the simulation is exactly the worker's evaluation.
  std::vector<pose_t> champion_trajectory(const Genome& champion, const Robot& robot, int32_t generation,
                                          const EvalSummary& expected) const;

  // The steps of step(), in order.
  /// The published genomes of a generation (the champion first; all with publish_all), with their
  /// species ids and grown robots.
  struct Published {
    std::vector<size_t> index;
    std::vector<int32_t> species_ids;
    std::vector<Robot> robots;
  };
  /// Logs the run message and evaluates the genomes (timing.evaluate); with the previous
  /// generation's champion still simulating, its poses go first. One result per genome.
  std::vector<EvalSummary> evaluate_generation(const std::vector<Genome>& genomes, StepTimings& timing);
  Published grow_published(const std::vector<Genome>& genomes, size_t champ) const;
  /// A champion whose genes changed: its trajectory's poses now, or (overlap_trajectory, not the
  /// last generation) started on a thread for finish_trajectory; empty otherwise.
  std::vector<pose_t> new_champion_poses(const Genome& champion, const Robot& robot, int32_t gen,
                                         const EvalSummary& result, bool last);
  /// The generation, genome and morphology messages.
  void emit_generation(const GenerationSummary& s, const std::vector<Genome>& genomes,
                       const std::vector<EvalSummary>& results, const Published& published);
  /// ROBOZOO_BUS: how publishing went (bus only).
  void publish_bus_status(int32_t gen);
  /// The generation's checkpoint (or the held one while its poses simulate); a finished run's is
  /// waited for.
  void checkpoint_step(StepTimings& timing);

  RunConfig config_;
  EvolveOptions options_;
  Evaluator& evaluator_;
  std::string run_id_;
  std::string checkpoint_path_;
  Rng rng_;
  std::unique_ptr<Population> population_;
  std::optional<EventLogWriter> log_;
  std::unique_ptr<Bus> bus_;
  BusPacer pacer_;  // every message's time on the bus and in the log
  std::unique_ptr<CheckpointWriter> checkpoint_writer_;
  int64_t evaluations_ = 0;
  int64_t start_evaluations_ = 0;  // evaluations_ when this process took the run over
  int start_generation_ = 0;
  int64_t bus_statuses_ = 0;  // ROBOZOO_BUS messages sent (not counted as published run messages)
  int64_t bus_status_bytes_ = 0;
  double best_so_far_ = 0.0;
  uint64_t last_champion_hash_ = 0;               // content hash (id aside) of the last champion
  std::optional<LogContinuation> log_continues_;  // the log begins at a later generation (checkpoint.hpp)
  double elapsed_before_ = 0.0;                   // from earlier sessions of a resumed run
  double elapsed_ = 0.0;
  bool finished_ = false;
  bool resumed_ = false;
  std::future<std::vector<pose_t>> pending_poses_;  // overlap_trajectory: the last generation's, simulating
  std::optional<Checkpoint> held_checkpoint_;       // the last generation's, once its poses were logged
  int held_generations_ = 0;                        // finished generations it holds
};

}  // namespace robozoo
