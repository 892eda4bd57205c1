#include "evolve/neat/population.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace robozoo {
namespace {

[[noreturn]] void bad(const std::string& key, const std::string& what) {
  throw std::invalid_argument("neat." + key + ": " + what);
}
void probability(const std::string& key, double v) {
  if (!(v >= 0.0 && v <= 1.0)) bad(key, "must be a probability in [0, 1], got " + std::to_string(v));
}
void positive(const std::string& key, double v) {
  if (!(v > 0.0) || !std::isfinite(v)) bad(key, "must be finite and > 0, got " + std::to_string(v));
}
void non_negative(const std::string& key, double v) {
  if (!(v >= 0.0) || !std::isfinite(v)) bad(key, "must be finite and >= 0, got " + std::to_string(v));
}

}  // namespace

void validate_neat_params(const NeatParams& p) {
  if (p.population < 1) bad("population", "must be >= 1, got " + std::to_string(p.population));
  non_negative("disjoint_coefficient", p.disjoint_coefficient);
  non_negative("excess_coefficient", p.excess_coefficient);
  non_negative("weight_coefficient", p.weight_coefficient);
  positive("compatibility_threshold", p.compatibility_threshold);
  non_negative("compatibility_modifier", p.compatibility_modifier);
  positive("min_compatibility_threshold", p.min_compatibility_threshold);
  if (p.target_species < 1) bad("target_species", "must be >= 1, got " + std::to_string(p.target_species));
  probability("survival_threshold", p.survival_threshold);
  if (p.dropoff_age < 1) bad("dropoff_age", "must be >= 1, got " + std::to_string(p.dropoff_age));
  probability("dropoff_factor", p.dropoff_factor);
  probability("add_node_probability", p.add_node_probability);
  probability("add_link_probability", p.add_link_probability);
  probability("mutate_weights_probability", p.mutate_weights_probability);
  if (p.young_link_age < 0) bad("young_link_age", "must be >= 0, got " + std::to_string(p.young_link_age));
  probability("old_link_perturb_probability", p.old_link_perturb_probability);
  non_negative("weight_perturbation", p.weight_perturbation);
  positive("weight_limit", p.weight_limit);
  non_negative("initial_weight_range", p.initial_weight_range);
  probability("mutate_only_probability", p.mutate_only_probability);
  probability("interspecies_mating_probability", p.interspecies_mating_probability);
  if (p.species_elitism_min_offspring < 1)
    bad("species_elitism_min_offspring", "must be >= 1, got " + std::to_string(p.species_elitism_min_offspring));
  if (p.add_link_tries < 0) bad("add_link_tries", "must be >= 0, got " + std::to_string(p.add_link_tries));
  probability("disabled_gene_probability", p.disabled_gene_probability);
  probability("weight_replace_probability", p.weight_replace_probability);
  const uint32_t valid_bits = (1u << kNumActivations) - 1u;
  if (p.hidden_activations == 0 || (p.hidden_activations & ~valid_bits) != 0)
    bad("hidden_activations", "must be a non-empty mask of activation codes 0.." +
                                  std::to_string(kNumActivations - 1) + ", got " +
                                  std::to_string(p.hidden_activations));
}

void validate_regime_links(const Genome& g, Regime regime, const NeatParams& p) {
  for (const auto& l : g.links) {
    if (l.from == l.to && !(regime == Regime::Recurrent && p.self_loops))
      throw std::invalid_argument("genome " + std::to_string(g.id) + " has a self-loop on node " +
                                  std::to_string(l.from) + ", which this regime does not allow");
    if (regime == Regime::FeedForward && p.link_rule == LinkRule::Positions && !is_forward_link(g, l))
      throw std::invalid_argument("genome " + std::to_string(g.id) + " has the link " + std::to_string(l.from) +
                                  " -> " + std::to_string(l.to) + " (innovation " + std::to_string(l.innovation) +
                                  "), which is not forward, in the feed-forward regime");
  }
  if (regime == Regime::FeedForward && p.link_rule == LinkRule::CycleTest) {
    Genome all = g;
    for (auto& l : all.links) l.enabled = true;
    if (has_cycle(all))
      throw std::invalid_argument("genome " + std::to_string(g.id) + " has a cycle in the feed-forward regime");
  }
}

