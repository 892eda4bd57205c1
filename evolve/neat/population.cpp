#include "evolve/neat/population.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace robozoo {
namespace {

// Stanley's Species::reproduce, population-level stagnation: the probability that a mutated copy
// of a champion gets its weights mutated (else a new link).
constexpr double kChampionWeightMutationProbability = 0.8;

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
  probability("mate_average_probability", p.mate_average_probability);
  probability("mate_only_probability", p.mate_only_probability);
  if (p.population_stagnation_generations < 0)
    bad("population_stagnation_generations",
        "must be >= 0, got " + std::to_string(p.population_stagnation_generations));
  const uint32_t valid_bits = (1u << kNumActivations) - 1u;
  if (p.hidden_activations == 0 || (p.hidden_activations & ~valid_bits) != 0)
    bad("hidden_activations", "must be a non-empty mask of activation codes 0.." + std::to_string(kNumActivations - 1) +
                                  ", got " + std::to_string(p.hidden_activations));
}

void validate_regime_params(Regime regime, const NeatParams& p) {
  if (regime == Regime::FeedForward && p.link_rule == LinkRule::CycleTest &&
      p.crossover_genes != CrossoverGenes::Fitter)
    throw std::invalid_argument("neat.crossover_genes: " + crossover_genes_name(p.crossover_genes) +
                                " joins both parents' links, which can close a cycle under neat.link_rule = "
                                "cycle_test in the feed-forward regime (use fitter, or link_rule positions)");
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
  validate_regime_params(regime_, params_);
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

Population::Population(const NeatParams& params, Regime regime, const GenomeLayout& layout, PopulationState state)
    : params_(params), regime_(regime), layout_(layout), s_(std::move(state)) {
  validate_neat_params(params_);
  validate_regime_params(regime_, params_);
  auto fail = [](const std::string& what) { throw std::invalid_argument("population state: " + what); };
  const size_t n = s_.genomes.size();
  if (static_cast<int>(n) != params_.population)
    fail("has " + std::to_string(n) + " genomes, the parameters say " + std::to_string(params_.population));
  if (s_.species_of.size() != n)
    fail("has " + std::to_string(s_.species_of.size()) + " species ids for " + std::to_string(n) + " genomes");
  if (!(s_.compatibility_threshold > 0.0) || !std::isfinite(s_.compatibility_threshold))
    fail("compatibility threshold must be finite and > 0");
  if (!(s_.speciation_threshold > 0.0) || !std::isfinite(s_.speciation_threshold))
    fail("speciation threshold must be finite and > 0");
  if (!(s_.record_fitness >= 0.0) || !std::isfinite(s_.record_fitness)) fail("record fitness must be finite and >= 0");
  if (s_.generations_since_record < 0) fail("generations since the record must be >= 0");
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
      if (m < 0 || static_cast<size_t>(m) >= n)
        fail("species " + std::to_string(sp.id) + " has member index " + std::to_string(m) + " out of range");
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
  s_.species_of =
      speciate(s_.genomes, s_.species, s_.compatibility_threshold, params_, s_.next_species_id, s_.generation);
  s_.compatibility_threshold =
      adjust_threshold(s_.compatibility_threshold, static_cast<int>(s_.species.size()), params_);
}

namespace {

/// advance()'s input check: one finite, non-negative fitness per genome.
void check_fitness(const std::vector<Genome>& genomes, const std::vector<double>& fitness) {
  const size_t n = genomes.size();
  if (fitness.size() != n)
    throw std::invalid_argument("Population::advance: " + std::to_string(fitness.size()) + " fitness values for " +
                                std::to_string(n) + " genomes");
  for (size_t i = 0; i < n; ++i)
    if (!std::isfinite(fitness[i]) || fitness[i] < 0.0)
      throw std::invalid_argument("Population::advance: fitness of genome " + std::to_string(genomes[i].id) +
                                  " (index " + std::to_string(i) + ") must be finite and >= 0, got " +
                                  std::to_string(fitness[i]));
}

/// The generation champion: its genome index and its species' position in the species list.
struct Champion {
  size_t index = 0;
  size_t species = 0;
};

/// Step 1: ranks each species' members, best first; finds the generation champion.
Champion rank_species(PopulationState& s, const std::vector<double>& fitness) {
  auto& species = s.species;
  for (auto& sp : species)
    std::stable_sort(sp.members.begin(), sp.members.end(),
                     [&](int a, int b) { return fitness[static_cast<size_t>(a)] > fitness[static_cast<size_t>(b)]; });
  Champion champ;
  for (size_t i = 1; i < fitness.size(); ++i)
    if (fitness[i] > fitness[champ.index]) champ.index = i;
  champ.species = species.size();
  for (size_t si = 0; si < species.size(); ++si)
    if (species[si].id == s.species_of[champ.index]) champ.species = si;
  if (champ.species == species.size()) throw std::logic_error("Population::advance: champion in no species");
  return champ;
}

/// What step 2 found out about each species, in species order.
struct SpeciesJudgement {
  std::vector<double> sizes;  ///< members (count)
  /// Whether the species' champion becomes its best genome ever (Representative::BestEver): in its
  /// first generation, or when it beats the species' best fitness.
  std::vector<char> new_best;
};

/// Step 2: records each species' improvement and judges its stagnation by the parameters' rule;
/// fills the report's species ids, stagnation and shared (dropped-off) fitness.
SpeciesJudgement judge_species(std::vector<Species>& species, const std::vector<double>& fitness, size_t champ_si,
                               int32_t gen, const NeatParams& params, GenerationReport& rep) {
  const bool stanley_stagnation = params.stagnation == StagnationRule::Stanley;
  const bool hyperneat_stagnation = params.stagnation == StagnationRule::HyperNeat;
  SpeciesJudgement j;
  j.new_best.assign(species.size(), 0);
  for (size_t si = 0; si < species.size(); ++si) {
    Species& sp = species[si];
    const double best = fitness[static_cast<size_t>(sp.members.front())];
    j.new_best[si] = sp.age == 0 || best > sp.best_fitness;
    bool stagnant;
    if (hyperneat_stagnation) {
      // HyperNEAT: judged before this generation's improvement is recorded (the improvement of
      // generation h counts from h + 1); a species' first generation is no improvement.
      stagnant = gen - sp.last_improvement > params.dropoff_age;
      if (sp.age == 0) {
        sp.best_fitness = std::max(sp.best_fitness, best);
      } else if (best > sp.best_fitness) {
        sp.best_fitness = best;
        sp.last_improvement = gen;
      }
      if (si == champ_si) sp.last_improvement = gen;
    } else if (stanley_stagnation) {
      // Stanley: judged before this generation's improvement is recorded; his age debt of 0
      // counts as 1, so the penalty starts dropoff_age - 1 generations after the improvement.
      stagnant = gen - sp.last_improvement >= params.dropoff_age - 1;
      if (best > sp.best_fitness) {
        sp.best_fitness = best;
        sp.last_improvement = gen;
      }
    } else {
      if (best > sp.best_fitness) {
        sp.best_fitness = best;
        sp.last_improvement = gen;
      }
      if (si == champ_si) sp.last_improvement = gen;
      stagnant = is_stagnant(sp, gen, params);
    }
    rep.species_ids.push_back(sp.id);
    rep.stagnant.push_back(stagnant);
    double shared = 0.0;
    const double size = static_cast<double>(sp.members.size());
    for (int m : sp.members) shared += fitness[static_cast<size_t>(m)] / size;
    rep.adjusted.push_back(stagnant ? shared * params.dropoff_factor : shared);
    j.sizes.push_back(size);
  }
  return j;
}

/// Step 3: offspring per species by the parameters' rounding rule.
std::vector<int> allocate_counts(const PopulationState& s, const std::vector<double>& fitness,
                                 const GenerationReport& rep, const std::vector<double>& sizes,
                                 const NeatParams& params) {
  const auto& species = s.species;
  const size_t n = fitness.size();
  const bool any_share = std::any_of(rep.adjusted.begin(), rep.adjusted.end(), [](double a) { return a > 0.0; });
  if (params.offspring_rounding == OffspringRounding::Skim && any_share) {
    std::vector<std::vector<double>> values(species.size());
    for (size_t si = 0; si < species.size(); ++si) {
      const double size = sizes[si];
      for (int m : species[si].members) {
        const double f = fitness[static_cast<size_t>(m)];
        values[si].push_back((rep.stagnant[si] ? f * params.dropoff_factor : f) / size);
      }
    }
    return allocate_offspring_skim(values, static_cast<int>(n));
  }
  if (params.offspring_rounding == OffspringRounding::BestFirst) {
    std::vector<size_t> order(n);
    for (size_t i = 0; i < n; ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t x, size_t y) { return fitness[x] > fitness[y]; });
    std::vector<size_t> species_by_rank;
    species_by_rank.reserve(n);
    for (size_t i : order)
      for (size_t si = 0; si < species.size(); ++si)
        if (species[si].id == s.species_of[i]) {
          species_by_rank.push_back(si);
          break;
        }
    return allocate_offspring_best_first(rep.adjusted, static_cast<int>(n), species_by_rank);
  }
  return allocate_offspring(rep.adjusted, static_cast<int>(n), sizes);
}

/// Population-level stagnation (Stanley's delta coding): when the record fitness has not been
/// beaten for long enough, the two species with the best champions get half the population each,
/// all from their champions. Rewrites `counts` then; returns which species breed from their
/// champion only.
std::vector<char> population_stagnation(PopulationState& s, const std::vector<double>& fitness, size_t champ,
                                        int32_t gen, const NeatParams& params, std::vector<int>& counts,
                                        GenerationReport& rep) {
  auto& species = s.species;
  std::vector<char> from_champion(species.size(), 0);
  if (params.population_stagnation_generations <= 0) return from_champion;
  if (fitness[champ] > s.record_fitness) {
    s.record_fitness = fitness[champ];
    s.generations_since_record = 0;
  } else {
    ++s.generations_since_record;
  }
  if (s.generations_since_record < params.population_stagnation_generations) return from_champion;
  s.generations_since_record = 0;
  rep.population_stagnation = true;
  std::vector<size_t> order(species.size());
  for (size_t si = 0; si < order.size(); ++si) order[si] = si;
  std::stable_sort(order.begin(), order.end(), [&](size_t x, size_t y) {
    return fitness[static_cast<size_t>(species[x].members.front())] >
           fitness[static_cast<size_t>(species[y].members.front())];
  });
  std::fill(counts.begin(), counts.end(), 0);
  const size_t n = fitness.size();
  const int half = static_cast<int>(n) / 2;
  // With one species only it gets the whole population (Stanley's code gives it n - n/2,
  // which would shrink the population).
  const size_t top = order.size() >= 2 ? 2 : 1;
  for (size_t k = 0; k < top; ++k) {
    const size_t si = order[k];
    counts[si] = top == 1 ? static_cast<int>(n) : (k == 0 ? half : static_cast<int>(n) - half);
    from_champion[si] = 1;
    species[si].last_improvement = gen;
  }
  return from_champion;
}

/// Step 4: breeding the next generation's genomes, in order, with fresh ids.
struct Breeding {
  PopulationState& s;
  const NeatParams& params;
  Regime regime;
  const GenomeLayout& layout;
  const std::vector<double>& fitness;
  InnovationTracker& tracker;
  int32_t child_gen;
  Rng& rng;
  std::vector<Genome> next;

  void copy_unchanged(size_t idx) {
    Genome c = s.genomes[idx];
    c.id = s.next_genome_id++;
    next.push_back(std::move(c));
  }

  /// Every offspring a mutated copy of the species' champion (weights with probability 0.8, else a
  /// new link), the last an unchanged copy unless the generation champion's copy is already made.
  void champion_copies(const Species& sp, int remaining, bool champion_copied) {
    const size_t c = static_cast<size_t>(sp.members.front());
    for (int k = 0; k < remaining; ++k) {
      if (k == remaining - 1 && !champion_copied) {
        copy_unchanged(c);
        continue;
      }
      Genome child = s.genomes[c];
      child.id = s.next_genome_id++;
      if (params.add_link_probability == 0.0 || rng.bernoulli(kChampionWeightMutationProbability))
        mutate_weights(child, params, child_gen, rng);
      else
        mutate_add_link(child, regime, layout, params, tracker, child_gen, rng);
      next.push_back(std::move(child));
    }
  }

  /// `count` offspring of species `si`: a parent from its best, mated (within the species or, by
  /// chance, with another species' champion) or copied, then mutated.
  void offspring(size_t si, int count) {
    const auto& species = s.species;
    const Species& sp = species[si];
    const int np = num_parents(static_cast<int>(sp.members.size()), params);
    for (int k = 0; k < count; ++k) {
      Genome child;
      const size_t pa = rng.index(static_cast<size_t>(np));
      const size_t a = static_cast<size_t>(sp.members[pa]);
      size_t b = a;
      bool mated = false;
      if (np == 1 || rng.bernoulli(params.mutate_only_probability)) {
        child = s.genomes[a];
      } else {
        mated = true;
        if (species.size() > 1 && rng.bernoulli(params.interspecies_mating_probability)) {
          size_t other = rng.index(species.size() - 1);
          if (other >= si) ++other;
          b = static_cast<size_t>(species[other].members.front());
        } else if (params.independent_parents) {
          b = static_cast<size_t>(sp.members[rng.index(static_cast<size_t>(np))]);
        } else {
          size_t pb = rng.index(static_cast<size_t>(np - 1));
          if (pb >= pa) ++pb;
          b = static_cast<size_t>(sp.members[pb]);
        }
        const bool average = params.mate_average_probability > 0.0 && rng.bernoulli(params.mate_average_probability);
        child = crossover(s.genomes[a], fitness[a], s.genomes[b], fitness[b], params, average, rng);
      }
      child.id = s.next_genome_id++;
      // Stanley: a mated offspring stays unmutated with mate_only_probability, unless its parents
      // are one genome or identical in the compatibility distance's eyes.
      const bool mate_only = mated && params.mate_only_probability > 0.0 &&
                             rng.bernoulli(params.mate_only_probability) && a != b &&
                             compatibility_distance(s.genomes[a], s.genomes[b], params) != 0.0;
      if (!mate_only) mutate(child, regime, layout, params, tracker, child_gen, rng);
      next.push_back(std::move(child));
    }
  }

  /// The whole next generation: the generation champion's unchanged copy first (if kept), then
  /// each species' offspring in species order.
  void all(const std::vector<int>& counts, const std::vector<char>& from_champion, Champion champ) {
    const bool keep_champion = params.keep_generation_champion;
    if (keep_champion) copy_unchanged(champ.index);
    for (size_t si = 0; si < s.species.size(); ++si) {
      const Species& sp = s.species[si];
      int remaining = counts[si];
      const bool champion_copied = keep_champion && si == champ.species;
      if (champion_copied) --remaining;  // the generation champion is this species' unchanged copy
      if (from_champion[si]) {
        champion_copies(sp, remaining, champion_copied);
        continue;
      }
      if (!champion_copied && remaining >= params.species_elitism_min_offspring) {
        copy_unchanged(static_cast<size_t>(sp.members.front()));
        --remaining;
      }
      offspring(si, remaining);
    }
  }
};

/// Step 5: species without offspring die (unless childless species stay); the others age by one
/// and are represented by this generation's champion (or their best ever, by the parameters).
void age_species(PopulationState& s, const std::vector<int>& counts, const std::vector<char>& new_best,
                 const NeatParams& params) {
  std::vector<Species> surviving;
  for (size_t si = 0; si < s.species.size(); ++si) {
    if (counts[si] == 0 && !params.childless_species_stay) continue;
    Species sp = std::move(s.species[si]);
    if (params.representative == Representative::Champion || new_best[si])
      sp.representative = s.genomes[static_cast<size_t>(sp.members.front())];
    sp.age += 1;
    surviving.push_back(std::move(sp));
  }
  s.species = std::move(surviving);
}

}  // namespace

