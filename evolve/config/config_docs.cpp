#include "evolve/config/config_docs.hpp"

#include <sstream>

#include "evolve/config/run_config.hpp"

namespace robozoo {

// The meanings are those of the parameter structs' comments (evolve/neat/params.hpp,
// evolve/growth/params.hpp, evolve/sim/params.hpp, evolve/config/run_config.hpp); a test
// checks that every key has one and that no entry names a key that does not exist.
const std::map<std::string, std::string>& config_docs() {
  static const std::map<std::string, std::string> docs = {
      {"cppn_updates", "synchronous CPPN updates per query (count)"},
      {"generations", "generations to run (count)"},
      {"growth.bias_input",
       "value of the CPPN's constant bias input (dimensionless); 0.3 as HyperNEAT's experiments and the first author's "
       "CPPN growth code feed it"},
      {"growth.bias_max", "motor neuron bias at omega = 1 (dimensionless)"},
      {"growth.bound", "sphere centres must have |x|, |y| <= bound (m)"},
      {"growth.cloud_points", "points per cloud (count), at angles k * cloud_step"},
      {"growth.cloud_step", "angle between cloud points (rad)"},
      {"growth.max_joint_range", "half range of motion at j = 1 (rad)"},
      {"growth.max_spheres",
       "Growth stops at this many spheres (count). The paper sets no cap; it binds for about half the robots that grow "
       "at all, at 50, 100 or 200 alike, so the counts of a robot at the cap are censored (docs/method.md section 2.3 "
       "step 4, docs/performance.md)."},
      {"growth.r_init", "root radius (m)"},
      {"growth.r_max", "largest sphere radius (m)"},
      {"growth.r_min", "smallest sphere radius (m)"},
      {"growth.rho_max", "density at m = 1 (mass per m^3)"},
      {"growth.rho_min", "density at m = t_matter (mass per m^3)"},
      {"growth.t_joint", "joint threshold on output j"},
      {"growth.t_matter", "matter threshold on output m"},
      {"growth.t_sensor", "sensor-present threshold on the four sensor outputs"},
      {"growth.tau_max", "motor neuron time constant at tau = +1 (s)"},
      {"growth.tau_min", "motor neuron time constant at tau = -1 (s)"},
      {"growth.touch_tolerance",
       "Relative tolerance of placement rules (b), (c), (d) (dimensionless): a distance within touch_tolerance * limit "
       "of its limit counts as exactly at the limit, so spheres that touch in exact geometry touch whatever the last "
       "bit of rounding says (docs/method.md section 2.3)."},
      {"growth.weight_mapping",
       "how a CPPN weight output w with |w| > weight_threshold T becomes a CTRNN weight: rescaled (HyperNEAT: sign(w) "
       "(|w| - T) / (1 - T) * weight_max, 0 at the threshold) or proportional (robozoo until M2: w * weight_max)"},
      {"growth.weight_max", "CTRNN weight at w = 1 (dimensionless)"},
      {"growth.weight_threshold", "|w| at or below this expresses no CTRNN link"},
      {"neat.add_link", "how add-link chooses"},
      {"neat.add_link_probability", "per offspring"},
      {"neat.add_link_tries", "attempts to find a new, legal link with add_link \"tries\" (count)"},
      {"neat.add_node", "how add-node splits"},
      {"neat.add_node_innovations",
       "numbers of an add-node split: fresh (HyperNEAT: a new node id and new link innovations for every split) or "
       "shared (NEAT's innovation list: one node id and pair of innovations per split link and generation)"},
      {"neat.add_node_probability", "per offspring"},
      {"neat.childless_species_stay",
       "true (Stanley): a species allotted no offspring stays a candidate when the new generation is speciated "
       "(represented by its champion) and lives on if another species' offspring joins it; false: it dies at once."},
      {"neat.compatibility", "how unmatched genes count"},
      {"neat.compatibility_modifier", "threshold step per generation (distance units)"},
      {"neat.compatibility_threshold", "initial threshold (distance units)"},
      {"neat.crossover_genes", "Which genes crossover passes on and how a matching gene's parent is chosen."},
      {"neat.crossover_rule", "How crossover treats enabled flags and fitness ties (see CrossoverRule)."},
      {"neat.disabled_gene_probability",
       "Crossover: a gene disabled in either parent is inherited disabled with this probability, else enabled (classic "
       "NEAT 0.75). 0: the chosen gene is copied as it is (HyperNEAT)."},
      {"neat.disjoint_coefficient", "c_d (distance units per gene)"},
      {"neat.dropoff_age", "generations without improvement before penalty"},
      {"neat.dropoff_factor", "fitness multiplier of a stagnant species"},
      {"neat.excess_coefficient", "c_e (distance units per gene)"},
      {"neat.hidden_activations",
       "Activation functions a new hidden node may get, as a bit mask over Activation codes: default signed sigmoid, "
       "signed cosine and Gaussian (bits 0, 1, 2)."},
      {"neat.independent_parents",
       "The second parent of a mating within the species is drawn from the parents independently of the first, so a "
       "genome may mate with itself (Stanley: mom and dad are two independent draws; such an offspring is always "
       "mutated). false: two different parents."},
      {"neat.initial_links", "generation-0 topology"},
      {"neat.initial_weight_range", "initial weights uniform in [-x, x] (weight units)"},
      {"neat.interspecies_mating_probability",
       "Crossover partner from another species (probability; HyperNEAT has no interspecies mating: 0; robozoo's "
       "mechanics 0.001, the NEAT paper's value)."},
      {"neat.keep_generation_champion",
       "true (HyperNEAT): the next generation starts with an unchanged copy of the generation champion, and the "
       "champion's species gets at least one offspring. false (Stanley): the champion survives only as its species' "
       "champion copy (species_elitism_min_offspring)."},
      {"neat.link_rule", "which links the feed-forward regime allows"},
      {"neat.mate_average_probability",
       "Crossover: probability that a mated offspring gets the mean of its parents' weights at every matching gene "
       "(Stanley's mate_multipoint_avg, mate_multipoint_avg_prob 0.4) instead of each matching gene copied from a "
       "parent drawn with probability 1/2 (mate_multipoint, 0.6). Probability; 0: never (no draw is made)."},
      {"neat.mate_only_probability",
       "Probability that a mated offspring is not mutated at all (Stanley's mate_only_prob 0.2), unless both parents "
       "are the same genome or at compatibility distance 0. Probability; 0: every offspring is mutated (no draw is "
       "made)."},
      {"neat.mechanics",
       "the named set of NEAT mechanics the other keys match (hyperneat, robozoo), or custom; read first, so that keys "
       "given beside it override it"},
      {"neat.min_compatibility_threshold", "the threshold never goes below this (distance units)"},
      {"neat.mutate_only_probability", "offspring made by mutation alone (no crossover)"},
      {"neat.mutate_weights_probability", "per offspring"},
      {"neat.mutation_order", "Which mutations an offspring may get."},
      {"neat.offspring_rounding", "How offspring are divided among species (see OffspringRounding)."},
      {"neat.old_link_perturb_probability", "per older link, when weights mutate"},
      {"neat.population", "genomes per generation (count)"},
      {"neat.population_stagnation_generations",
       "Population-level stagnation (Stanley's delta coding): when the population's best raw fitness has not beaten "
       "its record for this many generations (Stanley: dropoff_age + 5 = 20), only the two species with the best "
       "champions reproduce, half the population each, all from their champion: every offspring but the last a mutated "
       "copy (weights mutated with probability 0.8, else a link added), the last an unchanged copy; their last "
       "improvement is set to now and the count starts again. Generations; 0: off."},
      {"neat.representative", "Which genome represents a species at the next speciation."},
      {"neat.self_loops", "recurrent regime: links from a node to itself allowed"},
      {"neat.species_elitism_min_offspring", "a species with at least this many offspring keeps its champion"},
      {"neat.split_bias_links",
       "false (Stanley's mutate_add_node): add-node never splits a link that leaves the bias input."},
      {"neat.stagnation", "When a species is stagnant (see StagnationRule)."},
      {"neat.structural_draw_decides",
       "true (Stanley): once the add-node (or add-link) draw succeeds, the offspring gets that mutation only, even "
       "when it finds nothing to add; false: a failed structural mutation falls through to the next one (see "
       "mutate())."},
      {"neat.survival_threshold", "fraction of each species allowed to reproduce"},
      {"neat.target_species", "threshold moves towards this many species (count)"},
      {"neat.threshold_rule", "How the compatibility threshold moves."},
      {"neat.weight_coefficient", "c_w (distance units per unit of weight difference)"},
      {"neat.weight_limit", "weights clamped to [-x, x] (weight units)"},
      {"neat.weight_mutation", "which weights a weight mutation changes"},
      {"neat.weight_perturbation", "perturbation uniform in [-x, x] (weight units)"},
      {"neat.weight_replace_probability",
       "Classic weight mutation: a link's weight is replaced by a new value uniform in [-initial_weight_range, "
       "initial_weight_range) with this probability, else perturbed."},
      {"neat.young_link_age", "links younger than this (generations) are always perturbed"},
      {"pose_every", "publish every k-th step of a champion's trajectory (count)"},
      {"publish_all", "publish every genome, not only champions"},
      {"regime", "feedforward (control: forward links only) or recurrent (experimental: recurrent links too)"},
      {"seed", "seed of the run's single generator"},
      {"sim.cfm", "world constraint force mixing (joints and stops)"},
      {"sim.contact_cfm", "contact CFM (soft contacts)"},
      {"sim.contact_erp", "contact ERP (soft contacts)"},
      {"sim.distance_sensor_range", "distance at which the sensor reads 0 (m)"},
      {"sim.dt", "physics step (s)"},
      {"sim.erp", "world error reduction parameter (joints and stops)"},
      {"sim.friction", "Coulomb friction coefficient mu (dContactApprox1:"},
      {"sim.gravity", "(m/s^2), along -z"},
      {"sim.max_angular_acceleration", "fault above this (rad/s^2)"},
      {"sim.max_contacts", "contact points per geom pair (count)"},
      {"sim.max_correcting_velocity", "dWorldSetContactMaxCorrectingVel: cap on the speed at"},
      {"sim.max_linear_acceleration", "fault above this (m/s^2)"},
      {"sim.motor_strength", "hinge torque limit in units of the largest gravity torque"},
      {"sim.ode_seed", "dRandSetSeed value before the first step"},
      {"sim.quickstep_iterations", "dWorldSetQuickStepNumIterations (count)"},
      {"sim.rest_angular_speed", "... and below this angular speed (rad/s)"},
      {"sim.rest_linear_speed", "a body is at rest below this speed (m/s)"},
      {"sim.rest_output_rate", "... and the controller below this |d output/dt| (1/s)"},
      {"sim.rest_steps", "consecutive steps at rest that end the run (count)"},
      {"sim.rolling_contact_fraction", "rule (i)'s fraction of the steps run (dimensionless)"},
      {"sim.rolling_contact_rule", "rule (i): some sphere in ground contact > fraction of steps"},
      {"sim.rolling_spin_rule", "rule (ii): |time-averaged angular velocity| of a body > threshold"},
      {"sim.rolling_spin_threshold",
       "Rule (ii)'s threshold (rad/s), from the worst body's time-averaged angular speed of robots that moved without "
       "a fault: random robots (661 movers of 1,000): median 0.07, 95th percentile 0.40, 99th 0.71 rad/s; robots grown "
       "from random CPPNs (308 movers): median 0.08, 95th 0.94, 99th 1.32. 1.0 passes 99.8 % and 95.5 % of them; a "
       "body that fails it turned more than 25 rad (4 turns) one way in the 25 s episode: it rolled."},
      {"sim.servo_gain", "target joint speed per rad of angle error (1/s)"},
      {"sim.servo_max_speed", "cap on the commanded joint speed (rad/s)"},
      {"sim.steps", "physics steps per evaluation (count)"},
      {"sim.target_x", "x of the target the robots walk towards (m): far enough that no robot reaches it in 25 s"},
      {"sim.target_y", "y of the target (m)"},
      {"sim.target_z", "z of the target (m)"},
      {"sim.time_sensor_frequency", "f of sin(2 pi f t) (Hz)"},
  };
  return docs;
}

namespace {

void explain(std::ostringstream& out, const nlohmann::json& j, const std::string& prefix) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string key = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (it->is_object()) {
      explain(out, *it, key);
      continue;
    }
    const auto doc = config_docs().find(key);
    out << key << " = " << it->dump();
    if (doc != config_docs().end()) out << "  # " << doc->second;
    out << "\n";
  }
}

}  // namespace

std::string explain_config(const RunConfig& c) {
  std::ostringstream out;
  explain(out, config_to_json(c), "");
  return out.str();
}

}  // namespace robozoo
