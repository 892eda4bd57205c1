#pragma once
// The clock that paces `play` and `sim`: real time for the program, a fake one
// in tests (so that no test sleeps or times anything).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace robozoo {

class PlayClock {
 public:
  virtual ~PlayClock() = default;
  /// Seconds since some fixed origin (s).
  virtual double now() = 0;
  /// Returns once now() >= t (s); at once when t is in the past.
  virtual void sleep_until(double t) = 0;
};

/// std::chrono::steady_clock.
class SteadyPlayClock : public PlayClock {
 public:
  double now() override;
  void sleep_until(double t) override;
};

/// Where played events go: (channel, bytes); returns false when sending failed.
using PublishFn = std::function<bool(const std::string& channel, const std::vector<uint8_t>& data)>;

}  // namespace robozoo