Population::Population(const NeatParams& params, Regime regime, const GenomeLayout& layout, Rng& rng)
    : params_(params), regime_(regime), layout_(layout) {
  validate_neat_params(params_);
  s_.generation = 0;
  s_.compatibility_threshold = params_.compatibility_threshold;
  s_.next_innovation = first_free_innovation(layout_);
  s_.next_node_id = layout_.first_hidden();
  s_.genomes.reserve(static_cast<size_t>(params_.population));
  for (int i = 0; i < params_.population; ++i)
    s_.genomes.push_back(initial_genome(layout_, s_.next_genome_id++, params_, regime_, rng));
  validate_genome(s_.genomes.front(), layout_);
  speciate_current();
}

Population::Population(const NeatParams& params, Regime regime, const GenomeLayout& layout,
                       PopulationState state)
    : params_(params), regime_(regime), layout_(layout), s_(std::move(state)) {
  validate_neat_params(params_);
  auto fail = [](const std::string& what) {
    throw std::invalid_argument("population state: " + what);
  };
  const size_t n = s_.genomes.size();
  if (static_cast<int>(n) != params_.population)
    fail("has " + std::to_string(n) + " genomes, the parameters say " + std::to_string(params_.population));
  if (s_.species_of.size() != n)
    fail("has " + std::to_string(s_.species_of.size()) + " species ids for " + std::to_string(n) + " genomes");
  if (!(s_.compatibility_threshold > 0.0) || !std::isfinite(s_.compatibility_threshold))
    fail("compatibility threshold must be finite and > 0");
  if (!(s_.speciation_threshold > 0.0) || !std::isfinite(s_.speciation_threshold))
    fail("speciation threshold must be finite and > 0");
  int64_t max_innovation = -1, max_id = -1;
  int32_t max_node = layout_.first_hidden() - 1;
  for (const auto& g : s_.genomes) {
    validate_genome(g, layout_);
    try {
      validate_regime_links(g, regime_, params_);
    } catch (const std::invalid_argument& e) {
      fail(e.what());
    }
    max_id = std::max(max_id, g.id);
    if (!g.links.empty()) max_innovation = std::max(max_innovation, g.links.back().innovation);
    max_node = std::max(max_node, g.nodes.back().id);
  }
  if (s_.next_genome_id <= max_id) fail("next genome id is not above every genome id");
  if (s_.next_innovation <= max_innovation) fail("next innovation is not above every innovation");
  if (s_.next_node_id <= max_node) fail("next node id is not above every node id");
  std::vector<int> seen(n, 0);
  for (const auto& sp : s_.species) {
    if (sp.id >= s_.next_species_id) fail("species id " + std::to_string(sp.id) + " is not below the next species id");
    if (sp.members.empty()) fail("species " + std::to_string(sp.id) + " has no members");
    validate_genome(sp.representative, layout_);
    for (int m : sp.members) {
      if (m < 0 || static_cast<size_t>(m) >= n) fail("species " + std::to_string(sp.id) + " has member index " + std::to_string(m) + " out of range");
      if (seen[static_cast<size_t>(m)]++) fail("genome index " + std::to_string(m) + " is in two species");
      if (s_.species_of[static_cast<size_t>(m)] != sp.id)
        fail("genome index " + std::to_string(m) + " is listed in species " + std::to_string(sp.id) +
             " but its species id is " + std::to_string(s_.species_of[static_cast<size_t>(m)]));
    }
  }
  for (size_t i = 0; i < n; ++i)
    if (!seen[i]) fail("genome index " + std::to_string(i) + " belongs to no species");
}

void Population::speciate_current() {
  s_.speciation_threshold = s_.compatibility_threshold;
  s_.species_of = speciate(s_.genomes, s_.species, s_.compatibility_threshold, params_,
                           s_.next_species_id, s_.generation);
  s_.compatibility_threshold =
      adjust_threshold(s_.compatibility_threshold, static_cast<int>(s_.species.size()), params_);
}

