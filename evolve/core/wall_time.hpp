#pragma once
// Wall-clock seconds since a moment, for progress lines and timings robozoo
// reports. Never part of a result.
#include <chrono>

namespace robozoo {

/// Seconds of wall time since t0 (steady clock).
inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace robozoo
