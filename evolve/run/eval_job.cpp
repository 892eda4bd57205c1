#include "evolve/run/eval_job.hpp"

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "evolve/messages/build.hpp"
#include "robozoo/eval_result_t.hpp"

namespace robozoo {

bool EvalSummary::operator==(const EvalSummary& o) const {
  return genome_id == o.genome_id && fitness == o.fitness && r == o.r && d == o.d && outcome == o.outcome &&
         num_spheres == o.num_spheres && num_bodies == o.num_bodies && num_joints == o.num_joints &&
         num_sensors == o.num_sensors && steps_run == o.steps_run;
}

std::vector<uint8_t> encode_eval_job(const Genome& g) {
  return encode_message(make_genome_message("", 0, g, 0, GenomeScore{}, 0));
}

Genome decode_eval_job(const std::vector<uint8_t>& bytes, const GenomeLayout& layout) {
  cppn_genome_t m{};
  int used = -1;
  try {
    used = m.decode(bytes.data(), 0, static_cast<int>(bytes.size()));
  } catch (const std::exception&) {
    used = -1;  // a corrupt count can make the generated decoder throw
  }
  if (used != static_cast<int>(bytes.size()))
    throw std::invalid_argument("evaluation job is not a cppn_genome_t message");
  return genome_from_message(m, layout);
}

EvalSummary summarize(int64_t genome_id, const Evaluation& e) {
  EvalSummary s;
  s.genome_id = genome_id;
  s.fitness = e.fitness;
  s.r = e.r;
  s.d = e.d;
  s.outcome = e.outcome;
  s.num_spheres = e.num_spheres;
  s.num_bodies = e.num_bodies;
  s.num_joints = e.num_joints;
  s.num_sensors = e.num_sensors;
  s.steps_run = e.sim.steps_run;
  return s;
}

std::vector<uint8_t> encode_eval_result(const EvalSummary& s) {
  eval_result_t m{};
  m.genome_id = s.genome_id;
  m.fitness = s.fitness;
  m.r_term = s.r;
  m.d_term = s.d;
  m.outcome = static_cast<int8_t>(s.outcome);
  m.num_spheres = s.num_spheres;
  m.num_bodies = s.num_bodies;
  m.num_joints = s.num_joints;
  m.num_sensors = s.num_sensors;
  m.steps_run = s.steps_run;
  return encode_message(m);
}

EvalSummary decode_eval_result(const std::vector<uint8_t>& bytes) {
  eval_result_t m{};
  if (m.decode(bytes.data(), 0, static_cast<int>(bytes.size())) != static_cast<int>(bytes.size()))
    throw std::invalid_argument("evaluation result is not an eval_result_t message");
  if (m.outcome < 0 || m.outcome >= kNumOutcomes)
    throw std::invalid_argument("evaluation result has unknown outcome " + std::to_string(m.outcome));
  EvalSummary s;
  s.genome_id = m.genome_id;
  s.fitness = m.fitness;
  s.r = m.r_term;
  s.d = m.d_term;
  s.outcome = static_cast<Outcome>(m.outcome);
  s.num_spheres = m.num_spheres;
  s.num_bodies = m.num_bodies;
  s.num_joints = m.num_joints;
  s.num_sensors = m.num_sensors;
  s.steps_run = m.steps_run;
  return s;
}

std::vector<uint8_t> run_eval_job(const std::vector<uint8_t>& job, const EvalParams& params) {
  const Genome g = decode_eval_job(job, robot_layout());
  return encode_eval_result(summarize(g.id, evaluate(g, params)));
}

std::function<std::vector<uint8_t>(const std::vector<uint8_t>&)> eval_work_from_setup(const std::string& setup) {
  const RunConfig config = config_from_record(nlohmann::json::parse(setup));
  return [eval = config.eval](const std::vector<uint8_t>& job) { return run_eval_job(job, eval); };
}

}  // namespace robozoo
