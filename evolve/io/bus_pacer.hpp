#pragma once
// The timing of robozoo's messages: when each may go out on the bus, and so the
// time stamp it carries in the log (docs/method.md section 1).
//
// Two token buckets, both of which a message must pass. Bytes: a subscriber's
// socket buffer holds some 200 kB, so at most `burst_bytes` go out at once and
// `bytes_per_second` after that. Messages: LCM (1.3.1) keeps at most 31
// received but undispatched messages for each subscription (its default queue
// capacity of 30, which lcm-logger never changes) and drops whatever arrives
// while that queue is full, however small. So at most `burst_messages` go out at
// once and `messages_per_second` after that: a subscriber that stops dispatching
// for a while (a process starved of CPU) has `burst_messages + messages_per_second
// x pause` waiting when it resumes, which must stay under 31.
//
// The schedule is a pure function of the messages' sizes and the times they are
// ready: the log is stamped with it whether or not a bus is connected, so that
// lcm-logplayer replays a log with the spacing robozoo-evolve publishes it with.
#include <cstddef>
#include <cstdint>

namespace robozoo {

struct BusPacing {
  double bytes_per_second = 1e6;    ///< sustained byte rate (bytes/s); 0: no byte limit
  double burst_bytes = 64e3;        ///< bytes that may go out at once (bytes)
  double messages_per_second = 50;  ///< sustained message rate (messages/s); 0: no message limit
  double burst_messages = 1;        ///< messages that may go out at once (count, >= 1)
};

class BusPacer {
 public:
  /// Throws std::invalid_argument for a negative or non-finite rate or a burst
  /// below one message (or below 0 bytes).
  explicit BusPacer(BusPacing pacing = {});
  /// The time (us, on the caller's clock) at which a message of `bytes`, ready
  /// at `ready_us`, may go out after every message scheduled before it; the
  /// message is booked. Never earlier than `ready_us` nor than the message
  /// scheduled before it. A message larger than `burst_bytes` waits for a full
  /// byte bucket, and what it takes beyond that delays the next message.
  int64_t schedule(int64_t ready_us, size_t bytes);
  /// No message is scheduled before `us` (a resumed run's last stamp).
  void not_before(int64_t us);
  const BusPacing& pacing() const { return pacing_; }

 private:
  BusPacing pacing_;
  bool started_ = false;
  int64_t last_us_ = 0;  // when the last message was scheduled (us)
  double byte_tokens_ = 0;
  double message_tokens_ = 0;
};

}  // namespace robozoo
