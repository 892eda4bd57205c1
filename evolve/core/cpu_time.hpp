#pragma once
// CPU time of the calling thread, for the timings robozoo reports (the CPPN's
// share of an evaluation, benchmarks): the machine may be shared, and wall time
// would count the time other processes hold the core. Never part of a result.
#include <ctime>

namespace robozoo {

/// Seconds of CPU time the calling thread has used.
inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace robozoo
