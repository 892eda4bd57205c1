#include "evolve/parallel/mpi/mpi_transport.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <thread>

#include "evolve/parallel/mpi/mpi_error.hpp"
#include "evolve/parallel/mpi/mpi_setup.hpp"

namespace robozoo {

namespace {
using Clock = std::chrono::steady_clock;
using mpi_detail::check;
using mpi_detail::error_text;
using mpi_detail::world;

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }
Clock::duration duration(double s) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}
}  // namespace

struct MpiTransport::Impl {
  struct Slot {
    bool dead = false;       ///< reported (or about to be reported) Died
    std::string death;       ///< why
    bool busy = false;       ///< a job is outstanding
    uint64_t job = 0;        ///< its index
    uint64_t bytes_out = 0;  ///< its message's size
    Clock::time_point sent_at;
    Bytes out;  ///< the message MPI may still be sending
    MPI_Request request = MPI_REQUEST_NULL;
  };

  MpiTransportParams params;
  bool started = false;
  std::vector<Slot> slots;
  std::deque<WorkerEvent> events;
  MpiTransportStats stats;

  std::string name(int w) const { return "rank " + std::to_string(rank_of(w)) + " (worker " + std::to_string(w) + ")"; }

  void bury(int w, const std::string& why) {
    Slot& s = slots[static_cast<size_t>(w)];
    if (s.dead) return;
    s.dead = true;
    s.busy = false;
    s.death = why;
    WorkerEvent e;
    e.kind = WorkerEvent::Kind::Died;
    e.worker = w;
    e.reason = name(w) + " " + why;
    events.push_back(std::move(e));
  }

  /// Completes (or, for a rank that is gone, abandons) w's message in flight.
  void settle(Slot& s, bool wait) {
    if (s.request == MPI_REQUEST_NULL) return;
    int done = 0;
    if (MPI_Test(&s.request, &done, MPI_STATUS_IGNORE) == MPI_SUCCESS && done) return;
    if (wait && MPI_Wait(&s.request, MPI_STATUS_IGNORE) == MPI_SUCCESS) return;
    MPI_Cancel(&s.request);
    MPI_Request_free(&s.request);
    s.request = MPI_REQUEST_NULL;
  }

  /// Takes one Result/Failure message if one has arrived; returns whether it did.
  bool take_one() {
    int flag = 0;
    MPI_Message message = MPI_MESSAGE_NULL;
    MPI_Status status;
    check(MPI_Improbe(MPI_ANY_SOURCE, mpi_detail::result_tag(params.session), world(), &flag, &message, &status),
          "MPI_Improbe");
    if (!flag) return false;
    int count = 0;
    check(MPI_Get_count(&status, MPI_BYTE, &count), "MPI_Get_count");
    const int source = status.MPI_SOURCE;
    Bytes buffer(static_cast<size_t>(std::max(count, 0)));
    const int rc = MPI_Mrecv(buffer.data(), count, MPI_BYTE, &message, MPI_STATUS_IGNORE);
    const int w = source - 1;
    if (w < 0 || w >= static_cast<int>(slots.size()))
      throw std::logic_error("MpiTransport: a result from rank " + std::to_string(source) + ", which is no worker");
    Slot& s = slots[static_cast<size_t>(w)];
    if (rc != MPI_SUCCESS) {
      bury(w, "could not be received from (" + error_text(rc) + ")");
      return true;
    }
    ++stats.messages_received;
    stats.bytes_received += buffer.size();
    Result result;
    try {
      result = result_from_frame(decode_message(buffer, params.max_body_bytes));
    } catch (const ProtocolError& err) {
      bury(w, std::string("broke the protocol (") + err.what() + ")");
      return true;
    }
    if (s.dead) return true;  // already reported dead: what it says no longer counts
    if (s.busy) {
      const double took = seconds(Clock::now() - s.sent_at);
      stats.busy_seconds[static_cast<size_t>(w)] += took;
      if (params.record_jobs) stats.timings.push_back(MpiJobTiming{w, result.index, s.bytes_out, buffer.size(), took});
    }
    ++stats.jobs[static_cast<size_t>(w)];
    s.busy = false;
    WorkerEvent e;
    e.kind = WorkerEvent::Kind::Result;
    e.worker = w;
    e.result = std::move(result);
    events.push_back(std::move(e));
    return true;
  }
};

MpiTransport::MpiTransport(MpiTransportParams params) : impl_(std::make_unique<Impl>()) {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) throw std::invalid_argument("MpiTransport: MPI is not initialised (create an MpiSession first)");
  int rank = -1, size = 0;
  check(MPI_Comm_rank(world(), &rank), "MPI_Comm_rank");
  check(MPI_Comm_size(world(), &size), "MPI_Comm_size");
  if (rank != 0) throw std::invalid_argument("MpiTransport: belongs on rank 0, this is rank " + std::to_string(rank));
  if (size < 2)
    throw std::invalid_argument("MpiTransport: needs at least 2 ranks (rank 0 and a worker rank), the job has " +
                                std::to_string(size));
  if (!(params.poll_min_sleep_s >= 0.0) || !(params.poll_max_sleep_s >= params.poll_min_sleep_s) ||
      !std::isfinite(params.poll_max_sleep_s))
    throw std::invalid_argument("MpiTransport: need 0 <= poll_min_sleep_s <= poll_max_sleep_s < infinity");
  if (!(params.shutdown_wait_s >= 0.0) || !std::isfinite(params.shutdown_wait_s))
    throw std::invalid_argument("MpiTransport: shutdown_wait_s must be finite and >= 0");
  impl_->params = params;
  impl_->slots.resize(static_cast<size_t>(size - 1));
  impl_->stats.jobs.assign(impl_->slots.size(), 0);
  impl_->stats.busy_seconds.assign(impl_->slots.size(), 0.0);
}

