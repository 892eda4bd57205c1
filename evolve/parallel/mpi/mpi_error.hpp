#pragma once
// Internal to robozoo_mpi (includes mpi.h): MPI error codes as exceptions, and the
// tags and communicator the transport and the worker ranks agree on.
#include <mpi.h>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace robozoo::mpi_detail {

/// Sessions whose tags differ (a result of an abandoned session never reaches a
/// later one); MPI guarantees tags up to 32767.
inline constexpr uint32_t kTagSessions = 16000;
/// Tag of rank 0's messages to a worker rank in `session`: Job and Shutdown frames.
inline int job_tag(uint32_t session) { return 1 + 2 * static_cast<int>(session % kTagSessions); }
/// Tag of a worker rank's messages to rank 0 in `session`: Result and Failure frames.
inline int result_tag(uint32_t session) { return 2 + 2 * static_cast<int>(session % kTagSessions); }
/// The job's ranks: rank 0 runs evolution, ranks 1.. evaluate.
inline MPI_Comm world() { return MPI_COMM_WORLD; }

/// MPI's text for an error code.
inline std::string error_text(int code) {
  char text[MPI_MAX_ERROR_STRING];
  int n = 0;
  if (MPI_Error_string(code, text, &n) != MPI_SUCCESS) return "MPI error " + std::to_string(code);
  return std::string(text, static_cast<size_t>(n));
}

/// Throws std::runtime_error("MPI: <what> failed: <MPI's text>") unless rc is MPI_SUCCESS.
inline void check(int rc, const std::string& what) {
  if (rc != MPI_SUCCESS) throw std::runtime_error("MPI: " + what + " failed: " + error_text(rc));
}

}  // namespace robozoo::mpi_detail
