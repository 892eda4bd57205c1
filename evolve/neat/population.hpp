#pragma once
// A CPPN-NEAT population: speciation with a dynamic threshold, fitness sharing,
// drop-off age, survival threshold, elitism, crossover and mutation.
// All randomness comes from the Rng passed in.
#include <cstdint>
#include <string>
#include <vector>

#include "evolve/core/rng.hpp"
#include "evolve/cppn/genome.hpp"
#include "evolve/neat/params.hpp"

namespace robozoo {

struct Species {
  int32_t id = 0;
  int32_t age = 0;                 ///< generations since creation
  int32_t last_improvement = 0;    ///< generation its best fitness last improved
  double best_fitness = 0.0;       ///< best raw fitness ever seen in it
  Genome representative;           ///< compared against during speciation
  std::vector<int> members;        ///< indices into the current population
};

/// Everything needed to continue a run exactly (for checkpoints).
struct PopulationState {
  int32_t generation = 0;
  int64_t next_genome_id = 0;
  int64_t next_innovation = 0;
  int32_t next_node_id = 0;
  int32_t next_species_id = 0;
  double compatibility_threshold = 6.0;
  std::vector<Genome> genomes;
  std::vector<int32_t> species_of;  ///< species id of each genome (after speciation)
  std::vector<Species> species;
};

class Population {
 public:
  /// Generation 0: every genome links every input to every output with weights
  /// uniform in [-initial_weight_range, initial_weight_range] and no hidden node.
  Population(const NeatParams& params, Regime regime, const GenomeLayout& layout, Rng& rng);
  /// Continues from a saved state (see state()).
  Population(const NeatParams& params, Regime regime, const GenomeLayout& layout,
             PopulationState state);

  const std::vector<Genome>& genomes() const;
  int generation() const;
  /// Species id of genome i of the current generation.
  int32_t species_of(size_t i) const;
  const std::vector<Species>& species() const;
  double compatibility_threshold() const;

  /// Fitnesses of the current generation, in genome order (non-negative).
  /// Then speciates, shares fitness and breeds the next generation.
  void advance(const std::vector<double>& fitness, Rng& rng);

  const PopulationState& state() const;

 private:
  NeatParams params_;
  Regime regime_;
  GenomeLayout layout_;
  PopulationState s_;
};

/// Compatibility distance of NEAT (genes aligned by innovation, N = 1).
double compatibility_distance(const Genome& a, const Genome& b, const NeatParams& p);

/// Uniform-by-innovation crossover: matching genes from either parent at random,
/// disjoint and excess genes from the fitter parent (`a` when fitness_a >= fitness_b).
Genome crossover(const Genome& a, double fitness_a, const Genome& b, double fitness_b, Rng& rng);

/// Innovation numbers handed out within one generation: the same structural
/// mutation (same from/to link, or same split link) gets the same number.
class InnovationTracker {
 public:
  InnovationTracker(int64_t next_innovation, int32_t next_node_id)
      : next_innovation_(next_innovation), next_node_id_(next_node_id) {}
  /// Innovation number for a new link from -> to.
  int64_t link(int32_t from, int32_t to);
  /// Node id and the two link innovations for splitting the link with the given innovation.
  struct Split { int32_t node; int64_t in_link; int64_t out_link; };
  Split split(int64_t link_innovation);
  /// Forget this generation's mutations (numbers keep increasing).
  void new_generation();
  int64_t next_innovation() const { return next_innovation_; }
  int32_t next_node_id() const { return next_node_id_; }

 private:
  int64_t next_innovation_;
  int32_t next_node_id_;
  std::vector<std::pair<std::pair<int32_t, int32_t>, int64_t>> links_;
  std::vector<std::pair<int64_t, Split>> splits_;
};

/// Mutations (each returns true if it changed the genome).
bool mutate_add_link(Genome& g, Regime regime, const GenomeLayout& layout, const NeatParams& p,
                     InnovationTracker& innov, int32_t generation, Rng& rng);
bool mutate_add_node(Genome& g, const NeatParams& p, InnovationTracker& innov,
                     int32_t generation, Rng& rng);
void mutate_weights(Genome& g, const NeatParams& p, int32_t generation, Rng& rng);

}  // namespace robozoo
