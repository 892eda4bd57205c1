#pragma once
// Building robozoo's LCM messages: pure functions of the science's data
// (docs/method.md section 3 and 6). Sending them is another module's job.
#include <cstdint>
#include <string>

#include "evolve/config/run_config.hpp"
#include "evolve/cppn/genome.hpp"
#include "evolve/fitness/evaluate.hpp"
#include "evolve/growth/robot.hpp"
#include "evolve/sim/episode/simulation.hpp"
#include "robozoo/bus_status_t.hpp"
#include "robozoo/generation_t.hpp"
#include "robozoo/cppn_genome_t.hpp"
#include "robozoo/morphology_t.hpp"
#include "robozoo/pose_t.hpp"
#include "robozoo/run_t.hpp"

namespace robozoo {

/// Channel names (docs/method.md section 3).
inline constexpr const char* kChannelRun = "ROBOZOO_RUN";
inline constexpr const char* kChannelGeneration = "ROBOZOO_GENERATION";
inline constexpr const char* kChannelGenome = "ROBOZOO_GENOME";
inline constexpr const char* kChannelMorphology = "ROBOZOO_MORPHOLOGY";
inline constexpr const char* kChannelPose = "ROBOZOO_POSE";
/// Bus only (bus_status_t), never logged: how live publishing went.
inline constexpr const char* kChannelBus = "ROBOZOO_BUS";

/// Software version written into every run_t.
std::string software_version();

run_t make_run_message(const std::string& run_id, const RunConfig& config, int64_t utime);

/// Everything a generation_t reports, computed by the evolution loop.
struct GenerationSummary {
  int32_t generation = 0;
  int64_t evaluations = 0;  ///< cumulative (count)
  double best_fitness = 0, mean_fitness = 0, stderr_fitness = 0, best_so_far_fitness = 0;
  int64_t champion_id = -1;
  int32_t num_species = 0;
  double compatibility_threshold = 0;
  int32_t outcome_counts[6] = {0, 0, 0, 0, 0, 0};  ///< indexed by Outcome
  double eval_seconds = 0, generation_seconds = 0;
};
generation_t make_generation_message(const std::string& run_id, const GenerationSummary& s, int64_t utime);

/// What an evaluation reports about a genome (a compact part of Evaluation).
struct GenomeScore {
  double fitness = 0, r = 0, d = 0;
  Outcome outcome = Outcome::NotSimulated;
};
cppn_genome_t make_genome_message(const std::string& run_id, int32_t generation, const Genome& g, int32_t species_id,
                                  const GenomeScore& score, int64_t utime);
morphology_t make_morphology_message(const std::string& run_id, int32_t generation, int64_t genome_id,
                                     const Robot& robot, int64_t utime);
pose_t make_pose_message(const std::string& run_id, int32_t generation, int64_t genome_id, const SimState& state,
                         int64_t utime);

/// Inverse of make_genome_message: checks counts and the genome against the
/// layout; throws std::invalid_argument naming the problem.
Genome genome_from_message(const cppn_genome_t& m, const GenomeLayout& layout);

/// Encodes any generated LCM type to bytes.
template <class T>
std::vector<uint8_t> encode_message(const T& m) {
  std::vector<uint8_t> buf(static_cast<size_t>(m.getEncodedSize()));
  m.encode(buf.data(), 0, static_cast<int>(buf.size()));
  return buf;
}

}  // namespace robozoo
