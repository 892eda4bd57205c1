#pragma once
// Writes a run's checkpoints one at a time, either at once or on a thread of its
// own while the caller goes on (the next generation's evaluation). Building and
// writing a population's checkpoint is rank 0's largest serial cost under MPI
// (~50 ms for 150 genomes: JSON, then write, fsync, rename): in the background it
// overlaps the workers' evaluations instead of adding to every generation.
//
// Each write is atomic (write_checkpoint): the file holds the previous checkpoint
// until the new one is complete, so a process killed during a background write
// resumes from the previous generation, with the same result. A background write
// that fails reports its error at the next write() or wait().
#include <atomic>
#include <exception>
#include <string>
#include <thread>

#include "evolve/record/checkpoint.hpp"

namespace robozoo {

class CheckpointWriter {
 public:
  /// Writes to `path`; `background`: on a thread, else within write().
  /// `generations_on_disk`: what the checkpoint already at `path` holds (-1: none).
  CheckpointWriter(std::string path, bool background, int generations_on_disk = -1);
  /// Waits for a write in flight; its error, if any, is dropped.
  ~CheckpointWriter();
  CheckpointWriter(const CheckpointWriter&) = delete;
  CheckpointWriter& operator=(const CheckpointWriter&) = delete;

  /// Writes `c`, which holds `generations_done` finished generations. In the
  /// background: waits for the previous write first (rethrowing its error), starts
  /// this one and returns. Throws std::runtime_error naming the path on failure.
  void write(Checkpoint c, int generations_done);
  /// Waits until nothing is being written; rethrows a background write's error.
  void wait();

  /// Finished generations held by the last checkpoint written in full (-1: none
  /// yet). Thread-safe: a signal watcher may read it at any time.
  int generations_written() const { return written_.load(); }
  bool background() const { return background_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  bool background_;
  std::thread thread_;
  std::exception_ptr error_;  ///< the last background write's failure, until reported
  std::atomic<int> written_{-1};
};

}  // namespace robozoo
