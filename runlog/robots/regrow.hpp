#pragma once
// Re-growing a logged genome, the one way every program does it: the genes of
// its ROBOZOO_GENOME (read with the robot's layout) grown under its run's
// configuration with the shared grow_genome, and the check that the robot
// re-grown is the one the log holds. How strictly the configuration is read
// from run_t.config_json is the caller's to decide (replay takes no default).
#include <cstdint>

#include "evolve/config/run_config.hpp"
#include "evolve/cppn/genome.hpp"
#include "evolve/growth/robot.hpp"
#include "robozoo/cppn_genome_t.hpp"
#include "robozoo/morphology_t.hpp"

namespace robozoo {

struct RegrownGenome {
  Genome genes;  ///< as logged (id, fitness and all)
  Robot robot;   ///< what they grow under the configuration
};

/// The genes of a logged genome. Throws std::invalid_argument naming the
/// problem when the message does not fit the robot's layout.
Genome logged_genes(const cppn_genome_t& genome);

/// logged_genes(genome) grown under `config` (its run's configuration).
/// Throws what logged_genes and grow_genome throw.
RegrownGenome regrow_genome(const cppn_genome_t& genome, const RunConfig& config);

/// Throws std::runtime_error when `robot` is not the logged `morphology` of
/// genome `genome_id` (another number of spheres, or a sphere elsewhere: another
/// software version or configuration).
void require_logged_morphology(const Robot& robot, const morphology_t& morphology, int64_t genome_id);

}  // namespace robozoo
