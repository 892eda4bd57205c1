#include "runlog/robots/regrow.hpp"

#include <stdexcept>
#include <string>

#include "evolve/fitness/evaluate.hpp"
#include "evolve/messages/build.hpp"

namespace robozoo {

Genome logged_genes(const cppn_genome_t& genome) { return genome_from_message(genome, robot_layout()); }

RegrownGenome regrow_genome(const cppn_genome_t& genome, const RunConfig& config) {
  RegrownGenome r;
  r.genes = logged_genes(genome);
  r.robot = grow_genome(r.genes, config.eval);
  return r;
}

void require_logged_morphology(const Robot& robot, const morphology_t& morphology, int64_t genome_id) {
  if (robot.spheres.size() != morphology.spheres.size())
    throw std::runtime_error("re-growing genome " + std::to_string(genome_id) + " gave " +
                             std::to_string(robot.spheres.size()) + " spheres, the log has " +
                             std::to_string(morphology.spheres.size()) + " (another version or configuration?)");
  for (size_t i = 0; i < robot.spheres.size(); ++i)
    for (int k = 0; k < 3; ++k)
      if (robot.spheres[i].center[k] != morphology.spheres[i].center[k])
        throw std::runtime_error("re-growing genome " + std::to_string(genome_id) + " moved sphere " +
                                 std::to_string(i) + " from where the log has it");
}

}  // namespace robozoo
