#pragma once
// `robozoo-replay play`: republish a log on an LCM bus at real-time speed.
//
// Timing: an event goes out after the previous one by the gap between their
// log timestamps, divided by --speed. A champion's trajectory is logged in one
// burst (Evolution::publish_trajectory), so its poses are instead spaced by
// their simulated time: a viewer sees the robot move at real speed. The pass
// that follows is shifted by that much.
//
// State first: before the first pose of a genome in a pass, the player sends
// the latest ROBOZOO_RUN of its run and that genome's ROBOZOO_GENOME and
// ROBOZOO_MORPHOLOGY (looked up anywhere earlier in the log, also before
// --start-generation, and whatever --channels selects) unless they already
// went out in this pass, so that a viewer that joins can draw at once. In a
// log played from its start with every robozoo channel, they always have.
#include <cstdint>
#include <string>
#include <vector>

#include "evolve/io/event_log.hpp"
#include "runlog/read/log_index.hpp"
#include "runlog/play/play_clock.hpp"

namespace robozoo {

struct PlayOptions {
  double speed = 1.0;                   ///< playback speed, times real time (> 0)
  std::string channels = "ROBOZOO_.*";  ///< ECMAScript regex; a channel is played when it matches whole.
                                        ///< LCM_SELF_TEST is never played (every LCM instance sends its own)
  bool loop = false;                    ///< start again after the last event
  int max_passes = 0;                   ///< with loop: stop after this many passes, 0 = never (count)
  int32_t start_generation = 0;         ///< skip the events of earlier generations
  bool pace_poses_by_sim_time = true;   ///< space a trajectory's poses by their sim_time
};

/// One event to send in a pass.
struct PlannedEvent {
  size_t record = 0;   ///< index in LogContents::records
  double at = 0.0;     ///< time after the start of the pass (s of wall time, speed applied)
  bool state = false;  ///< sent by the state-first rule (not at its own place in the log)
};

/// The events of one pass, in sending order. Throws std::invalid_argument for a
/// bad regex or speed, a start generation the log does not reach, or when no
/// event is selected.
std::vector<PlannedEvent> plan_pass(const LogContents& log, const LogIndex& index, const PlayOptions& options);

struct PlayStats {
  int64_t passes = 0;             ///< (count)
  int64_t events_sent = 0;        ///< including state events (count)
  int64_t state_events_sent = 0;  ///< sent by the state-first rule (count)
  int64_t publish_failures = 0;   ///< (count)
};

/// Plays the plan once, or (loop) again and again, waiting on `clock`.
PlayStats play(const LogContents& log, const LogIndex& index, const PlayOptions& options, PlayClock& clock,
               const PublishFn& publish);

}  // namespace robozoo
