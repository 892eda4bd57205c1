#pragma once
// What one page has yet to receive: a bounded queue of frames. The thread that
// reads the bus only ever pushes here (never waits for a page); the page's
// connection pops and writes at its own pace. When a slow page falls behind,
// the oldest poses are dropped first and counted; a page so far behind that
// even its other frames (generations, robots) pass their limit is marked
// overflowed, and its connection is closed.
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>

#include "view/state/frames.hpp"

namespace robozoo::view {

struct QueueLimits {
  size_t max_poses = 240;   ///< pose frames waiting, at most (count; about 10 s of a 25 Hz stream)
  size_t max_other = 4096;  ///< other frames waiting before the page is given up (count)
};

struct QueueCounters {
  int64_t pushed = 0;         ///< frames accepted (count)
  int64_t popped = 0;         ///< frames handed to the connection (count)
  int64_t dropped_poses = 0;  ///< pose frames dropped, oldest first (count)
  size_t waiting = 0;         ///< frames waiting now (count)
  size_t waiting_poses = 0;   ///< of which poses (count)
  bool overflowed = false;    ///< more than max_other other frames waited: the page is given up
};

class ClientQueue {
 public:
  explicit ClientQueue(QueueLimits limits = {}) : limits_(limits) {}
  /// Adds a frame; true when the writer must be woken: the queue was empty
  /// (it may be idle), or it just overflowed (it must close the connection).
  bool push(Frame f, bool is_pose);
  /// The oldest frame waiting, if any.
  std::optional<Frame> pop();
  QueueCounters counters() const;

 private:
  struct Entry {
    Frame frame;
    bool pose = false;
  };
  QueueLimits limits_;
  mutable std::mutex mutex_;
  std::deque<Entry> entries_;
  size_t poses_ = 0;
  QueueCounters counters_;
};

}  // namespace robozoo::view
