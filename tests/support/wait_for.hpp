#pragma once
// Test support: polling for something another process or thread makes happen.
#include <chrono>
#include <thread>

namespace robozoo::testing {

/// Waits until `pred()` holds, polling every `poll_ms`, at most `seconds`; false on timeout.
template <class Pred>
bool wait_for(Pred pred, double seconds, int poll_ms = 100) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(poll_ms));
  }
  return pred();
}

}  // namespace robozoo::testing
