#include "evolve/io/bus.hpp"

#include <chrono>
#include <stdexcept>
#include <thread>

#include <lcm/lcm-cpp.hpp>

#include "evolve/io/event_log.hpp"

namespace robozoo {

Bus::Bus(const std::string& url) : url_(url), lcm_(std::make_unique<lcm::LCM>(url)) {
  if (!lcm_->good()) throw std::runtime_error("cannot start LCM on '" + url + "'");
}

Bus::~Bus() = default;

bool Bus::publish(const std::string& channel, const std::vector<uint8_t>& data, int64_t send_at_us) {
  for (int64_t wait = send_at_us - now_us(); wait > 0; wait = send_at_us - now_us())
    std::this_thread::sleep_for(std::chrono::microseconds(wait));
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
