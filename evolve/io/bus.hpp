#pragma once
// Live publishing on an LCM bus. Optional and lossy by nature (the log is the record).
#include <memory>
#include <string>
#include <vector>

namespace lcm { class LCM; }

namespace robozoo {

/// LCM's default URL: multicast that never leaves the host (ttl=0).
inline constexpr const char* kDefaultLcmUrl = "udpm://239.255.76.67:7667?ttl=0";

/// Messages LCM may hold for one of robozoo's subscriptions while its handler is
/// busy (lcm::Subscription::setQueueCapacity). LCM's default, 30, is some 40 ms of
/// a champion's pose stream: a busy machine lost poses (measured with robozoo-view).
inline constexpr int kSubscriberQueueMessages = 10000;

/// Pacing of live publishing: UDP multicast drops packets when a burst overflows
/// a subscriber's receive buffer (a champion's pose stream is ~1,000 messages at
/// once), so the bus sends at most `bytes_per_second` after a `burst_bytes` burst.
struct BusParams {
  double bytes_per_second = 1e6;  ///< sustained rate (bytes/s); 0: unpaced. With the default
                                  ///< 208 KiB socket buffer a subscriber may stall ~0.2 s
  double burst_bytes = 64e3;      ///< sent at once before pacing starts (bytes)
};

class Bus {
 public:
  /// Connects to `url`; throws std::runtime_error naming the URL if LCM cannot start.
  explicit Bus(const std::string& url, BusParams params = {});
  ~Bus();
  Bus(const Bus&) = delete;
  Bus& operator=(const Bus&) = delete;
  /// Publishes raw bytes; returns false (and counts it) when LCM reports a failure.
  bool publish(const std::string& channel, const std::vector<uint8_t>& data);
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
  BusParams params_;
  double tokens_ = 0;       // bytes that may be sent now
  double last_refill_ = 0;  // (s, steady clock)
};

}  // namespace robozoo
