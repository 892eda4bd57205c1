#pragma once
// A CPPN-NEAT population: speciation with a dynamic threshold, fitness sharing,
// drop-off age, survival threshold, elitism, crossover and mutation.
// All randomness comes from the Rng passed in.
//
// One generation, as Population::advance runs it (docs/method.md, "CPPN-NEAT";
// where the paper is silent the C++ HyperNEAT package decides; the defaults are
// HyperNEAT's mechanics, robozoo's earlier ones noted in brackets):
//  1. Each species' members are ranked by raw fitness (stable: ties keep
//     population order). The generation champion is the first genome with the
//     highest fitness.
//  2. Stagnation (stagnation = hyperneat): judged first, a species is stagnant
//     more than dropoff_age generations after its last improvement (its
//     founding counts as the previous generation's); then this generation's
//     improvement is recorded: its champion beating its best fitness (not in
//     its first generation), or holding the generation champion. [robozoo:
//     improvement recorded first, stagnant dropoff_age generations after it.]
//  3. Explicit fitness sharing: a species' share is its mean raw fitness
//     (times dropoff_factor when stagnant); each species gets the whole part
//     of its proportional share, the rest go one each to the species of the
//     best genomes, best first (offspring_rounding = best_first) [largest
//     remainder]. The champion's species gets at least one (taken from the
//     largest allocation).
//  4. The next generation starts with an unchanged copy of the generation
//     champion; then, species by species, an unchanged copy of the species
//     champion when the species has at least species_elitism_min_offspring
//     offspring (the generation champion counts as its species' copy), and the
//     rest as children of the best num_parents() members: with
//     mutate_only_probability (or when only one parent) a mutated copy of one
//     parent, else a mutated crossover of two different parents (the second
//     from another species' champion with interspecies_mating_probability, 0
//     in HyperNEAT). Crossover and mutation follow crossover_genes and
//     mutation_order.
//  5. Every species' representative becomes its best genome ever
//     (representative = best_ever) [its champion of the generation]; species
//     without offspring stay candidates (childless_species_stay) [die]; the new
//     generation is speciated in order against them (species left without
//     members die), then the threshold adjusted (threshold_rule).
// Copies get fresh ids: every genome of a run has its own id, increasing.
//
// Options that follow Stanley's own NEAT C++ instead (all off by default; the
// neat-paper XOR preset uses them on top of NeatMechanics::Robozoo; see params.hpp): crossover_rule, mate_average_probability, mate_only_probability
// and independent_parents change step 4's matings; keep_generation_champion =
// false drops the generation champion's copy and its species' guaranteed
// offspring; stagnation = stanley decides stagnation before this generation's
// improvement, with no exemption; offspring_rounding = skim divides offspring by
// carried fractions; population_stagnation_generations > 0 lets only the two
// best species reproduce, from their champions, after that many generations
// without a new population record; childless_species_stay keeps a species
// without offspring as a speciation candidate in step 5.
#include <cstdint>
#include <string>
#include <vector>

#include "evolve/core/rng.hpp"
#include "evolve/cppn/genome.hpp"
#include "evolve/neat/species/compatibility.hpp"
#include "evolve/neat/variation/crossover.hpp"
#include "evolve/neat/start/initial_genome.hpp"
#include "evolve/neat/variation/innovation.hpp"
#include "evolve/neat/variation/mutation.hpp"
#include "evolve/neat/params.hpp"
#include "evolve/neat/species/reproduction.hpp"
#include "evolve/neat/species/speciation.hpp"
#include "evolve/neat/species/species.hpp"

