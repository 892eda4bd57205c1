#pragma once
// Progress of a whole experiment and an estimate of when it will finish.
//
// The estimate divides the wall time robozoo-evolve has spent on the
// experiment's trials (their checkpoints' elapsed_seconds, or their compact
// results' evolve_seconds) by the generations it was spent on, and multiplies by
// the generations left. Generations done whose time is unknown (a compact result
// without it) count as done, but not towards the time per generation. Later generations of a
// run cost more than early ones (more robots earn simulation), so the estimate
// is low until the first trials have finished; trials run seed by seed, so it
// settles after the first pair.
#include <cstdint>
#include <ctime>
#include <string>

namespace robozoo {

struct ProgressTotals {
  int64_t generations_total = 0;    ///< generations of every trial (count)
  int64_t generations_done = 0;     ///< finished generations (count)
  double seconds_spent = 0;         ///< robozoo-evolve's wall time on those generations (s)
  int64_t generations_untimed = 0;  ///< of generations_done, those seconds_spent leaves out (count)
};

struct ProgressEstimate {
  double fraction = 0;           ///< done / total, in [0, 1]
  bool known = false;            ///< an estimate exists (some generation finished, some time spent)
  double remaining_seconds = 0;  ///< estimated wall time left (s), when known
};

ProgressEstimate estimate_progress(const ProgressTotals& t);

/// "45s", "12m05s", "3h07m", "2d04h".
std::string format_duration(double seconds);
/// Local clock time of `when`: "23:45" on the day of `now`, "2024-05-02 01:10" on another day.
std::string format_clock(std::time_t when, std::time_t now);

}  // namespace robozoo
