#pragma once
// The state robozoo-view keeps for its pages, fed one ROBOZOO_* message at a
// time (from the bus or a log) through the shared MessageCollector.
//
// - Which run: the first run seen, then any run whose ROBOZOO_RUN appears for
//   the first time later (a new run on the bus); pages start over with it.
// - What is shown: the genome whose pose stream started last (evolve streams
//   a champion's trajectory once per change of genes).
// - Champions: the run's distinct champions (NEAT's unchanged copies count once).
// - Joining: a page that joins gets, in one go under the state's lock, the
//   run, every generation so far, the champions, the robot shown and its poses
//   so far; then every frame that follows. Nothing is missed or doubled.
// - Pages never hold up ingest(): frames go to each page's bounded ClientQueue
//   (oldest poses dropped first) and its `wake` is called, which must not block.
// - Memory: live, the poses of the last `keep_streams` pose streams are kept
//   (replays of older champions re-simulate them); from a log, all of them.
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "runlog/read/message_collector.hpp"
#include "view/serve/client_queue.hpp"

namespace robozoo::view {

struct ViewStateOptions {
  QueueLimits queue;         ///< per page
  size_t keep_streams = 8;   ///< pose streams whose poses stay in memory (count); 0 = all
  int resimulate_every = 4;  ///< re-simulated replays keep every k-th step (count; evolve's default pose rate)
};

/// One connected page.
struct Client {
  int64_t id = 0;
  ClientQueue queue;
  std::function<void()> wake;  ///< called (under the state's lock) when the writer must look at the queue
  explicit Client(QueueLimits l) : queue(l) {}
};

struct ViewCounters {
  int64_t messages = 0;        ///< bus or log messages ingested (count)
  int64_t bad = 0;             ///< of which undecodable or inconsistent, skipped (count)
  int64_t generations = 0;     ///< generations of the shown run (count)
  int64_t champions = 0;       ///< distinct champions of the shown run (count)
  int64_t poses = 0;           ///< poses of the shown run broadcast (count)
  int64_t dropped_poses = 0;   ///< pose frames dropped for slow pages, all pages ever (count)
  int64_t pages = 0;           ///< pages connected now (count)
  int64_t pages_given_up = 0;  ///< pages closed because their queue overflowed (count)
  std::string run_id;          ///< the run shown
};

/// A replay a page asked for: the frames to send now, or a re-simulation to
/// run first (off every lock: it takes a fraction of a second).
struct ReplayPlan {
  std::vector<Frame> frames;               ///< ready: the robot, then its poses
  std::optional<run_t> run;                ///< to re-simulate: the run,
  std::optional<cppn_genome_t> genome;     ///< the genome
  std::optional<morphology_t> morphology;  ///< and its logged morphology (checked against the re-grown robot)
  std::string error;                       ///< set when the genome is unknown
};

class ViewState {
 public:
  /// `mode`: "live" or "log"; `source`: the URL or log path (shown on the page).
  ViewState(std::string mode, std::string source, ViewStateOptions options = {});

  /// One message; never throws (bad ones are counted in counters().bad).
  void ingest(const std::string& channel, const void* data, size_t size) noexcept;
  /// Ends every open pose stream (end of a log, a quiet bus).
  void end_of_input() noexcept;
  /// Forgets everything (a log played again with --loop); pages start over.
  void restart();
  /// While quiet, messages update the state but nothing goes to the pages
  /// (a log's first generations taken in at once); when it ends, every page
  /// gets the whole state again, as if it had just joined.
  void set_quiet(bool quiet);

  /// Registers a page: its queue gets the whole state first.
  std::shared_ptr<Client> join(std::function<void()> wake);
  void leave(const std::shared_ptr<Client>& client);

  /// What to send for a page's request to replay `genome_id`.
  ReplayPlan plan_replay(int64_t genome_id) const;
  /// Runs the re-simulation of a plan; returns the frames (robot, then poses) or
  /// throws what simulate_trajectory throws.
  std::vector<Frame> resimulate(const ReplayPlan& plan) const;

  /// A "stats" frame for one page.
  Frame stats_frame(const Client& client) const;
  ViewCounters counters() const;
  bool has_open_stream() const;

 private:
  void reset_run_locked();
  void broadcast_locked(const Frame& f, bool is_pose);
  void push_snapshot_locked(Client& c);
  void push_locked(Client& c, const Frame& f, bool is_pose);
  void handle_run(const RunRecord& run);
  void handle_generation(const RunRecord& run);
  void handle_champion(const RunRecord& run, const GenomeRecord& g);
  void handle_pose(const RunRecord& run, const GenomeRecord& g, const pose_t& p);
  void handle_stream_end(const RunRecord& run, GenomeRecord& g);
  void install_callbacks();

  std::string mode_, source_;
  ViewStateOptions options_;
  mutable std::mutex mutex_;
  std::unique_ptr<MessageCollector> collector_;
  std::string run_id_;
  nlohmann::json run_frame_;  ///< null until a run is seen
  std::vector<nlohmann::json> history_;
  std::vector<nlohmann::json> champions_;
  uint64_t last_champion_genes_ = 0;
  bool have_champion_ = false;
  int64_t shown_id_ = -1;
  nlohmann::json robot_frame_;  ///< null until a robot is shown
  nlohmann::json shown_poses_ = nlohmann::json::array();
  bool shown_done_ = false;
  std::vector<GenomeRecord*> completed_;  ///< streams with poses kept, oldest first
  std::vector<std::shared_ptr<Client>> clients_;
  int64_t next_client_ = 1;
  bool quiet_ = false;
  int64_t poses_ = 0, dropped_by_departed_ = 0, given_up_ = 0;
};

}  // namespace robozoo::view
