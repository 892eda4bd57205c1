#pragma once
// Where evaluations run. The evolution loop hands a generation's genomes to an
// Evaluator and gets their results back in genome order, whatever runs them.
#include <vector>

#include "evolve/cppn/genome.hpp"
#include "evolve/run/eval_job.hpp"

namespace robozoo {

class Evaluator {
 public:
  virtual ~Evaluator() = default;
  /// Results in the order of `genomes`; identical whatever the evaluator.
  virtual std::vector<EvalSummary> evaluate(const std::vector<Genome>& genomes) = 0;
  /// Number of evaluations running at once.
  virtual int parallelism() const = 0;
  /// Whether evaluate() simulates in this process. ODE's state is partly
  /// process-wide (the seed of its random constraint order), so nothing else
  /// may simulate in this process while such an evaluator does.
  virtual bool simulates_in_process() const { return true; }
};

/// Evaluates in this process, one after the other (tests, debugging).
class InProcessEvaluator : public Evaluator {
 public:
  explicit InProcessEvaluator(const EvalParams& params) : params_(params) {}
  std::vector<EvalSummary> evaluate(const std::vector<Genome>& genomes) override;
  int parallelism() const override { return 1; }

 private:
  EvalParams params_;
};

}  // namespace robozoo
