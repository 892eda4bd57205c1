#include "evolve/parallel/scaling_model.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <queue>
#include <stdexcept>
#include <utility>

namespace robozoo {

double list_schedule_makespan(const std::vector<double>& durations, int workers) {
  if (workers < 1) throw std::invalid_argument("list_schedule_makespan: need at least 1 worker");
  // (time the worker becomes free, worker): the first free takes the next job.
  using Free = std::pair<double, int>;
  std::priority_queue<Free, std::vector<Free>, std::greater<Free>> free;
  for (int w = 0; w < workers; ++w) free.push({0.0, w});
  double makespan = 0.0;
  for (const double d : durations) {
    if (!(d >= 0.0) || !std::isfinite(d))
      throw std::invalid_argument("list_schedule_makespan: durations must be finite and >= 0");
    const Free f = free.top();
    free.pop();
    const double end = f.first + d;
    makespan = std::max(makespan, end);
    free.push({end, f.second});
  }
  return makespan;
}

GenerationProjection project_generation(const GenerationCost& cost, int workers, const ClusterParams& cluster) {
  if (workers < 1) throw std::invalid_argument("project_generation: need at least 1 worker");
  if (cost.job_bytes.size() != cost.job_seconds.size())
    throw std::invalid_argument("project_generation: job_bytes and job_seconds differ in length");
  auto positive = [](double x) { return x > 0.0 && std::isfinite(x); };
  if (!positive(cluster.bandwidth_bytes_per_s) || !positive(cluster.core_speed) || !(cluster.latency_s >= 0.0) ||
      !std::isfinite(cluster.latency_s))
    throw std::invalid_argument("project_generation: latency must be >= 0, bandwidth and core speed > 0");
  if (!(cost.serial_seconds >= 0.0) || !(cost.root_seconds_per_job >= 0.0))
    throw std::invalid_argument("project_generation: negative rank-0 times");
  std::vector<double> occupied(cost.job_seconds.size());
  double bytes = 0.0;
  for (size_t i = 0; i < occupied.size(); ++i) {
    occupied[i] = cost.job_seconds[i] / cluster.core_speed + 2.0 * cluster.latency_s +
                  cost.job_bytes[i] / cluster.bandwidth_bytes_per_s;
    bytes += cost.job_bytes[i];
  }
  GenerationProjection p;
  p.workers = list_schedule_makespan(occupied, workers);
  p.root_link =
      static_cast<double>(occupied.size()) * cost.root_seconds_per_job + bytes / cluster.bandwidth_bytes_per_s;
  p.serial = cost.serial_seconds;
  p.seconds = p.serial + std::max(p.workers, p.root_link);
  if (p.serial > std::max(p.workers, p.root_link))
    p.bound = "rank 0 serial";
  else
    p.bound = p.workers >= p.root_link ? "evaluations" : "rank 0 messaging";
  return p;
}

}  // namespace robozoo
