#include "evolve/io/bus.hpp"

#include <chrono>
#include <stdexcept>
#include <thread>

#include <lcm/lcm-cpp.hpp>

namespace robozoo {

namespace {
double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

Bus::Bus(const std::string& url, BusParams params)
    : url_(url), lcm_(std::make_unique<lcm::LCM>(url)), params_(params) {
  if (!lcm_->good()) throw std::runtime_error("cannot start LCM on '" + url + "'");
  tokens_ = params_.burst_bytes;
  last_refill_ = now_s();
}

Bus::~Bus() = default;

bool Bus::publish(const std::string& channel, const std::vector<uint8_t>& data) {
  if (params_.bytes_per_second > 0) {
    const double need = static_cast<double>(data.size());
    for (;;) {
      const double t = now_s();
      tokens_ = std::min(params_.burst_bytes, tokens_ + (t - last_refill_) * params_.bytes_per_second);
      last_refill_ = t;
      if (tokens_ >= std::min(need, params_.burst_bytes)) break;
      std::this_thread::sleep_for(std::chrono::duration<double>(
          (std::min(need, params_.burst_bytes) - tokens_) / params_.bytes_per_second));
    }
    tokens_ -= need;
  }
  const int rc = lcm_->publish(channel, data.data(), static_cast<unsigned int>(data.size()));
  if (rc != 0) {
    ++failures_;
    return false;
  }
  ++published_;
  bytes_ += static_cast<int64_t>(data.size());
  return true;
}

lcm::LCM& Bus::lcm() { return *lcm_; }

}  // namespace robozoo
