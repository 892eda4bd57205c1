#include "runlog/play/play_clock.hpp"

#include <chrono>
#include <thread>

namespace robozoo {

double SteadyPlayClock::now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void SteadyPlayClock::sleep_until(double t) {
  const double wait = t - now();
  if (wait > 0) std::this_thread::sleep_for(std::chrono::duration<double>(wait));
}

}  // namespace robozoo
