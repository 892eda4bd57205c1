#pragma once
// Gathers ROBOZOO_* messages, one at a time, into RunRecords: the same code for
// logs (offline) and the bus (live). It never throws on bad input: a message
// that fails to decode (safe_decode), or whose sizes do not add up, is counted,
// described and skipped.
//
// Joining: messages of a run are ignored until its first ROBOZOO_RUN arrives
// (evolve repeats it every generation, so a late subscriber starts at the next
// generation).
//
// Pose streams: evolve publishes a champion's whole trajectory right after its
// genome and morphology, step 0 first and the last step last. A stream is
// complete when (a) a pose reaches run_t.steps, (b) the next ROBOZOO_RUN,
// ROBOZOO_GENERATION or ROBOZOO_GENOME of that run arrives (an early stop or a
// fault ends a trajectory before run_t.steps), (c) a pose of another genome of
// that run starts, or (d) the owner calls close_open_streams (end of a log; a
// quiet bus).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "runlog/read/run_record.hpp"

namespace robozoo {

struct CollectorOptions {
  bool keep_poses = true;    ///< store pose_t messages (live mode releases them after use)
  size_t max_problems = 20;  ///< problem descriptions kept (the counts are complete)
};

struct CollectorStats {
  int64_t messages = 0;               ///< all messages seen (count)
  int64_t accepted = 0;               ///< decoded, consistent and stored (count)
  int64_t before_run = 0;             ///< of a run whose ROBOZOO_RUN had not arrived yet: skipped (count)
  int64_t undecodable = 0;            ///< failed safe_decode (count)
  int64_t inconsistent = 0;           ///< decoded but sizes or values do not add up (count)
  int64_t orphans = 0;                ///< morphology or pose of a genome never seen (count)
  int64_t other_channels = 0;         ///< not a ROBOZOO_* channel, e.g. LCM_SELF_TEST (count)
  int64_t streams_completed = 0;      ///< pose streams closed (count)
  std::vector<std::string> problems;  ///< the first few problems, described
  int64_t rejected() const { return undecodable + inconsistent + orphans; }
};

class MessageCollector {
 public:
  /// Called when a champion's genome and morphology are both in.
  using ChampionFn = std::function<void(const RunRecord&, const GenomeRecord&)>;
  /// Called when a pose stream is complete (the record may be changed, e.g. to
  /// release its poses).
  using StreamFn = std::function<void(const RunRecord&, GenomeRecord&)>;
  /// Called after a ROBOZOO_RUN or ROBOZOO_GENERATION was stored (the latest
  /// one is run.run / run.generations.back()).
  using RunFn = std::function<void(const RunRecord&)>;
  /// Called after a pose was accepted into the genome's open stream (it is
  /// `pose`; stored in genome.poses too when poses are kept).
  using PoseFn = std::function<void(const RunRecord&, const GenomeRecord&, const pose_t&)>;

  explicit MessageCollector(CollectorOptions options = {});

  void on_champion(ChampionFn f) { on_champion_ = std::move(f); }
  void on_stream_complete(StreamFn f) { on_stream_ = std::move(f); }
  void on_run(RunFn f) { on_run_ = std::move(f); }
  void on_generation(RunFn f) { on_generation_ = std::move(f); }
  void on_pose(PoseFn f) { on_pose_ = std::move(f); }

  /// Takes one message; `source` names where it came from (log path, URL).
  /// Never throws: problems are counted in stats().
  void ingest(const std::string& channel, const void* data, size_t size, const std::string& source = "") noexcept;
  /// Completes every open pose stream (end of input, or a quiet bus).
  void close_open_streams() noexcept;
  /// True while some pose stream is open.
  bool has_open_stream() const;

  const std::vector<std::unique_ptr<RunRecord>>& runs() const { return runs_; }
  const CollectorStats& stats() const { return stats_; }

 private:
  void problem(int64_t& counter, const std::string& what);
  RunRecord* find_run(const std::string& run_id) const;
  void complete(RunRecord& run, GenomeRecord& g);
  void close_streams(RunRecord& run, const GenomeRecord* except);
  void handle_run(const void* data, size_t size, const std::string& source);
  void handle_generation(const void* data, size_t size);
  void handle_genome(const void* data, size_t size);
  void handle_morphology(const void* data, size_t size);
  void handle_pose(const void* data, size_t size);

  CollectorOptions options_;
  CollectorStats stats_;
  std::vector<std::unique_ptr<RunRecord>> runs_;
  ChampionFn on_champion_;
  StreamFn on_stream_;
  RunFn on_run_, on_generation_;
  PoseFn on_pose_;
};

/// Checks a morphology's internal consistency (parents, bodies, radii, finite
/// numbers, array sizes); returns "" when it is sound, else what is wrong.
std::string morphology_problem(const morphology_t& m);
/// Checks a pose against its robot's morphology; "" when it fits.
std::string pose_problem(const pose_t& p, const morphology_t& m);

}  // namespace robozoo
