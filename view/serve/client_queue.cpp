#include "view/serve/client_queue.hpp"

#include <algorithm>

namespace robozoo::view {

bool ClientQueue::push(Frame f, bool is_pose) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (counters_.overflowed) return false;
  const bool was_empty = entries_.empty();
  if (is_pose && poses_ >= limits_.max_poses) {
    if (limits_.max_poses == 0) {
      ++counters_.dropped_poses;
      return false;
    }
    const auto oldest = std::find_if(entries_.begin(), entries_.end(), [](const Entry& e) { return e.pose; });
    entries_.erase(oldest);
    --poses_;
    ++counters_.dropped_poses;
  }
  if (!is_pose && entries_.size() - poses_ >= limits_.max_other) {
    counters_.overflowed = true;
    entries_.clear();
    poses_ = 0;
    return true;  // wake the writer: it closes the connection
  }
  entries_.push_back({std::move(f), is_pose});
  poses_ += is_pose;
  ++counters_.pushed;
  return was_empty;
}

std::optional<Frame> ClientQueue::pop() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (entries_.empty()) return std::nullopt;
  Entry e = std::move(entries_.front());
  entries_.pop_front();
  poses_ -= e.pose;
  ++counters_.popped;
  return std::move(e.frame);
}

QueueCounters ClientQueue::counters() const {
  std::lock_guard<std::mutex> lock(mutex_);
  QueueCounters c = counters_;
  c.waiting = entries_.size();
  c.waiting_poses = poses_;
  return c;
}

}  // namespace robozoo::view
