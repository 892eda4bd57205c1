#pragma once
// A play clock for tests: it moves only when asked to wait, so tests never sleep,
// and it records every time it was asked to wait until.
#include <vector>

#include "runlog/play/play_clock.hpp"

namespace robozoo::testing {

struct FakeClock : PlayClock {
  explicit FakeClock(double start) : t(start) {}
  double t;                   ///< now, in seconds
  std::vector<double> waits;  ///< every sleep_until, in order
  double now() override { return t; }
  void sleep_until(double until) override {
    waits.push_back(until);
    if (until > t) t = until;
  }
};

}  // namespace robozoo::testing