void Population::advance(const std::vector<double>& fitness, Rng& rng) {
  check_fitness(s_.genomes, fitness);
  const size_t n = s_.genomes.size();
  const int32_t gen = s_.generation;

  // 1. Rank each species' members; find the generation champion.
  const Champion champ = rank_species(s_, fitness);

  // 2. Improvement and stagnation; 3. sharing and allocation.
  GenerationReport rep;
  rep.generation = gen;
  rep.champion = champ.index;
  rep.champion_fitness = fitness[champ.index];
  const SpeciesJudgement judged = judge_species(s_.species, fitness, champ.species, gen, params_, rep);
  std::vector<int> counts = allocate_counts(s_, fitness, rep, judged.sizes, params_);
  const std::vector<char> from_champion = population_stagnation(s_, fitness, champ.index, gen, params_, counts, rep);
  if (params_.keep_generation_champion && counts[champ.species] == 0) {
    const size_t donor = static_cast<size_t>(std::max_element(counts.begin(), counts.end()) - counts.begin());
    --counts[donor];
    ++counts[champ.species];
  }
  rep.offspring = counts;

  // 4. Breed.
  InnovationTracker tracker(s_.next_innovation, s_.next_node_id);
  const int32_t child_gen = gen + 1;
  Breeding breeding{s_, params_, regime_, layout_, fitness, tracker, child_gen, rng, {}};
  breeding.next.reserve(n);
  breeding.all(counts, from_champion, champ);
  if (breeding.next.size() != n)
    throw std::logic_error("Population::advance: bred " + std::to_string(breeding.next.size()) +
                           " genomes for a population of " + std::to_string(n));

  // 5. Species without offspring die; the others are represented by their
  // champion of this generation. Then the new generation is speciated.
  age_species(s_, counts, judged.new_best, params_);
  s_.genomes = std::move(breeding.next);
  s_.generation = child_gen;
  s_.next_innovation = tracker.next_innovation();
  s_.next_node_id = tracker.next_node_id();
  speciate_current();
  report_ = std::move(rep);
}

}  // namespace robozoo
