#pragma once
// Evaluations in a pool of worker processes (evolve/parallel): genomes travel
// as cppn_genome_t bytes, results as eval_result_t bytes, collected by index, so the
// run is bit-identical for any number of workers.
#include <memory>

#include "evolve/parallel/worker_pool.hpp"
#include "evolve/run/evaluator.hpp"

namespace robozoo {

class PoolEvaluator : public Evaluator {
 public:
  /// Forks `workers` processes that evaluate with `params`. Create it before any
  /// other thread starts (LCM) and before opening files the workers need not share.
  PoolEvaluator(int workers, const EvalParams& params, double job_timeout_s = 600.0);
  /// Evaluates over a transport whose workers run run_eval_job with the run's
  /// EvalParams themselves (an MpiTransport: its ranks get them at start()).
  explicit PoolEvaluator(std::unique_ptr<Transport> transport, double job_timeout_s = 600.0);
  std::vector<EvalSummary> evaluate(const std::vector<Genome>& genomes) override;
  int parallelism() const override { return pool_->workers(); }
  bool simulates_in_process() const override { return false; }  // forked workers or MPI ranks
  const PoolStats& stats() const { return pool_->stats(); }
  /// The worker processes' ids (tests kill one on purpose).
  std::vector<int> worker_pids();
  Transport& transport() { return pool_->transport(); }

 private:
  std::unique_ptr<WorkerPool> pool_;
};

}  // namespace robozoo
