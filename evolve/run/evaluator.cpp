#include "evolve/run/evaluator.hpp"

namespace robozoo {

std::vector<EvalSummary> InProcessEvaluator::evaluate(const std::vector<Genome>& genomes) {
  std::vector<EvalSummary> out;
  out.reserve(genomes.size());
  for (const auto& g : genomes) out.push_back(decode_eval_result(run_eval_job(encode_eval_job(g), params_)));
  return out;
}

}  // namespace robozoo
