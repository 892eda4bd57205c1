#include "study/experiment/progress_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace robozoo {

ProgressEstimate estimate_progress(const ProgressTotals& t) {
  ProgressEstimate e;
  if (t.generations_total > 0)
    e.fraction = std::min(
        1.0, std::max(0.0, static_cast<double>(t.generations_done) / static_cast<double>(t.generations_total)));
  if (t.generations_done >= t.generations_total) {
    e.known = true;
    return e;
  }
  const int64_t timed = t.generations_done - t.generations_untimed;
  if (timed > 0 && t.seconds_spent > 0) {
    e.known = true;
    e.remaining_seconds =
        t.seconds_spent / static_cast<double>(timed) * static_cast<double>(t.generations_total - t.generations_done);
  }
  return e;
}

std::string format_duration(double seconds) {
  if (!(seconds >= 0)) seconds = 0;
  const auto s = static_cast<long long>(std::llround(seconds));
  char buf[64];
  if (s < 60)
    std::snprintf(buf, sizeof buf, "%llds", s);
  else if (s < 3600)
    std::snprintf(buf, sizeof buf, "%lldm%02llds", s / 60, s % 60);
  else if (s < 86400)
    std::snprintf(buf, sizeof buf, "%lldh%02lldm", s / 3600, (s % 3600) / 60);
  else
    std::snprintf(buf, sizeof buf, "%lldd%02lldh", s / 86400, (s % 86400) / 3600);
  return buf;
}

std::string format_clock(std::time_t when, std::time_t now) {
  std::tm w{}, n{};
  localtime_r(&when, &w);
  localtime_r(&now, &n);
  char buf[64];
  if (w.tm_year == n.tm_year && w.tm_yday == n.tm_yday)
    std::strftime(buf, sizeof buf, "%H:%M", &w);
  else
    std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M", &w);
  return buf;
}

}  // namespace robozoo
