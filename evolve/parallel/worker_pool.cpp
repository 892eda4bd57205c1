#include "evolve/parallel/worker_pool.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <limits>

namespace robozoo {

struct WorkerPool::MapRun {
  const std::vector<Bytes>& jobs;
  std::vector<Bytes> results;
  std::vector<char> done;
  std::vector<int> failures;   ///< attempts that killed a worker, per job
  std::deque<size_t> pending;  ///< jobs waiting for a worker, next first
  size_t remaining = 0;        ///< jobs without a result

  explicit MapRun(const std::vector<Bytes>& j)
      : jobs(j), results(j.size()), done(j.size(), 0), failures(j.size(), 0), remaining(j.size()) {
    for (size_t i = 0; i < j.size(); ++i) pending.push_back(i);
  }
};

WorkerPool::WorkerPool(int workers, WorkFn fn, PoolParams params) : params_(params) {
  validate();
  if (workers < 1) throw std::invalid_argument("WorkerPool: need at least 1 worker, got " + std::to_string(workers));
  transport_ = std::make_unique<PipeTransport>(workers, std::move(fn), params_.pipe);
  slots_.resize(static_cast<size_t>(workers));
}

WorkerPool::WorkerPool(std::unique_ptr<Transport> transport, PoolParams params)
    : transport_(std::move(transport)), params_(params) {
  validate();
  if (!transport_) throw std::invalid_argument("WorkerPool: no transport");
  if (transport_->size() < 1) throw std::invalid_argument("WorkerPool: transport has no workers");
  slots_.resize(static_cast<size_t>(transport_->size()));
}

WorkerPool::~WorkerPool() = default;

void WorkerPool::validate() const {
  if (std::isnan(params_.job_timeout_s) || params_.job_timeout_s <= 0.0)
    throw std::invalid_argument("WorkerPool: job_timeout_s must be > 0 (or +infinity), got " +
                                std::to_string(params_.job_timeout_s));
  if (params_.max_attempts < 1)
    throw std::invalid_argument("WorkerPool: max_attempts must be >= 1, got " + std::to_string(params_.max_attempts));
}

double WorkerPool::now() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void WorkerPool::restart(int w) {
  try {
    transport_->restart(w);
  } catch (const std::exception& e) {
    broken_ = true;
    broken_reason_ = "worker " + std::to_string(w) + " could not be replaced: " + e.what();
    throw PoolError("WorkerPool: " + broken_reason_);
  }
  ++stats_.restarts;
  slots_[static_cast<size_t>(w)].state = State::Idle;
}

std::vector<Bytes> WorkerPool::map(const std::vector<Bytes>& jobs) {
  if (broken_) throw PoolError("WorkerPool: unusable since " + broken_reason_);
  MapRun run(jobs);
  try {
    while (run.remaining > 0) {
      assign(run);
      // Wait for the next event, but no later than the earliest deadline. With
      // nobody busy (workers Down) their Died events are queued and come at once.
      double earliest = std::numeric_limits<double>::infinity();
      for (const Slot& s : slots_)
        if (s.state == State::Busy) earliest = std::min(earliest, s.deadline);
      const double wait = std::isinf(earliest) ? 1.0 : std::max(0.0, earliest - now());
      if (auto event = transport_->receive(wait)) handle(run, std::move(*event));
      expire(run);
    }
  } catch (...) {
    abandon();
    throw;
  }
  for (size_t i = 0; i < jobs.size(); ++i)
    if (!run.done[i]) throw std::logic_error("WorkerPool: job " + std::to_string(i) + " has no result");
  ++stats_.maps;
  return std::move(run.results);
}

void WorkerPool::assign(MapRun& run) {
  for (int w = 0; w < static_cast<int>(slots_.size()) && !run.pending.empty(); ++w) {
    Slot& slot = slots_[static_cast<size_t>(w)];
    if (slot.state != State::Idle) continue;
    const size_t j = run.pending.front();
    if (!transport_->send(w, Job{static_cast<uint64_t>(j), run.jobs[j]})) {
      slot.state = State::Down;  // died while idle; the job goes to the next worker
      continue;
    }
    run.pending.pop_front();
    slot.state = State::Busy;
    slot.job = j;
    slot.deadline =
        std::isinf(params_.job_timeout_s) ? std::numeric_limits<double>::infinity() : now() + params_.job_timeout_s;
  }
}

void WorkerPool::handle(MapRun& run, WorkerEvent event) {
  const int w = event.worker;
  if (w < 0 || w >= static_cast<int>(slots_.size()))
    throw std::logic_error("WorkerPool: event from unknown worker " + std::to_string(w));
  Slot& slot = slots_[static_cast<size_t>(w)];
  const bool busy = slot.state == State::Busy;
  const size_t j = slot.job;

  if (event.kind == WorkerEvent::Kind::Died) {
    ++stats_.worker_deaths;
    restart(w);
    if (busy) charge(run, j, event.reason);
    return;
  }

  // A result: it must answer the job this worker was given.
  if (!busy || event.result.index != static_cast<uint64_t>(j)) {
    ++stats_.worker_deaths;
    restart(w);
    const std::string why = "worker " + std::to_string(w) + " answered job " + std::to_string(event.result.index) +
                            ", which it was not given";
    if (busy) charge(run, j, why);
    return;
  }
  slot.state = State::Idle;
  if (!event.result.ok)
    throw PoolError("WorkerPool: job " + std::to_string(j) + " failed in worker " + std::to_string(w) + ": " +
                    event.result.error);
  run.results[j] = std::move(event.result.payload);
  run.done[j] = 1;
  --run.remaining;
  ++stats_.jobs_completed;
}

void WorkerPool::expire(MapRun& run) {
  const double t = now();
  for (int w = 0; w < static_cast<int>(slots_.size()); ++w) {
    Slot& slot = slots_[static_cast<size_t>(w)];
    if (slot.state != State::Busy || slot.deadline > t) continue;
    const size_t j = slot.job;
    ++stats_.job_timeouts;
    restart(w);  // kills the hung worker
    charge(run, j,
           "worker " + std::to_string(w) + " ran past job_timeout_s = " + std::to_string(params_.job_timeout_s) +
               " s and was killed");
  }
}

void WorkerPool::charge(MapRun& run, size_t j, const std::string& reason) {
  const int n = ++run.failures[j];
  if (n >= params_.max_attempts)
    throw PoolError("WorkerPool: job " + std::to_string(j) + " failed: its worker died " + std::to_string(n) + " time" +
                    (n == 1 ? "" : "s") + " (max_attempts = " + std::to_string(params_.max_attempts) +
                    "); last: " + reason);
  run.pending.push_front(j);  // soonest retry: the job has waited longest
  ++stats_.jobs_reissued;
}

void WorkerPool::abandon() noexcept {
  for (int w = 0; w < static_cast<int>(slots_.size()); ++w) {
    if (slots_[static_cast<size_t>(w)].state != State::Busy) continue;
    try {
      restart(w);
    } catch (...) {
      // restart() marked the pool broken; the next map() reports why.
    }
  }
}

}  // namespace robozoo
