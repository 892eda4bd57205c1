#pragma once
// CPPN-NEAT parameters. Defaults are those of the C++ HyperNEAT package the
// paper names, as its authors' own parameter files set them (docs/method.md,
// "CPPN-NEAT"). The topology rules (which links may exist, the initial genome,
// add-link, add-node, compatibility) follow HyperNEAT's NEAT_GeneticIndividual
// by default; the classic NEAT variants stay reachable as options.
#include <cstdint>
#include <string>

namespace robozoo {

/// Control regime: forward links only. Experimental: recurrent links allowed too.
enum class Regime : int8_t { FeedForward = 0, Recurrent = 1 };

/// Which links the feed-forward regime allows.
enum class LinkRule : int8_t {
  Positions = 0,  ///< HyperNEAT: a link is forward when pos(from) < pos(to); only those
  CycleTest = 1,  ///< classic NEAT: any link that closes no directed cycle
};
/// The links of a generation-0 genome.
enum class InitialLinks : int8_t {
  AllAllowed = 0,       ///< HyperNEAT's createTopology: every node to every non-input node the regime allows
  InputsToOutputs = 1,  ///< classic NEAT: every input to every output only
  /// AllAllowed's links and draws, but every link out of an output at weight 0:
  /// the recurrent start's structure with the inputs-to-outputs start's behaviour
  AllAllowedRecurrentZero = 2,
};
/// How add-link picks its new link.
enum class AddLinkRule : int8_t {
  Uniform = 0,  ///< uniformly among all allowed, not yet linked pairs; fails only when none is left
  Tries = 1,    ///< up to add_link_tries random (from, to) pairs, the first allowed one
};
/// How add-node splits a link.
enum class AddNodeRule : int8_t {
  HyperNeat = 0,  ///< forward links only; the old link stays enabled at w/2, in-link 1, out-link w/4
  Classic = 1,    ///< any enabled link; the old link is disabled, in-link 1, out-link w
};
/// Which numbers add-node gives the node and links of a split.
enum class AddNodeInnovations : int8_t {
  /// HyperNEAT (Globals::assignNodeID, assignLinkID): every split gets a new node id, so its two
  /// links are new (from, to) pairs with new innovation numbers, even when another genome of
  /// the same generation split the same link
  Fresh = 0,
  /// NEAT's innovation list (robozoo's earlier rule): the same link split by several genomes of
  /// one generation gets the same node id, innovations and activation
  Shared = 1,
};
/// Which link weights a weight mutation changes.
enum class WeightMutationRule : int8_t {
  HyperNeat = 0,  ///< links younger than young_link_age always perturbed, older ones with old_link_perturb_probability
  Classic =
      1,  ///< the NEAT paper: every link; replaced by a new random value with weight_replace_probability, else perturbed
  /// Stanley's NEAT C++ (mutate_link_weights, rate 1): one call in two is "severe" (each link
  /// 70 % perturbed, 20 % replaced, 10 % kept); otherwise, in a genome of at least 10 link genes,
  /// the links past 80 % of the list (the newest) 50 % perturbed, 20 % replaced, 30 % kept, and
  /// every other link perturbed. Replacement values, like perturbations, are uniform in
  /// [-weight_perturbation, weight_perturbation).
  Stanley = 2,
};
/// How crossover treats the enabled flag, and which parent is the fitter on a tie.
enum class CrossoverRule : int8_t {
  /// A gene disabled in either parent, matching or not, is inherited disabled with
  /// disabled_gene_probability, else enabled; on equal fitness the first parent is the fitter.
  Robozoo = 0,
  /// Stanley's mate_multipoint / mate_multipoint_avg: only a matching gene disabled in either
  /// parent is inherited disabled with disabled_gene_probability; otherwise a copied matching
  /// gene keeps its own flag and an averaged one is enabled; disjoint and excess genes keep
  /// their flags. On equal fitness the parent with fewer link genes is the fitter (the second
  /// when both have as many).
  Stanley = 1,
};
/// When a species counts as stagnant (its shared fitness then times dropoff_factor).
enum class StagnationRule : int8_t {
  /// robozoo's own: this generation's improvement is recorded first, the generation champion's
  /// species always counts as improved, and a species is stagnant dropoff_age generations after
  /// its last improvement.
  Robozoo = 0,
  /// Stanley's Species::adjust_fitness: checked before this generation's improvement is recorded,
  /// no exemption for the champion's species, and stagnant from dropoff_age - 1 generations after
  /// the last improvement on (his age_debt of 0 is counted as 1).
  Stanley = 1,
  /// HyperNEAT's GeneticSpecies::setMultiplier: judged before this generation's improvement is
  /// recorded; an improvement (or holding the generation champion, HyperNEAT's exemption) in
  /// generation h lifts the penalty from h + 1 until generation h + dropoff_age; a species
  /// founded in generation g0 is stagnant from g0 + dropoff_age on. A species' first generation
  /// is never an improvement (HyperNEAT founds a species with its best member).
  HyperNeat = 2,
};
/// How the population's offspring are divided among species.
enum class OffspringRounding : int8_t {
  /// Proportional to the species' shares, largest remainders first (allocate_offspring).
  LargestRemainder = 0,
  /// Stanley's count_offspring: every member expects (its shared fitness) / (the population's
  /// mean shared fitness) offspring; walking species and members in order, whole parts are given
  /// at once and fractions carried over ("skim"), one more offspring whenever the carry exceeds 1;
  /// a shortfall goes to the species expecting the most (allocate_offspring_skim).
  Skim = 1,
  /// HyperNEAT's GeneticPopulation::produceNextGeneration: every species gets the whole part of
  /// its proportional share; the offspring left over go one each to the species of the
  /// population's genomes in order of raw fitness, best first, round and round
  /// (allocate_offspring_best_first).
  BestFirst = 2,
};
/// Which genes crossover passes on.
enum class CrossoverGenes : int8_t {
  /// robozoo's (classic NEAT): disjoint and excess genes from the fitter parent only, a matching
  /// gene from either parent with probability 1/2; the child has the fitter parent's structure.
  Fitter = 0,
  /// HyperNEAT's GeneticIndividual crossover (MisterTea/HyperNEAT): every gene of either parent;
  /// a matching gene from parent a with probability fitness_a / (fitness_a + fitness_b).
  Both = 1,
  /// HyperNEAT as the first author's later copy of it has it (jauerb/CPPN_Trimesh): one draw per gene of either parent, parent
  /// a with probability fitness_a / (fitness_a + fitness_b); a matching gene comes from the
  /// drawn parent, a gene only one parent has is kept when that parent is drawn.
  Drawn = 2,
};
/// Which mutations an offspring may get.
enum class MutationOrder : int8_t {
  /// robozoo's (the NEAT paper's): add-node; if none was added, add-link; if the structure did
  /// not change, the weights.
  OneStructural = 0,
  /// HyperNEAT's GeneticIndividual::testMutate: add-node, add-link and the weight mutation are
  /// three independent draws, in that order; one offspring may get all three.
  Independent = 1,
};
/// Which genome represents a species when the next generation is speciated.
enum class Representative : int8_t {
  Champion = 0,  ///< robozoo's: the species' champion of the generation just evaluated
  /// HyperNEAT's GeneticSpecies::getBestIndividual: the best genome the species ever had (its
  /// first generation's champion, replaced whenever a champion beats the species' best fitness).
  BestEver = 1,
};
/// How the compatibility threshold moves towards target_species.
enum class ThresholdRule : int8_t {
  /// robozoo's: +- compatibility_modifier, never below min_compatibility_threshold.
  Clamp = 0,
  /// HyperNEAT's GeneticPopulation::speciate: with m = -modifier (too few species), +modifier (too
  /// many) or 0: a threshold below |m| + min_compatibility_threshold is halved when m < 0 (raised
  /// to 0.001 first if below it), else a threshold below m + min_compatibility_threshold is
  /// doubled, else m is added. (HyperNEAT's constant 0.3 is min_compatibility_threshold here.)
  HyperNeat = 1,
};
/// Named sets of the mechanics above (see apply_neat_mechanics).
enum class NeatMechanics : int8_t {
  HyperNeat = 0,  ///< the paper's HyperNEAT (the default)
  Robozoo = 1,    ///< robozoo's mechanics before it followed HyperNEAT's (NEAT-paper style)
};
/// How the compatibility distance counts unmatched genes.
enum class CompatibilityRule : int8_t {
  HyperNeat = 0,  ///< excess = |#links(a) - #links(b)|; disjoint = unmatched genes up to the shorter list's end
  Classic = 1,    ///< excess = genes beyond the other genome's last innovation; disjoint = the others
};

std::string link_rule_name(LinkRule r);          ///< "positions" / "cycle_test"
std::string initial_links_name(InitialLinks r);  ///< "all_allowed" / "inputs_to_outputs" / "all_allowed_recurrent_zero"
std::string add_link_rule_name(AddLinkRule r);   ///< "uniform" / "tries"
std::string add_node_rule_name(AddNodeRule r);   ///< "hyperneat" / "classic"
std::string add_node_innovations_name(AddNodeInnovations r);  ///< "fresh" / "shared"
std::string compatibility_rule_name(CompatibilityRule r);     ///< "hyperneat" / "classic"
std::string weight_mutation_rule_name(WeightMutationRule r);  ///< "hyperneat" / "classic" / "stanley"
std::string crossover_rule_name(CrossoverRule r);             ///< "robozoo" / "stanley"
std::string stagnation_rule_name(StagnationRule r);           ///< "robozoo" / "stanley" / "hyperneat"
std::string offspring_rounding_name(OffspringRounding r);     ///< "largest_remainder" / "skim" / "best_first"
std::string crossover_genes_name(CrossoverGenes r);           ///< "fitter" / "both" / "drawn"
std::string mutation_order_name(MutationOrder r);             ///< "one_structural" / "independent"
std::string representative_name(Representative r);            ///< "champion" / "best_ever"
std::string threshold_rule_name(ThresholdRule r);             ///< "clamp" / "hyperneat"
std::string neat_mechanics_name(NeatMechanics m);             ///< "hyperneat" / "robozoo"
/// Inverses of the *_name functions; throw std::invalid_argument listing the names.
LinkRule link_rule_from_name(const std::string& s);
InitialLinks initial_links_from_name(const std::string& s);
AddLinkRule add_link_rule_from_name(const std::string& s);
AddNodeRule add_node_rule_from_name(const std::string& s);
AddNodeInnovations add_node_innovations_from_name(const std::string& s);
CompatibilityRule compatibility_rule_from_name(const std::string& s);
WeightMutationRule weight_mutation_rule_from_name(const std::string& s);
CrossoverRule crossover_rule_from_name(const std::string& s);
StagnationRule stagnation_rule_from_name(const std::string& s);
OffspringRounding offspring_rounding_from_name(const std::string& s);
CrossoverGenes crossover_genes_from_name(const std::string& s);
MutationOrder mutation_order_from_name(const std::string& s);
Representative representative_from_name(const std::string& s);
ThresholdRule threshold_rule_from_name(const std::string& s);
NeatMechanics neat_mechanics_from_name(const std::string& s);

struct NeatParams {
  int population = 150;  ///< genomes per generation (count)
  // Compatibility distance: c_d * D / N + c_e * E / N + c_w * Wbar, with N = 1.
  double disjoint_coefficient = 2.0;          ///< c_d (distance units per gene)
  double excess_coefficient = 2.0;            ///< c_e (distance units per gene)
  double weight_coefficient = 1.0;            ///< c_w (distance units per unit of weight difference)
  double compatibility_threshold = 6.0;       ///< initial threshold (distance units)
  double compatibility_modifier = 0.3;        ///< threshold step per generation (distance units)
  double min_compatibility_threshold = 0.3;   ///< the threshold never goes below this (distance units)
  int target_species = 8;                     ///< threshold moves towards this many species (count)
  double survival_threshold = 0.2;            ///< fraction of each species allowed to reproduce
  int dropoff_age = 15;                       ///< generations without improvement before penalty
  double dropoff_factor = 0.001;              ///< fitness multiplier of a stagnant species
  double add_node_probability = 0.03;         ///< per offspring
  double add_link_probability = 0.05;         ///< per offspring
  double mutate_weights_probability = 0.8;    ///< per offspring
  int young_link_age = 18;                    ///< links younger than this (generations) are always perturbed
  double old_link_perturb_probability = 0.1;  ///< per older link, when weights mutate
  double weight_perturbation = 2.5;           ///< perturbation uniform in [-x, x] (weight units)
  double weight_limit = 5.0;                  ///< weights clamped to [-x, x] (weight units)
  double initial_weight_range = 3.0;          ///< initial weights uniform in [-x, x] (weight units)
  double mutate_only_probability = 0.25;      ///< offspring made by mutation alone (no crossover)
  /// Crossover partner from another species (probability; HyperNEAT has no interspecies mating: 0;
  /// robozoo's mechanics 0.001, the NEAT paper's value).
  double interspecies_mating_probability = 0.0;
  int species_elitism_min_offspring = 5;     ///< a species with at least this many offspring keeps its champion
  int add_link_tries = 20;                   ///< attempts to find a new, legal link with add_link "tries" (count)
  LinkRule link_rule = LinkRule::Positions;  ///< which links the feed-forward regime allows
  bool self_loops = false;                   ///< recurrent regime: links from a node to itself allowed
  InitialLinks initial_links = InitialLinks::AllAllowed;  ///< generation-0 topology
  AddLinkRule add_link = AddLinkRule::Uniform;            ///< how add-link chooses
  AddNodeRule add_node = AddNodeRule::HyperNeat;          ///< how add-node splits
  /// Which numbers a split gets (HyperNEAT's fresh ones by default). Not part of neat.mechanics:
  /// a recorded configuration without this key ran with shared numbers.
  AddNodeInnovations add_node_innovations = AddNodeInnovations::Fresh;
  CompatibilityRule compatibility = CompatibilityRule::HyperNeat;      ///< how unmatched genes count
  WeightMutationRule weight_mutation = WeightMutationRule::HyperNeat;  ///< which weights a weight mutation changes
  /// Classic weight mutation: a link's weight is replaced by a new value uniform in
  /// [-initial_weight_range, initial_weight_range) with this probability, else perturbed.
  double weight_replace_probability = 0.1;
  /// Crossover: a gene disabled in either parent is inherited disabled with this
  /// probability, else enabled (classic NEAT 0.75). 0: the chosen gene is copied as it is (HyperNEAT).
  double disabled_gene_probability = 0.0;
  /// Activation functions a new hidden node may get, as a bit mask over Activation
  /// codes: default signed sigmoid, signed cosine and Gaussian (bits 0, 1, 2).
  uint32_t hidden_activations = 0b111;

