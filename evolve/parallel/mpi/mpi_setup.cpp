#include "evolve/parallel/mpi/mpi_setup.hpp"

#include <climits>
#include <cstdint>

#include "evolve/parallel/mpi/mpi_error.hpp"

namespace robozoo {

using mpi_detail::check;

// Wire: a header of two uint64 (size: 0 for no session, n + 1 for a setup of n
// bytes; the session number), then the n bytes, both broadcast from rank 0.

void broadcast_setup(const std::optional<MpiSetup>& setup) {
  if (setup && setup->text.size() > static_cast<size_t>(INT_MAX))
    throw std::invalid_argument("broadcast_setup: a setup text of " + std::to_string(setup->text.size()) +
                                " bytes is too large for one broadcast");
  uint64_t header[2] = {setup ? static_cast<uint64_t>(setup->text.size()) + 1 : 0, setup ? setup->session : 0};
  check(MPI_Bcast(header, 2, MPI_UINT64_T, 0, mpi_detail::world()), "MPI_Bcast (setup header)");
  if (!setup || setup->text.empty()) return;
  std::string copy = setup->text;  // MPI_Bcast's buffer is not const
  check(MPI_Bcast(copy.data(), static_cast<int>(copy.size()), MPI_CHAR, 0, mpi_detail::world()), "MPI_Bcast (setup)");
}

std::optional<MpiSetup> receive_setup() {
  uint64_t header[2] = {0, 0};
  check(MPI_Bcast(header, 2, MPI_UINT64_T, 0, mpi_detail::world()), "MPI_Bcast (setup header)");
  if (header[0] == 0) return std::nullopt;
  const uint64_t n = header[0] - 1;
  if (n > static_cast<uint64_t>(INT_MAX) || header[1] > UINT32_MAX)
    throw std::runtime_error("receive_setup: rank 0 announced " + std::to_string(n) + " bytes for session " +
                             std::to_string(header[1]));
  MpiSetup setup;
  setup.session = static_cast<uint32_t>(header[1]);
  setup.text.assign(static_cast<size_t>(n), '\0');
  if (n > 0)
    check(MPI_Bcast(setup.text.data(), static_cast<int>(n), MPI_CHAR, 0, mpi_detail::world()), "MPI_Bcast (setup)");
  return setup;
}

}  // namespace robozoo
