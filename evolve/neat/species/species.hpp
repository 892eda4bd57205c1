#pragma once
// A NEAT species: a group of genomes within the compatibility threshold of its
// representative, with the history that drop-off (stagnation) needs.
#include <cstdint>
#include <vector>

#include "evolve/cppn/genome.hpp"

namespace robozoo {

struct Species {
  int32_t id = 0;
  int32_t age = 0;               ///< generations since creation (count)
  int32_t last_improvement = 0;  ///< generation its best fitness last improved (generation)
  double best_fitness = 0.0;     ///< best raw fitness ever seen in it (fitness units)
  Genome representative;         ///< compared against during speciation
  std::vector<int> members;      ///< indices into the current population, ascending
  bool operator==(const Species& o) const {
    return id == o.id && age == o.age && last_improvement == o.last_improvement && best_fitness == o.best_fitness &&
           representative == o.representative && members == o.members;
  }
};

}  // namespace robozoo
