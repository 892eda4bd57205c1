#pragma once
// The evaluation job and its result as bytes: what travels between the
// evolution process and its workers, whatever the transport (pipes to local
// worker processes now, MPI ranks later). Pure functions.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "evolve/config/run_config.hpp"
#include "evolve/cppn/genome.hpp"
#include "evolve/fitness/evaluate.hpp"

namespace robozoo {

struct EvalSummary {
  int64_t genome_id = -1;
  double fitness = 0, r = 0, d = 0;
  Outcome outcome = Outcome::NotSimulated;
  int32_t num_spheres = 0, num_bodies = 0, num_joints = 0, num_sensors = 0, steps_run = 0;
  bool operator==(const EvalSummary& o) const;
};

std::vector<uint8_t> encode_eval_job(const Genome& g);
/// Throws std::invalid_argument on bytes that are not a valid genome of `layout`.
Genome decode_eval_job(const std::vector<uint8_t>& bytes, const GenomeLayout& layout);

EvalSummary summarize(int64_t genome_id, const Evaluation& e);
std::vector<uint8_t> encode_eval_result(const EvalSummary& s);
/// Throws std::invalid_argument on bytes that are not an eval_result_t.
EvalSummary decode_eval_result(const std::vector<uint8_t>& bytes);

/// The worker's whole job: decode, evaluate with `params`, encode.
std::vector<uint8_t> run_eval_job(const std::vector<uint8_t>& job, const EvalParams& params);

/// A worker rank's work function for a run whose resolved configuration is the
/// JSON text `setup` (what MpiTransport::start sends): run_eval_job with its
/// EvalParams. Throws ConfigError / nlohmann::json::exception for a bad setup.
std::function<std::vector<uint8_t>(const std::vector<uint8_t>&)> eval_work_from_setup(const std::string& setup);

}  // namespace robozoo
