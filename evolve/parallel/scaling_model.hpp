#pragma once
// A model of one generation's wall time on W worker ranks, from what a small run
// measured (robozoo-mpi-bench): the pool hands job i to the first free worker, in
// job order (WorkerPool::map), so the evaluation phase is the makespan of that list
// schedule; each job also pays two messages' latency and its bytes on the link;
// rank 0 handles every message itself and its link carries every byte; after the
// results, rank 0 alone breeds, logs, publishes and checkpoints (the serial part).
//
//   T(W) = serial + max( makespan_W(d_i / speed + 2 latency + bytes_i / bandwidth),
//                         n * root_per_job + sum(bytes_i) / bandwidth )
//
// The first term of the max is the workers' part, the second rank 0's messaging
// and link; whichever is larger bounds the generation, and the serial part adds.
#include <cstdint>
#include <string>
#include <vector>

namespace robozoo {

struct ClusterParams {
  double latency_s = 50e-6;              ///< one-way latency of a message, MPI over TCP on
                                         ///< Ethernet ~50 us, InfiniBand ~2 us (s)
  double bandwidth_bytes_per_s = 125e6;  ///< rank 0's link: 1 Gbit/s Ethernet = 125e6 (bytes/s)
  double core_speed = 1.0;               ///< a cluster core's speed relative to the measuring
                                         ///< machine's, for evaluations (ratio)
};

/// One generation's costs as measured.
struct GenerationCost {
  std::vector<double> job_seconds;    ///< each job's evaluation time on one core, in job order (s)
  std::vector<double> job_bytes;      ///< each job's Job + Result message bytes, in job order (bytes)
  double serial_seconds = 0.0;        ///< rank 0 alone: breeding, logging, publishing, checkpoint (s)
  double root_seconds_per_job = 0.0;  ///< rank 0's own time per job handed out and collected (s)
};

struct GenerationProjection {
  double seconds = 0.0;    ///< projected wall time of the generation (s)
  double workers = 0.0;    ///< the workers' part: the list schedule's makespan (s)
  double root_link = 0.0;  ///< rank 0's messaging and link time (s)
  double serial = 0.0;     ///< rank 0's serial part (s)
  /// What bounds it: "evaluations" (the workers' part), "rank 0 messaging" (rank 0's
  /// handling and link), "rank 0 serial" (the serial part exceeds both).
  std::string bound;
};

/// Makespan of handing `durations` out in order, each to the first free of
/// `workers` (>= 1; ties to the lowest worker). Throws std::invalid_argument on
/// workers < 1 or a negative or non-finite duration.
double list_schedule_makespan(const std::vector<double>& durations, int workers);

/// T(W) as above. Throws std::invalid_argument on workers < 1, mismatched sizes,
/// or parameters that are not positive and finite.
GenerationProjection project_generation(const GenerationCost& cost, int workers, const ClusterParams& cluster);

}  // namespace robozoo