MpiTransport::~MpiTransport() {
  Impl& m = *impl_;
  try {
    if (!m.started) {
      broadcast_setup(std::nullopt);  // the worker ranks leave their session loop
      return;
    }
    const Bytes shutdown = encode_shutdown();
    std::vector<MPI_Request> requests;
    for (int w = 0; w < size(); ++w) {
      Impl::Slot& s = m.slots[static_cast<size_t>(w)];
      m.settle(s, false);
      // Dead ranks too: one that broke the protocol may still be waiting.
      MPI_Request r = MPI_REQUEST_NULL;
      if (MPI_Isend(shutdown.data(), static_cast<int>(shutdown.size()), MPI_BYTE, rank_of(w),
                    mpi_detail::job_tag(m.params.session), world(), &r) == MPI_SUCCESS)
        requests.push_back(r);
    }
    const auto deadline = Clock::now() + duration(m.params.shutdown_wait_s);
    for (;;) {
      int done = 0;
      if (requests.empty() ||
          MPI_Testall(static_cast<int>(requests.size()), requests.data(), &done, MPI_STATUSES_IGNORE) != MPI_SUCCESS ||
          done || Clock::now() >= deadline)
        break;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    for (auto& r : requests)
      if (r != MPI_REQUEST_NULL) {
        MPI_Cancel(&r);
        MPI_Request_free(&r);
      }
  } catch (...) {
    // A destructor does not throw; the job is ending and MPI reports its own failures.
  }
}

void MpiTransport::start(const std::string& setup) {
  if (impl_->started) throw std::logic_error("MpiTransport::start: already started");
  broadcast_setup(MpiSetup{setup, impl_->params.session});
  impl_->started = true;
  impl_->stats.setup_bytes = setup.size();
}

bool MpiTransport::started() const { return impl_->started; }

int MpiTransport::size() const { return static_cast<int>(impl_->slots.size()); }

const MpiTransportStats& MpiTransport::stats() const { return impl_->stats; }

void MpiTransport::reset_stats() {
  MpiTransportStats& s = impl_->stats;
  s = MpiTransportStats{};
  s.jobs.assign(impl_->slots.size(), 0);
  s.busy_seconds.assign(impl_->slots.size(), 0.0);
}

bool MpiTransport::send(int w, const Job& job) {
  Impl& m = *impl_;
  if (!m.started) throw std::logic_error("MpiTransport::send before start()");
  if (w < 0 || w >= size())
    throw std::out_of_range("MpiTransport: no worker " + std::to_string(w) + " (have " + std::to_string(size()) + ")");
  Impl::Slot& s = m.slots[static_cast<size_t>(w)];
  if (s.dead) return false;
  if (s.busy) throw std::logic_error("MpiTransport::send: " + m.name(w) + " already has a job");
  m.settle(s, true);  // its previous job message was received (it answered): completes at once
  s.out = encode_job(job);
  const int rc = MPI_Isend(s.out.data(), static_cast<int>(s.out.size()), MPI_BYTE, rank_of(w),
                           mpi_detail::job_tag(m.params.session), world(), &s.request);
  if (rc != MPI_SUCCESS) {
    s.request = MPI_REQUEST_NULL;
    m.bury(w, "could not be sent to (" + error_text(rc) + ")");
    return false;
  }
  s.busy = true;
  s.job = job.index;
  s.bytes_out = s.out.size();
  s.sent_at = Clock::now();
  ++m.stats.messages_sent;
  m.stats.bytes_sent += s.out.size();
  return true;
}

std::optional<WorkerEvent> MpiTransport::receive(double timeout_s) {
  Impl& m = *impl_;
  if (std::isnan(timeout_s)) throw std::invalid_argument("MpiTransport::receive: NaN timeout");
  const auto deadline = Clock::now() + duration(std::min(std::max(timeout_s, 0.0), 1e6));
  double pause = m.params.poll_min_sleep_s;
  for (bool first = true;; first = false) {
    if (m.events.empty()) {
      while (m.take_one()) {
      }
    }
    if (!m.events.empty()) {
      WorkerEvent e = std::move(m.events.front());
      m.events.pop_front();
      return e;
    }
    const auto now = Clock::now();
    if (!first && now >= deadline) return std::nullopt;  // probe at least once
    const double left = seconds(deadline - now);
    if (left > 0.0) std::this_thread::sleep_for(duration(std::min(pause, left)));
    pause = std::min(pause * 2.0, m.params.poll_max_sleep_s);
  }
}

void MpiTransport::restart(int w) {
  Impl& m = *impl_;
  if (w < 0 || w >= size())
    throw std::out_of_range("MpiTransport: no worker " + std::to_string(w) + " (have " + std::to_string(size()) + ")");
  const Impl::Slot& s = m.slots[static_cast<size_t>(w)];
  const std::string what = s.dead ? s.death : s.busy ? "did not answer its job in time" : "was given up";
  throw std::runtime_error(m.name(w) + " " + what +
                           "; a running MPI job cannot replace a rank: end the job and resume the run from its "
                           "checkpoint");
}

}  // namespace robozoo
