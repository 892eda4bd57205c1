#pragma once
// robozoo-view LOG: plays a finished or growing log into the view.
//
// The log is played as robozoo-replay play plays it (plan_pass/play: events
// spaced by their log timestamps over --speed, a champion's poses by their
// simulated time, so the robot moves at real speed). With --generation G the
// generations before G are taken in at once (the chart starts with them) and
// playing starts at G. At the end: --loop starts again (the pages start over),
// --follow waits for the log to grow and plays what is appended (poses at real
// speed, the rest as it comes), else the last state stays on show.
#include <functional>
#include <ostream>
#include <string>

#include "view/state/view_state.hpp"

namespace robozoo::view {

struct LogFeedOptions {
  std::string path;
  double speed = 1.0;         ///< times real time (> 0)
  bool loop = false;          ///< play again from the start at the end
  bool follow = false;        ///< at the end, play what is appended to the log
  int32_t generation = 0;     ///< start playing at this generation
  double poll_seconds = 0.5;  ///< --follow: look for new events this often (s)
  bool exit_at_end = false;   ///< return at the end of the log (tests, measurements)
};

/// Plays until `should_stop()` (checked about every 100 ms). Throws
/// std::runtime_error or std::invalid_argument for an unreadable log or bad options.
void play_log(const LogFeedOptions& options, ViewState& state, const std::function<bool()>& should_stop,
              std::ostream& log);

}  // namespace robozoo::view
