#pragma once
// Live publishing on an LCM bus. Optional and lossy by nature (the log is the record).
#include <memory>
#include <string>
#include <vector>

namespace lcm { class LCM; }

namespace robozoo {

/// LCM's default URL: multicast that never leaves the host (ttl=0).
inline constexpr const char* kDefaultLcmUrl = "udpm://239.255.76.67:7667?ttl=0";

class Bus {
 public:
  /// Connects to `url`; throws std::runtime_error naming the URL if LCM cannot start.
  explicit Bus(const std::string& url);
  ~Bus();
  Bus(const Bus&) = delete;
  Bus& operator=(const Bus&) = delete;
  /// Publishes raw bytes; returns false (and counts it) when LCM reports a failure.
  bool publish(const std::string& channel, const std::vector<uint8_t>& data);
  int64_t failures() const { return failures_; }
  const std::string& url() const { return url_; }
  lcm::LCM& lcm();

 private:
  std::string url_;
  std::unique_ptr<lcm::LCM> lcm_;
  int64_t failures_ = 0;
};

}  // namespace robozoo
