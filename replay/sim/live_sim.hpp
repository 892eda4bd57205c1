#pragma once
// `robozoo-replay sim`: re-simulate one logged genome and publish its full-rate
// pose stream at real time, so that `robozoo-render live`
// can film a champion that was logged without poses.
//
// It first sends the run's latest ROBOZOO_RUN and the genome's ROBOZOO_GENOME
// as logged, and the ROBOZOO_MORPHOLOGY of the robot it grows (the model the
// poses belong to), then a ROBOZOO_POSE after every pose_every-th step (step 0
// and the last step always), each at its simulated time divided by --speed.
#include <cstdint>
#include <string>

#include "evolve/io/event_log.hpp"
#include "runlog/read/log_index.hpp"
#include "runlog/play/play_clock.hpp"

namespace robozoo::replay {

struct LiveSimOptions {
  int64_t genome_id = -1;  ///< the genome to re-simulate
  std::string run_id;      ///< its run; empty: the run of the last genome logged with that id
  double speed = 1.0;      ///< times real time (> 0)
  int pose_every = 1;      ///< publish every k-th step (count); 1: every step
  bool force = false;      ///< accept a run written by another software version
};

struct LiveSimStats {
  std::string run_id;
  int32_t generation = -1;
  int64_t poses_sent = 0;               ///< (count)
  int steps_run = 0;                    ///< physics steps simulated (count)
  bool simulated_in_evolution = false;  ///< the robot earned simulation (r term); otherwise simulated anyway
  double d = 0.0;                       ///< the re-simulation's d term (m)
  int64_t publish_failures = 0;
};

/// Throws std::invalid_argument with a clear message: unknown genome id (the
/// message lists the logged ones), no ROBOZOO_RUN for its run, a refused
/// version, an unusable configuration or genome, bad options.
LiveSimStats live_simulate(const LogContents& log, const LogIndex& index, const LiveSimOptions& options,
                           PlayClock& clock, const PublishFn& publish);

}  // namespace robozoo::replay
