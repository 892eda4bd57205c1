#include "evolve/neat/variation/crossover.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace robozoo {
namespace {

// HyperNEAT's parents need a positive fitness: a parent of fitness 0 counts as 0.0001.
constexpr double kZeroFitness = 0.0001;

// CrossoverGenes::Both and ::Drawn: genes from both parents, parent a drawn with probability
// fitness_a / (fitness_a + fitness_b); the child's nodes are the inputs and outputs and every
// hidden node one of its links touches (a's copy where both parents have it).
Genome crossover_both_parents(const Genome& a, double fitness_a, const Genome& b, double fitness_b, const NeatParams& p,
                              bool average_weights, Rng& rng) {
  const double fa = fitness_a == 0.0 ? kZeroFitness : fitness_a;
  const double fb = fitness_b == 0.0 ? kZeroFitness : fitness_b;
  const double share_a = fa / (fa + fb);
  const bool drawn = p.crossover_genes == CrossoverGenes::Drawn;
  const double q = p.disabled_gene_probability;
  Genome child;
  child.id = -1;
  auto keep = [&](LinkGene gene, bool disabled_in_either) {
    if (q > 0.0 && disabled_in_either) gene.enabled = !rng.bernoulli(q);
    child.links.push_back(gene);
  };
  size_t i = 0, j = 0;
  while (i < a.links.size() || j < b.links.size()) {
    // Drawn (the first author's copy of HyperNEAT in jauerb/CPPN_Trimesh): one draw per gene position, matching or not.
    const bool choose_a_now = drawn ? rng.bernoulli(share_a) : false;
    const LinkGene* la = i < a.links.size() ? &a.links[i] : nullptr;
    const LinkGene* lb = j < b.links.size() ? &b.links[j] : nullptr;
    if (la && (!lb || la->innovation < lb->innovation)) {
      if (!drawn || choose_a_now) keep(*la, !la->enabled);
      ++i;
      continue;
    }
    if (lb && (!la || lb->innovation < la->innovation)) {
      if (!drawn || !choose_a_now) keep(*lb, !lb->enabled);
      ++j;
      continue;
    }
    if (la->from != lb->from || la->to != lb->to)
      throw std::logic_error("crossover: innovation " + std::to_string(la->innovation) +
                             " joins different nodes in genomes " + std::to_string(a.id) + " and " +
                             std::to_string(b.id));
    LinkGene gene;
    if (average_weights) {
      gene = *la;
      gene.weight = (la->weight + lb->weight) / 2.0;
      gene.enabled = true;
    } else {
      // Both (MisterTea's HyperNEAT): the draw is made for matching genes only.
      const bool choose_a = drawn ? choose_a_now : rng.bernoulli(share_a);
      gene = choose_a ? *la : *lb;
    }
    keep(gene, !la->enabled || !lb->enabled);
    ++i;
    ++j;
  }
  // Nodes: inputs and outputs (the same in every genome), then the hidden nodes the links need.
  std::vector<int32_t> needed;
  for (const LinkGene& l : child.links) {
    needed.push_back(l.from);
    needed.push_back(l.to);
  }
  std::sort(needed.begin(), needed.end());
  auto is_needed = [&](int32_t id) { return std::binary_search(needed.begin(), needed.end(), id); };
  for (const NodeGene& n : a.nodes)
    if (n.kind != NodeKind::Hidden || is_needed(n.id)) child.nodes.push_back(n);
  for (const NodeGene& n : b.nodes) {
    if (n.kind != NodeKind::Hidden || !is_needed(n.id)) continue;
    const auto at = std::lower_bound(child.nodes.begin(), child.nodes.end(), n.id,
                                     [](const NodeGene& x, int32_t id) { return x.id < id; });
    if (at == child.nodes.end() || at->id != n.id) child.nodes.insert(at, n);
  }
  return child;
}

}  // namespace

Genome crossover(const Genome& a, double fitness_a, const Genome& b, double fitness_b, Rng& rng) {
  NeatParams p;
  p.crossover_genes = CrossoverGenes::Fitter;
  return crossover(a, fitness_a, b, fitness_b, p, rng);
}

Genome crossover(const Genome& a, double fitness_a, const Genome& b, double fitness_b, const NeatParams& p, Rng& rng) {
  return crossover(a, fitness_a, b, fitness_b, p, false, rng);
}

Genome crossover(const Genome& a, double fitness_a, const Genome& b, double fitness_b, const NeatParams& p,
                 bool average_weights, Rng& rng) {
  if (p.crossover_genes != CrossoverGenes::Fitter)
    return crossover_both_parents(a, fitness_a, b, fitness_b, p, average_weights, rng);
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
                             " joins different nodes in genomes " + std::to_string(a.id) + " and " +
                             std::to_string(b.id));
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
