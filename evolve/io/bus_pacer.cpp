#include "evolve/io/bus_pacer.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace robozoo {

BusPacer::BusPacer(BusPacing pacing) : pacing_(pacing) {
  const auto bad = [](double v) { return !std::isfinite(v) || v < 0; };
  if (bad(pacing_.bytes_per_second) || bad(pacing_.messages_per_second))
    throw std::invalid_argument("bus rates must be finite and not negative");
  if (bad(pacing_.burst_bytes) || !std::isfinite(pacing_.burst_messages) || pacing_.burst_messages < 1)
    throw std::invalid_argument("a bus burst must be at least one message and not negative bytes");
  byte_tokens_ = pacing_.burst_bytes;
  message_tokens_ = pacing_.burst_messages;
}

int64_t BusPacer::schedule(int64_t ready_us, size_t bytes) {
  int64_t t = started_ ? std::max(ready_us, last_us_) : ready_us;
  const auto refill = [&](int64_t to) {
    const double dt = started_ ? static_cast<double>(to - last_us_) * 1e-6 : 0.0;
    byte_tokens_ = std::min(pacing_.burst_bytes, byte_tokens_ + dt * pacing_.bytes_per_second);
    message_tokens_ = std::min(pacing_.burst_messages, message_tokens_ + dt * pacing_.messages_per_second);
  };
  refill(t);
  const double need = std::min(static_cast<double>(bytes), pacing_.burst_bytes);
  double wait_s = 0;
  if (pacing_.bytes_per_second > 0 && byte_tokens_ < need)
    wait_s = std::max(wait_s, (need - byte_tokens_) / pacing_.bytes_per_second);
  if (pacing_.messages_per_second > 0 && message_tokens_ < 1)
    wait_s = std::max(wait_s, (1 - message_tokens_) / pacing_.messages_per_second);
  if (wait_s > 0) {
    const int64_t before = t;
    t += static_cast<int64_t>(std::ceil(wait_s * 1e6 - 1e-6));  // whole microseconds, rounding noise aside
    last_us_ = before;                                          // refill from the moment the tokens were counted
    started_ = true;
    refill(t);
  }
  if (pacing_.bytes_per_second > 0) byte_tokens_ -= static_cast<double>(bytes);
  if (pacing_.messages_per_second > 0) message_tokens_ -= 1;
  last_us_ = t;
  started_ = true;
  return t;
}

void BusPacer::not_before(int64_t us) {
  if (started_ && us <= last_us_) return;
  last_us_ = us;  // the buckets stay as they are (full before the first message)
  started_ = true;
}

}  // namespace robozoo