  // Mechanics of Stanley's own NEAT C++ (NEAT 1.2.1: genome.cpp, species.cpp, population.cpp;
  // the code behind the NEAT paper's XOR figures, parameter file p2nv.ne). Every default below
  // leaves robozoo's NEAT exactly as it was; robozoo-xor's neat-paper preset switches them on.
  /// Crossover: probability that a mated offspring gets the mean of its parents' weights at
  /// every matching gene (Stanley's mate_multipoint_avg, mate_multipoint_avg_prob 0.4) instead of
  /// each matching gene copied from a parent drawn with probability 1/2 (mate_multipoint, 0.6).
  /// Probability; 0: never (no draw is made).
  double mate_average_probability = 0.0;
  /// Probability that a mated offspring is not mutated at all (Stanley's mate_only_prob 0.2),
  /// unless both parents are the same genome or at compatibility distance 0. Probability; 0:
  /// every offspring is mutated (no draw is made).
  double mate_only_probability = 0.0;
  /// How crossover treats enabled flags and fitness ties (see CrossoverRule).
  CrossoverRule crossover_rule = CrossoverRule::Robozoo;
  /// The second parent of a mating within the species is drawn from the parents independently
  /// of the first, so a genome may mate with itself (Stanley: mom and dad are two independent
  /// draws; such an offspring is always mutated). false: two different parents.
  bool independent_parents = false;
  /// true (HyperNEAT): the next generation starts with an unchanged copy of the generation
  /// champion, and the champion's species gets at least one offspring. false (Stanley): the
  /// champion survives only as its species' champion copy (species_elitism_min_offspring).
  bool keep_generation_champion = true;
  /// When a species is stagnant (see StagnationRule).
  StagnationRule stagnation = StagnationRule::HyperNeat;
  /// How offspring are divided among species (see OffspringRounding).
  OffspringRounding offspring_rounding = OffspringRounding::BestFirst;
  /// Population-level stagnation (Stanley's delta coding): when the population's best raw fitness
  /// has not beaten its record for this many generations (Stanley: dropoff_age + 5 = 20), only
  /// the two species with the best champions reproduce, half the population each, all from their
  /// champion: every offspring but the last a mutated copy (weights mutated with probability 0.8,
  /// else a link added), the last an unchanged copy; their last improvement is set to now and the
  /// count starts again. Generations; 0: off.
  int population_stagnation_generations = 0;
  /// false (Stanley's mutate_add_node): add-node never splits a link that leaves the bias input.
  bool split_bias_links = true;
  /// true (Stanley): once the add-node (or add-link) draw succeeds, the offspring gets that
  /// mutation only, even when it finds nothing to add; false: a failed structural mutation falls
  /// through to the next one (see mutate()).
  bool structural_draw_decides = false;
  /// true (Stanley): a species allotted no offspring stays a candidate when the new generation
  /// is speciated (represented by its champion) and lives on if another species' offspring
  /// joins it; false: it dies at once.
  bool childless_species_stay = true;

