#include "render/scene/robot_card.hpp"

#include <cstdio>
#include <stdexcept>

namespace robozoo::render {

RobotCard make_card(const RunRecord& run, const GenomeRecord& genome) {
  if (!genome.has_morphology)
    throw std::invalid_argument("genome " + std::to_string(genome.genome.genome_id) + " has no morphology in the log");
  RobotCard c;
  c.run_id = run.run.run_id;
  c.regime = run.run.regime;
  c.generation = genome.genome.generation;
  c.genome_id = genome.genome.genome_id;
  c.fitness = genome.genome.fitness;
  c.r_term = genome.genome.r_term;
  c.d_term = genome.genome.d_term;
  c.shape = shape_from_morphology(genome.morphology);
  return c;
}

std::string regime_label(int regime) { return regime == 1 ? "recurrent" : "feed-forward"; }

std::vector<std::string> card_caption(const RobotCard& card) {
  if (!card.caption.empty()) return card.caption;
  char line[160];
  std::snprintf(line, sizeof line, "%s \u00b7 generation %d \u00b7 fitness %.2f", regime_label(card.regime).c_str(),
                card.generation, card.fitness);
  return {card.run_id, line};
}

}  // namespace robozoo::render
