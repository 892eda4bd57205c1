#pragma once
// The start of an evaluation session under MPI: rank 0 broadcasts one setup text
// (robozoo-evolve: the run's resolved configuration as JSON) from which every
// worker rank builds its work function, or tells the worker ranks that there is
// no session (rank 0 stopped before evaluating anything). Collective: every rank
// of MPI_COMM_WORLD calls one of these, rank 0 the first.
#include <cstdint>
#include <optional>
#include <string>

namespace robozoo {

struct MpiSetup {
  std::string text;      ///< what the worker ranks build their work function from
  uint32_t session = 0;  ///< the session's number: its messages' tags (mpi_error.hpp)
};

/// Rank 0: starts a session with `setup` (any bytes, may be empty), or with
/// nullopt tells the worker ranks that no session follows. Throws
/// std::runtime_error on an MPI error.
void broadcast_setup(const std::optional<MpiSetup>& setup);

/// A worker rank: waits for rank 0's broadcast_setup; nullopt when no session
/// follows. Throws std::runtime_error on an MPI error.
std::optional<MpiSetup> receive_setup();

}  // namespace robozoo