  // HyperNEAT's own mechanics (NEAT_GeneticIndividual, NEAT_GeneticSpecies, NEAT_GeneticPopulation;
  // the first author's later copy in jauerb/CPPN_Trimesh, his 2012-14 triangle-mesh code and not the paper's, where the two differ). The defaults, here and in
  // interspecies_mating_probability, stagnation, offspring_rounding and childless_species_stay
  // above, are HyperNEAT's (apply_neat_mechanics(p, NeatMechanics::HyperNeat));
  // NeatMechanics::Robozoo restores robozoo's earlier ones.
  /// Which genes crossover passes on and how a matching gene's parent is chosen.
  CrossoverGenes crossover_genes = CrossoverGenes::Drawn;
  /// Which mutations an offspring may get.
  MutationOrder mutation_order = MutationOrder::Independent;
  /// Which genome represents a species at the next speciation.
  Representative representative = Representative::BestEver;
  /// How the compatibility threshold moves.
  ThresholdRule threshold_rule = ThresholdRule::HyperNeat;
};

/// Sets the mechanics a named set decides (crossover_genes, mutation_order, representative,
/// threshold_rule, stagnation, offspring_rounding, childless_species_stay,
/// interspecies_mating_probability); leaves every other field alone.
void apply_neat_mechanics(NeatParams& p, NeatMechanics m);
/// The name of the set p's mechanics match, or "custom" when they match none.
std::string neat_mechanics_of(const NeatParams& p);

}  // namespace robozoo