void Population::advance(const std::vector<double>& fitness, Rng& rng) {
  const size_t n = s_.genomes.size();
  if (fitness.size() != n)
    throw std::invalid_argument("Population::advance: " + std::to_string(fitness.size()) +
                                " fitness values for " + std::to_string(n) + " genomes");
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(fitness[i]) || fitness[i] < 0.0)
      throw std::invalid_argument("Population::advance: fitness of genome " +
                                  std::to_string(s_.genomes[i].id) + " (index " + std::to_string(i) +
                                  ") must be finite and >= 0, got " + std::to_string(fitness[i]));
  const int32_t gen = s_.generation;
  auto& species = s_.species;

  // 1. Rank each species' members; find the generation champion.
  for (auto& sp : species)
    std::stable_sort(sp.members.begin(), sp.members.end(),
                     [&](int a, int b) { return fitness[static_cast<size_t>(a)] > fitness[static_cast<size_t>(b)]; });
  size_t champ = 0;
  for (size_t i = 1; i < n; ++i)
    if (fitness[i] > fitness[champ]) champ = i;
  size_t champ_si = species.size();
  for (size_t si = 0; si < species.size(); ++si)
    if (species[si].id == s_.species_of[champ]) champ_si = si;
  if (champ_si == species.size()) throw std::logic_error("Population::advance: champion in no species");

  // 2. Improvement and stagnation; 3. sharing and allocation.
  GenerationReport rep;
  rep.generation = gen;
  rep.champion = champ;
  rep.champion_fitness = fitness[champ];
  std::vector<double> sizes;
  for (size_t si = 0; si < species.size(); ++si) {
    Species& sp = species[si];
    const double best = fitness[static_cast<size_t>(sp.members.front())];
    if (best > sp.best_fitness) {
      sp.best_fitness = best;
      sp.last_improvement = gen;
    }
    if (si == champ_si) sp.last_improvement = gen;
    rep.species_ids.push_back(sp.id);
    rep.stagnant.push_back(is_stagnant(sp, gen, params_));
    rep.adjusted.push_back(species_adjusted_fitness(sp, fitness, gen, params_));
    sizes.push_back(static_cast<double>(sp.members.size()));
  }
  std::vector<int> counts = allocate_offspring(rep.adjusted, static_cast<int>(n), sizes);
  if (counts[champ_si] == 0) {
    const size_t donor = static_cast<size_t>(std::max_element(counts.begin(), counts.end()) - counts.begin());
    --counts[donor];
    ++counts[champ_si];
  }
  rep.offspring = counts;

  // 4. Breed.
  InnovationTracker tracker(s_.next_innovation, s_.next_node_id);
  const int32_t child_gen = gen + 1;
  std::vector<Genome> next;
  next.reserve(n);
  auto copy_unchanged = [&](size_t idx) {
    Genome c = s_.genomes[idx];
    c.id = s_.next_genome_id++;
    next.push_back(std::move(c));
  };
  copy_unchanged(champ);
  for (size_t si = 0; si < species.size(); ++si) {
    const Species& sp = species[si];
    int remaining = counts[si];
    if (si == champ_si) {
      --remaining;  // the generation champion is this species' unchanged copy
    } else if (remaining >= params_.species_elitism_min_offspring) {
      copy_unchanged(static_cast<size_t>(sp.members.front()));
      --remaining;
    }
    const int np = num_parents(static_cast<int>(sp.members.size()), params_);
    for (int k = 0; k < remaining; ++k) {
      Genome child;
      const size_t pa = rng.index(static_cast<size_t>(np));
      const size_t a = static_cast<size_t>(sp.members[pa]);
      if (np == 1 || rng.bernoulli(params_.mutate_only_probability)) {
        child = s_.genomes[a];
      } else {
        size_t b;
        if (species.size() > 1 && rng.bernoulli(params_.interspecies_mating_probability)) {
          size_t other = rng.index(species.size() - 1);
          if (other >= si) ++other;
          b = static_cast<size_t>(species[other].members.front());
        } else {
          size_t pb = rng.index(static_cast<size_t>(np - 1));
          if (pb >= pa) ++pb;
          b = static_cast<size_t>(sp.members[pb]);
        }
        child = crossover(s_.genomes[a], fitness[a], s_.genomes[b], fitness[b], params_, rng);
      }
      child.id = s_.next_genome_id++;
      mutate(child, regime_, layout_, params_, tracker, child_gen, rng);
      next.push_back(std::move(child));
    }
  }
  if (next.size() != n)
    throw std::logic_error("Population::advance: bred " + std::to_string(next.size()) +
                           " genomes for a population of " + std::to_string(n));

  // 5. Species without offspring die; the others are represented by their
  // champion of this generation. Then the new generation is speciated.
  std::vector<Species> surviving;
  for (size_t si = 0; si < species.size(); ++si) {
    if (counts[si] == 0) continue;
    Species sp = std::move(species[si]);
    sp.representative = s_.genomes[static_cast<size_t>(sp.members.front())];
    sp.age += 1;
    surviving.push_back(std::move(sp));
  }
  species = std::move(surviving);
  s_.genomes = std::move(next);
  s_.generation = child_gen;
  s_.next_innovation = tracker.next_innovation();
  s_.next_node_id = tracker.next_node_id();
  speciate_current();
  report_ = std::move(rep);
}

}  // namespace robozoo
