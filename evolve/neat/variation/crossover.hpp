#pragma once
// NEAT crossover, genes aligned by innovation.
#include "evolve/core/rng.hpp"
#include "evolve/cppn/genome.hpp"
#include "evolve/neat/params.hpp"

namespace robozoo {

/// With p.crossover_genes == CrossoverGenes::Fitter (robozoo's): matching genes (same innovation) are copied whole (weight, enabled flag,
/// birth generation) from either parent with probability 1/2 each; disjoint and
/// excess genes come from the fitter parent (`a` when fitness_a >= fitness_b)
/// only, so the child has exactly the fitter parent's structure: its node genes
/// and the set of its link innovations. The child's id is -1 (the caller
/// assigns one). With p.disabled_gene_probability > 0 (classic NEAT), a gene
/// disabled in either parent is then inherited disabled with that probability
/// and enabled otherwise (one draw per such gene, in innovation order); with 0
/// no draw is made and the chosen gene is copied as it is (HyperNEAT).
/// With CrossoverGenes::Both (MisterTea's HyperNEAT) every gene of either parent is inherited and a
/// matching gene comes from `a` with probability fa / (fa + fb) (one draw per matching gene); with
/// CrossoverGenes::Drawn (HyperNEAT as jauerb/CPPN_Trimesh has it) one such draw is made for every gene of either
/// parent, in innovation order: a matching gene comes from the drawn parent, a gene only one parent
/// has is kept when that parent is drawn. There a fitness of 0 counts as 0.0001, and the child's
/// nodes are the inputs and outputs and every hidden node its links touch (a's copy first).
Genome crossover(const Genome& a, double fitness_a, const Genome& b, double fitness_b, const NeatParams& p, Rng& rng);
/// The same, and with `average_weights` (Stanley's mate_multipoint_avg) every matching gene is
/// the fitter parent's gene with the mean of both parents' weights, enabled (no parent draw).
/// With p.crossover_rule == CrossoverRule::Stanley: on equal fitness the parent with fewer link
/// genes is the fitter (b when both have as many); disjoint and excess genes keep their enabled
/// flags; a matching gene disabled in either parent is inherited disabled with
/// p.disabled_gene_probability (one draw per such gene), else it keeps the chosen gene's flag
/// (copied) or is enabled (averaged).
Genome crossover(const Genome& a, double fitness_a, const Genome& b, double fitness_b, const NeatParams& p,
                 bool average_weights, Rng& rng);
/// The same with disabled_gene_probability 0 and CrossoverGenes::Fitter.
Genome crossover(const Genome& a, double fitness_a, const Genome& b, double fitness_b, Rng& rng);

}  // namespace robozoo
