#pragma once
// What a robozoo log holds, found in one pass: the runs, every logged genome
// (champions first of all) with its morphology and poses, and every event that
// could not be used. Bytes are decoded with safe_decode only; nothing here
// throws on bad input, it is reported in `problems`.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "evolve/io/event_log.hpp"

namespace robozoo {

enum class EventKind : int8_t {
  Run,          ///< ROBOZOO_RUN
  Generation,   ///< ROBOZOO_GENERATION
  Genome,       ///< ROBOZOO_GENOME
  Morphology,   ///< ROBOZOO_MORPHOLOGY
  Pose,         ///< ROBOZOO_POSE
  Foreign,      ///< a channel robozoo does not own (LCM_SELF_TEST, others): ignored
  Undecodable,  ///< a robozoo channel whose bytes are not its type (reported in problems)
};

/// One event of the log with the fields replay needs to find its way.
struct IndexedEvent {
  size_t record = 0;  ///< index in LogContents::records
  EventKind kind = EventKind::Foreign;
  std::string run_id;       ///< robozoo kinds
  int32_t generation = -1;  ///< Generation, Genome, Morphology, Pose
  int64_t genome_id = -1;   ///< Genome, Morphology, Pose; Generation: the champion's id
  int32_t step = -1;        ///< Pose: physics step (count)
  double sim_time = 0.0;    ///< Pose: simulated time (s)
};

/// A genome message with the morphology and poses logged for it.
struct LoggedGenome {
  std::string run_id;
  int32_t generation = -1;
  int64_t genome_id = -1;
  size_t genome_event = 0;          ///< index in LogIndex::events
  int64_t run_event = -1;           ///< the latest ROBOZOO_RUN of its run before it, -1 if none
  int64_t morphology_event = -1;    ///< its ROBOZOO_MORPHOLOGY, -1 if none was logged
  std::vector<size_t> pose_events;  ///< its ROBOZOO_POSEs, in log order
  bool champion = false;            ///< named by its generation's generation_t, or no generation_t logged
};

/// An event replay could not use.
struct InputProblem {
  int64_t event = -1;     ///< index in LogIndex::events, -1 for the log as a whole
  int64_t eventnum = -1;  ///< the event's number in the log, -1 if none
  std::string channel;
  std::string what;  ///< one sentence
};

struct LogIndex {
  std::vector<IndexedEvent> events;   ///< every event, in log order
  std::vector<LoggedGenome> genomes;  ///< in log order of their genome messages
  std::vector<size_t> run_events;     ///< every ROBOZOO_RUN event
  std::vector<InputProblem> problems;
  size_t foreign_events = 0;  ///< events of channels robozoo does not own (count)
  /// Champions only (or every genome with `all`), in log order.
  std::vector<const LoggedGenome*> to_check(bool all) const;
  /// The genome logged last with this id (in `run_id` when not empty); nullptr if none.
  const LoggedGenome* find_genome(int64_t genome_id, const std::string& run_id = "") const;
};

/// Builds the index. Poses and morphologies attach to the latest genome message
/// of the same run and genome id before them; those without one are problems.
LogIndex index_log(const LogContents& log);

/// Channel name -> kind (Foreign for channels robozoo does not own).
EventKind kind_of_channel(const std::string& channel);

}  // namespace robozoo
