#pragma once
// Live publishing on an LCM bus. Optional and lossy by nature (the log is the record).
// When each message goes out is BusPacer's schedule (evolve/io/bus_pacer.hpp).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace lcm {
class LCM;
}

namespace robozoo {

/// LCM's default URL: multicast that never leaves the host (ttl=0).
inline constexpr const char* kDefaultLcmUrl = "udpm://239.255.76.67:7667?ttl=0";

/// Messages LCM may hold for one of robozoo's subscriptions while its handler is
/// busy (lcm::Subscription::setQueueCapacity). LCM's default, 30, is some 40 ms of
/// a champion's pose stream: a busy machine lost poses (measured with robozoo-view).
inline constexpr int kSubscriberQueueMessages = 10000;

class Bus {
 public:
  /// Connects to `url`; throws std::runtime_error naming the URL if LCM cannot start.
  explicit Bus(const std::string& url);
  ~Bus();
  Bus(const Bus&) = delete;
  Bus& operator=(const Bus&) = delete;
  /// Waits until `send_at_us` (us since the Unix epoch, the clock of now_us();
  /// 0 or a past time: at once), then publishes raw bytes; returns false (and
  /// counts it) when LCM reports a failure.
  bool publish(const std::string& channel, const std::vector<uint8_t>& data, int64_t send_at_us = 0);
  int64_t failures() const { return failures_; }    ///< messages LCM refused (count)
  int64_t published() const { return published_; }  ///< messages LCM accepted (count)
  int64_t bytes() const { return bytes_; }          ///< their payload bytes (bytes)
  const std::string& url() const { return url_; }
  lcm::LCM& lcm();

 private:
  std::string url_;
  std::unique_ptr<lcm::LCM> lcm_;
  int64_t failures_ = 0;
  int64_t published_ = 0;
  int64_t bytes_ = 0;
};

}  // namespace robozoo
