#include "evolve/run/pool_evaluator.hpp"

namespace robozoo {

PoolEvaluator::PoolEvaluator(int workers, const EvalParams& params, double job_timeout_s) {
  PoolParams p;
  p.job_timeout_s = job_timeout_s;
  pool_ = std::make_unique<WorkerPool>(
      workers, [params](const Bytes& job) { return run_eval_job(job, params); }, p);
}

PoolEvaluator::PoolEvaluator(std::unique_ptr<Transport> transport, double job_timeout_s) {
  PoolParams p;
  p.job_timeout_s = job_timeout_s;
  pool_ = std::make_unique<WorkerPool>(std::move(transport), p);
}

std::vector<EvalSummary> PoolEvaluator::evaluate(const std::vector<Genome>& genomes) {
  std::vector<Bytes> jobs;
  jobs.reserve(genomes.size());
  for (const auto& g : genomes) jobs.push_back(encode_eval_job(g));
  const std::vector<Bytes> results = pool_->map(jobs);
  std::vector<EvalSummary> out;
  out.reserve(results.size());
  for (const auto& r : results) out.push_back(decode_eval_result(r));
  return out;
}

std::vector<int> PoolEvaluator::worker_pids() {
  std::vector<int> pids;
  auto* pipe = dynamic_cast<PipeTransport*>(&pool_->transport());
  if (pipe)
    for (int w = 0; w < pipe->size(); ++w) pids.push_back(static_cast<int>(pipe->pid(w)));
  return pids;
}

}  // namespace robozoo
