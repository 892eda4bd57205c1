#pragma once
// CPPN-NEAT parameters. Defaults are those of the C++ HyperNEAT package the
// paper names, as its authors' own parameter files set them (DESIGN.md section 2).
#include <cstdint>

namespace robozoo {

/// Control regime: add-link never closes a cycle. Experimental: any link, self-loops included.
enum class Regime : int8_t { FeedForward = 0, Recurrent = 1 };

struct NeatParams {
  int population = 150;                  ///< genomes per generation (count)
  // Compatibility distance: c_d * D / N + c_e * E / N + c_w * Wbar, with N = 1.
  double disjoint_coefficient = 2.0;     ///< c_d (distance units per gene)
  double excess_coefficient = 2.0;       ///< c_e (distance units per gene)
  double weight_coefficient = 1.0;       ///< c_w (distance units per unit of weight difference)
  double compatibility_threshold = 6.0;  ///< initial threshold (distance units)
  double compatibility_modifier = 0.3;   ///< threshold step per generation (distance units)
  double min_compatibility_threshold = 0.3;  ///< the threshold never goes below this (distance units)
  int target_species = 8;                ///< threshold moves towards this many species (count)
  double survival_threshold = 0.2;       ///< fraction of each species allowed to reproduce
  int dropoff_age = 15;                  ///< generations without improvement before penalty
  double dropoff_factor = 0.001;         ///< fitness multiplier of a stagnant species
  double add_node_probability = 0.03;    ///< per offspring
  double add_link_probability = 0.05;    ///< per offspring
  double mutate_weights_probability = 0.8;  ///< per offspring
  int young_link_age = 18;               ///< links younger than this (generations) are always perturbed
  double old_link_perturb_probability = 0.1;  ///< per older link, when weights mutate
  double weight_perturbation = 2.5;      ///< perturbation uniform in [-x, x] (weight units)
  double weight_limit = 5.0;             ///< weights clamped to [-x, x] (weight units)
  double initial_weight_range = 3.0;     ///< initial weights uniform in [-x, x] (weight units)
  double mutate_only_probability = 0.25; ///< offspring made by mutation alone (no crossover)
  double interspecies_mating_probability = 0.001;  ///< crossover partner from another species
  int species_elitism_min_offspring = 5; ///< a species with at least this many offspring keeps its champion
  int add_link_tries = 20;               ///< attempts to find a new, legal link (count)
  /// Activation functions a new hidden node may get, as a bit mask over Activation
  /// codes: default signed sigmoid, signed cosine and Gaussian (bits 0, 1, 2).
  uint32_t hidden_activations = 0b111;
};

}  // namespace robozoo
