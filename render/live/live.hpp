#pragma once
// Live mode: subscribe to the ROBOZOO_* channels of an LCM bus, keep
// OUT/latest.png showing the current champion and write one video per new
// champion, OUT/<run>_gen<G>_genome<ID>.mp4, when its pose stream completes.
//
// A subscriber that joins mid-run waits for the next ROBOZOO_RUN (evolve
// repeats it every generation) and works from there. Messages that fail to
// decode, or whose sizes do not add up, are counted, reported and skipped
// (MessageCollector); the LCM callback never throws. A pose stream is
// complete when its last step arrives, when the run's next message arrives,
// or after `stream_timeout` seconds without any message (the end of a run
// whose last champion stopped early). Drawing and encoding happen on a worker
// thread so the subscriber keeps reading the bus.
#include <functional>
#include <ostream>
#include <string>

#include "render/video/video.hpp"
#include "render/zoo/zoo_sheet.hpp"

namespace robozoo::render {

struct LiveOptions {
  std::string url;              ///< LCM URL
  std::string out_dir;          ///< where latest.png and the videos go (created if missing)
  double stream_timeout = 3.0;  ///< bus silence that completes an open pose stream (s)
  double idle_exit = 0.0;       ///< exit after this long without a message once a run was seen (s); 0: never
  ZooOptions picture;           ///< latest.png (cell size, fonts)
  VideoOptions video;           ///< the videos
};

struct LiveSummary {
  int64_t messages = 0, rejected = 0, before_run = 0;  ///< (count)
  int64_t runs = 0, champions = 0, streams = 0;        ///< (count)
  int64_t pictures = 0, videos = 0, failures = 0;      ///< (count)
};

/// Throws std::invalid_argument for bad options.
void validate(const LiveOptions& o);

/// Runs until `should_stop()` returns true (checked about every 100 ms) or the
/// idle exit; finishes the queued drawing before returning. One line per event
/// goes to `log`. Throws std::runtime_error when LCM cannot start on the URL or
/// the output folder cannot be made.
LiveSummary run_live(const LiveOptions& options, const std::function<bool()>& should_stop, std::ostream& log);

/// A file name made of safe characters ([A-Za-z0-9._-]; others become '_').
std::string safe_file_name(const std::string& s);

}  // namespace robozoo::render
