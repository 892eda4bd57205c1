#pragma once
// MPI for one process of robozoo: MPI_Init_thread at construction, MPI_Finalize at
// destruction. Only the thread that created the session calls MPI (MPI_THREAD_FUNNELED).
// Errors on MPI_COMM_WORLD are returned, not fatal, so that they become exceptions
// with a clear message. This header does not include mpi.h: MPI stays inside
// robozoo_mpi (evolve/parallel/mpi).
#include <string>

namespace robozoo {

class MpiSession {
 public:
  /// Initialises MPI with the program's arguments (either may be null). Throws
  /// std::runtime_error if MPI cannot start or was already started in this process.
  MpiSession(int* argc, char*** argv);
  /// MPI_Finalize (collective: it returns when every rank has called it).
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }  ///< this process's rank in MPI_COMM_WORLD
  int size() const { return size_; }  ///< number of ranks in MPI_COMM_WORLD
  std::string host() const;           ///< MPI's name of this process's node

  /// Ends every rank of the job now (MPI_Abort with `code`); never returns.
  [[noreturn]] void abort(int code) const;

 private:
  int rank_ = 0;
  int size_ = 1;
};

/// Whether the command line asks for MPI (`--mpi` anywhere). A program must know
/// before it parses its options: MPI starts first, so that only rank 0 speaks.
bool mpi_requested(int argc, char** argv);

}  // namespace robozoo
