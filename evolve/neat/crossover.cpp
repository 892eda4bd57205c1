#include "evolve/neat/crossover.hpp"

#include <stdexcept>
#include <string>

namespace robozoo {

Genome crossover(const Genome& a, double fitness_a, const Genome& b, double fitness_b, Rng& rng) {
  return crossover(a, fitness_a, b, fitness_b, NeatParams{}, rng);
}

Genome crossover(const Genome& a, double fitness_a, const Genome& b, double fitness_b,
                 const NeatParams& p, Rng& rng) {
  return crossover(a, fitness_a, b, fitness_b, p, false, rng);
}

Genome crossover(const Genome& a, double fitness_a, const Genome& b, double fitness_b,
                 const NeatParams& p, bool average_weights, Rng& rng) {
  const double q = p.disabled_gene_probability;
  const bool stanley = p.crossover_rule == CrossoverRule::Stanley;
  // Robozoo: the rule applies to every inherited gene disabled in either parent.
  auto inherit = [&](LinkGene gene, bool disabled_in_either) {
    if (q > 0.0 && disabled_in_either) gene.enabled = !rng.bernoulli(q);
    return gene;
  };
  bool a_fitter = fitness_a >= fitness_b;
  if (stanley && fitness_a == fitness_b) a_fitter = a.links.size() < b.links.size();
  const Genome& fit = a_fitter ? a : b;
  const Genome& other = a_fitter ? b : a;
  Genome child;
  child.id = -1;
  child.nodes = fit.nodes;
  child.links.reserve(fit.links.size());
  size_t j = 0;
  for (const LinkGene& l : fit.links) {
    while (j < other.links.size() && other.links[j].innovation < l.innovation) ++j;
    const bool matching = j < other.links.size() && other.links[j].innovation == l.innovation;
    if (!matching) {
      // Stanley: disjoint and excess genes of the fitter parent keep their flags.
      child.links.push_back(stanley ? l : inherit(l, !l.enabled));
      continue;
    }
    const LinkGene& g = other.links[j];
    // Invariant: an innovation number names one from -> to pair in every genome.
    if (g.from != l.from || g.to != l.to)
      throw std::logic_error("crossover: innovation " + std::to_string(l.innovation) +
                             " joins different nodes in genomes " + std::to_string(a.id) +
                             " and " + std::to_string(b.id));
    const bool disabled_in_either = !g.enabled || !l.enabled;
    LinkGene gene;
    if (average_weights) {
      // Stanley's mate_multipoint_avg: the fitter parent's gene with the mean weight; enabled
      // unless the disabled-gene rule disables it.
      gene = l;
      gene.weight = (l.weight + g.weight) / 2.0;
      gene.enabled = true;
    } else {
      // One draw per matching gene, in innovation order.
      gene = rng.bernoulli(0.5) ? g : l;
    }
    if (!stanley) {
      child.links.push_back(inherit(gene, disabled_in_either));
      continue;
    }
    if (q > 0.0 && disabled_in_either && rng.bernoulli(q)) gene.enabled = false;
    child.links.push_back(gene);
  }
  return child;
}

}  // namespace robozoo