namespace robozoo {

/// Everything needed to continue a run exactly (for checkpoints), apart from
/// the Rng (save Rng::state() beside it).
struct PopulationState {
  int32_t generation = 0;
  int64_t next_genome_id = 0;
  int64_t next_innovation = 0;
  int32_t next_node_id = 0;
  int32_t next_species_id = 0;
  double compatibility_threshold = 6.0;  ///< threshold the next speciation uses (distance units)
  double speciation_threshold = 6.0;     ///< threshold the current generation was speciated with (distance units)
  std::vector<Genome> genomes;
  std::vector<int32_t> species_of;  ///< species id of each genome (after speciation)
  std::vector<Species> species;
  /// Population-level stagnation (neat.population_stagnation_generations > 0 only; else both
  /// stay 0): the best raw fitness the population has reached (fitness units) and the
  /// generations since it was last beaten (count).
  double record_fitness = 0.0;
  int32_t generations_since_record = 0;
  bool operator==(const PopulationState& o) const {
    return generation == o.generation && next_genome_id == o.next_genome_id && record_fitness == o.record_fitness &&
           generations_since_record == o.generations_since_record && next_innovation == o.next_innovation &&
           next_node_id == o.next_node_id && next_species_id == o.next_species_id &&
           compatibility_threshold == o.compatibility_threshold && speciation_threshold == o.speciation_threshold &&
           genomes == o.genomes && species_of == o.species_of && species == o.species;
  }
};

/// What advance() did with the generation it was given (for logs and tests).
struct GenerationReport {
  int32_t generation = 0;            ///< the generation that was evaluated
  size_t champion = 0;               ///< index of the generation champion in it
  double champion_fitness = 0.0;     ///< its raw fitness
  std::vector<int32_t> species_ids;  ///< species, in order
  std::vector<double> adjusted;      ///< each species' shared (and dropped-off) fitness
  std::vector<int> offspring;        ///< offspring allocated to each species (sum = population)
  std::vector<bool> stagnant;        ///< whether each species was stagnant
  /// Population-level stagnation struck: only the two best species reproduced, from their champions.
  bool population_stagnation = false;
};

class Population {
 public:
  /// Generation 0: params.population genomes made by initial_genome (ids 0..P-1),
  /// speciated. Throws std::invalid_argument for bad parameters.
  /// A saved state is checked against the regime's link rules (validate_regime_links).
  Population(const NeatParams& params, Regime regime, const GenomeLayout& layout, Rng& rng);
  /// Continues from a saved state (see state()). Throws std::invalid_argument
  /// if the state does not fit the parameters and layout.
  Population(const NeatParams& params, Regime regime, const GenomeLayout& layout, PopulationState state);

  const std::vector<Genome>& genomes() const { return s_.genomes; }
  int generation() const { return s_.generation; }
  /// Species id of genome i of the current generation.
  int32_t species_of(size_t i) const { return s_.species_of.at(i); }
  const std::vector<Species>& species() const { return s_.species; }
  /// The threshold the next generation will be speciated with.
  double compatibility_threshold() const { return s_.compatibility_threshold; }
  /// The threshold in force for the current generation: the one it was speciated with.
  double speciation_threshold() const { return s_.speciation_threshold; }

  /// Fitnesses of the current generation, in genome order (finite, >= 0;
  /// std::invalid_argument otherwise). Then shares fitness and breeds and
  /// speciates the next generation.
  void advance(const std::vector<double>& fitness, Rng& rng);
  /// The report of the last advance() (empty before the first).
  const GenerationReport& last_report() const { return report_; }

  const PopulationState& state() const { return s_; }
  const NeatParams& params() const { return params_; }
  Regime regime() const { return regime_; }
  const GenomeLayout& layout() const { return layout_; }

 private:
  void speciate_current();

  NeatParams params_;
  Regime regime_;
  GenomeLayout layout_;
  PopulationState s_;
  GenerationReport report_;
};

/// Throws std::invalid_argument naming the first parameter out of range.
void validate_neat_params(const NeatParams& p);

/// Throws std::invalid_argument when the parameters do not fit the regime: a crossover that joins
/// both parents' links (crossover_genes both / drawn) with the cycle-test link rule in the
/// feed-forward regime, where the union of two acyclic genomes may hold a cycle.
void validate_regime_params(Regime regime, const NeatParams& p);

/// Throws std::invalid_argument when g holds a link gene (enabled or not) that
/// the regime never allows: in the feed-forward regime a non-forward link
/// (LinkRule::Positions) or a cycle (CycleTest); a self-loop unless the
/// recurrent regime allows self-loops.
void validate_regime_links(const Genome& g, Regime regime, const NeatParams& p);

}  // namespace robozoo
