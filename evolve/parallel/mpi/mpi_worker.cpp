#include "evolve/parallel/mpi/mpi_worker.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "evolve/parallel/mpi/mpi_error.hpp"
#include "evolve/parallel/mpi/mpi_setup.hpp"

namespace robozoo {

namespace {
using Clock = std::chrono::steady_clock;
using mpi_detail::check;

/// Waits (probing with growing pauses) for rank 0's next message to this rank.
Bytes next_message(const MpiWorkerParams& p, uint32_t session) {
  double pause = p.poll_min_sleep_s;
  for (;;) {
    int flag = 0;
    MPI_Message message = MPI_MESSAGE_NULL;
    MPI_Status status;
    check(MPI_Improbe(0, mpi_detail::job_tag(session), mpi_detail::world(), &flag, &message, &status), "MPI_Improbe");
    if (flag) {
      int count = 0;
      check(MPI_Get_count(&status, MPI_BYTE, &count), "MPI_Get_count");
      Bytes buffer(static_cast<size_t>(std::max(count, 0)));
      check(MPI_Mrecv(buffer.data(), count, MPI_BYTE, &message, MPI_STATUS_IGNORE), "MPI_Mrecv");
      return buffer;
    }
    std::this_thread::sleep_for(std::chrono::duration<double>(pause));
    pause = std::min(pause * 2.0, p.poll_max_sleep_s);
  }
}
}  // namespace

bool serve_mpi_session(const WorkFnFactory& make, MpiWorkerStats* stats, MpiWorkerParams params) {
  if (!make) throw std::invalid_argument("serve_mpi_session: no work function factory");
  if (!(params.poll_min_sleep_s >= 0.0) || !(params.poll_max_sleep_s >= params.poll_min_sleep_s) ||
      !std::isfinite(params.poll_max_sleep_s))
    throw std::invalid_argument("serve_mpi_session: need 0 <= poll_min_sleep_s <= poll_max_sleep_s < infinity");
  int rank = 0;
  check(MPI_Comm_rank(mpi_detail::world(), &rank), "MPI_Comm_rank");
  if (rank == 0) throw std::invalid_argument("serve_mpi_session: rank 0 owns the pool; workers are ranks 1..");

  const std::optional<MpiSetup> setup = receive_setup();
  if (!setup) return false;
  const WorkFn fn = make(setup->text);
  if (!fn) throw std::invalid_argument("serve_mpi_session: the factory gave no work function");

  for (;;) {
    const Bytes message = next_message(params, setup->session);
    const auto t0 = Clock::now();
    std::optional<Bytes> reply = serve_frame(fn, decode_message(message, params.max_body_bytes));
    if (!reply) return true;  // Shutdown
    if (stats) {
      ++stats->jobs;
      stats->busy_seconds += std::chrono::duration<double>(Clock::now() - t0).count();
    }
    check(MPI_Send(reply->data(), static_cast<int>(reply->size()), MPI_BYTE, 0, mpi_detail::result_tag(setup->session),
                   mpi_detail::world()),
          "MPI_Send (result)");
  }
}

std::vector<MpiWorkerStats> gather_worker_stats(const MpiWorkerStats& mine) {
  int rank = 0, size = 0;
  check(MPI_Comm_rank(mpi_detail::world(), &rank), "MPI_Comm_rank");
  check(MPI_Comm_size(mpi_detail::world(), &size), "MPI_Comm_size");
  const double sent[2] = {static_cast<double>(mine.jobs), mine.busy_seconds};
  std::vector<double> all(rank == 0 ? 2 * static_cast<size_t>(size) : 0);
  check(MPI_Gather(sent, 2, MPI_DOUBLE, all.data(), 2, MPI_DOUBLE, 0, mpi_detail::world()), "MPI_Gather");
  std::vector<MpiWorkerStats> out;
  if (rank != 0) return out;
  out.resize(static_cast<size_t>(size));
  for (size_t r = 0; r < out.size(); ++r) {
    out[r].jobs = static_cast<uint64_t>(all[2 * r]);
    out[r].busy_seconds = all[2 * r + 1];
  }
  return out;
}

}  // namespace robozoo
