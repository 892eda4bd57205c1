#include "evolve/neat/crossover.hpp"

#include <stdexcept>
#include <string>

namespace robozoo {

Genome crossover(const Genome& a, double fitness_a, const Genome& b, double fitness_b, Rng& rng) {
  return crossover(a, fitness_a, b, fitness_b, NeatParams{}, rng);
}

Genome crossover(const Genome& a, double fitness_a, const Genome& b, double fitness_b,
                 const NeatParams& p, Rng& rng) {
  const double q = p.disabled_gene_probability;
  auto inherit = [&](LinkGene gene, bool disabled_in_either) {
    if (q > 0.0 && disabled_in_either) gene.enabled = !rng.bernoulli(q);
    return gene;
  };
  const bool a_fitter = fitness_a >= fitness_b;
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
      child.links.push_back(inherit(l, !l.enabled));
      continue;
    }
    const LinkGene& g = other.links[j];
    // Invariant: an innovation number names one from -> to pair in every genome.
    if (g.from != l.from || g.to != l.to)
      throw std::logic_error("crossover: innovation " + std::to_string(l.innovation) +
                             " joins different nodes in genomes " + std::to_string(a.id) +
                             " and " + std::to_string(b.id));
    // One draw per matching gene, in innovation order.
    child.links.push_back(inherit(rng.bernoulli(0.5) ? g : l, !g.enabled || !l.enabled));
  }
  return child;
}

}  // namespace robozoo
