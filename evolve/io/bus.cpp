#include "evolve/io/bus.hpp"

#include <stdexcept>

#include <lcm/lcm-cpp.hpp>

namespace robozoo {

Bus::Bus(const std::string& url) : url_(url), lcm_(std::make_unique<lcm::LCM>(url)) {
  if (!lcm_->good()) throw std::runtime_error("cannot start LCM on '" + url + "'");
}

Bus::~Bus() = default;

bool Bus::publish(const std::string& channel, const std::vector<uint8_t>& data) {
  const int rc = lcm_->publish(channel, data.data(), static_cast<unsigned int>(data.size()));
  if (rc != 0) ++failures_;
  return rc == 0;
}

lcm::LCM& Bus::lcm() { return *lcm_; }

}  // namespace robozoo
