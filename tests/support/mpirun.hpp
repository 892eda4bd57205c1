#pragma once
// Test support: Open MPI's mpirun as the tests use it, on one machine: ranks may
// outnumber cores (--oversubscribe), and root may run them (--allow-run-as-root,
// only when the tests run as root).
#include <unistd.h>

#include <fstream>
#include <string>
#include <vector>

#include "tests/support/subprocess.hpp"

namespace robozoo::testing {

/// mpirun's arguments before the program: `np` ranks on this machine. Shared-memory
/// messages are copied through the shared segment (no CMA single copy, which needs
/// ptrace rights that containers often withhold).
inline std::vector<std::string> mpirun_args(int np) {
  std::vector<std::string> a = {
      "/usr/bin/mpirun", "--oversubscribe", "--mca", "btl_vader_single_copy_mechanism", "none", "-np",
      std::to_string(np)};
  if (::geteuid() == 0) a.insert(a.begin() + 1, "--allow-run-as-root");
  return a;
}

/// `mpirun -np N argv...` as one argv.
inline std::vector<std::string> under_mpirun(int np, const std::vector<std::string>& argv) {
  std::vector<std::string> a = mpirun_args(np);
  a.insert(a.end(), argv.begin(), argv.end());
  return a;
}

/// The MPI rank of a process started by mpirun (from its environment), or -1.
inline int mpi_rank_of(pid_t pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/environ", std::ios::binary);
  std::string var;
  const std::string key = "OMPI_COMM_WORLD_RANK=";
  while (std::getline(in, var, '\0'))
    if (var.compare(0, key.size(), key) == 0) return std::stoi(var.substr(key.size()));
  return -1;
}

/// The process of rank `rank` among mpirun's children (one machine: mpirun starts
/// the ranks itself), or -1.
/// The pid of an MPI rank started by `mpirun`, waiting up to 5 s for mpirun to
/// start it (a resumed job may reach the interruption point before its ranks
/// exist); -1 if it never appears.
inline pid_t rank_pid(pid_t mpirun, int rank) {
  for (int attempt = 0; attempt < 250; ++attempt) {
    for (pid_t c : children_of(mpirun))
      if (mpi_rank_of(c) == rank) return c;
    ::usleep(20000);
  }
  return -1;
}

}  // namespace robozoo::testing
