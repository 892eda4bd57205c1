#pragma once
// robozoo-view --lcm-url: follows a live run on an LCM bus. The subscriber's
// thread only ingests (ViewState never waits for a page), so the bus is read
// as fast as it arrives.
#include <functional>
#include <ostream>
#include <string>

#include "evolve/io/bus.hpp"
#include "view/state/view_state.hpp"

namespace robozoo::view {

struct BusFeedOptions {
  std::string url;              ///< LCM URL
  double stream_timeout = 3.0;  ///< a pose stream is over after this long without a message (s)
  double idle_exit = 0.0;       ///< once a run was seen, return after this long without a message (s); 0 = never
  int queue_messages =
      kSubscriberQueueMessages;  ///< messages LCM may hold while ingest() is busy, beyond them it drops
                                 ///< (count; about 10 s of evolve's paced 1 MB/s)
};

/// Reads the bus until `should_stop()` (checked about every 100 ms) or the idle
/// exit; says what it joins and what it skips on `log`. Throws
/// std::runtime_error naming the URL when LCM cannot start or stops reading.
void follow_bus(const BusFeedOptions& options, ViewState& state, const std::function<bool()>& should_stop,
                std::ostream& log);

}  // namespace robozoo::view
