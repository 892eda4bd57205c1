#include "evolve/analysis/experiment_tables.hpp"

namespace robozoo {

namespace {

std::string regime_label(int8_t r) { return r == 0 ? "feedforward" : "recurrent"; }

}  // namespace

CsvWriter fitness_curve_table(const ExperimentAnalysis& a) {
  CsvWriter t({"generation", "feedforward_n", "feedforward_mean", "feedforward_se", "recurrent_n", "recurrent_mean",
               "recurrent_se"});
  for (const auto& p : a.fitness_curve)
    t.add_row({std::to_string(p.generation), std::to_string(p.control.n), csv_number(p.control.mean),
               csv_number(p.control.se), std::to_string(p.experimental.n), csv_number(p.experimental.mean),
               csv_number(p.experimental.se)});
  return t;
}

CsvWriter comparison_table(const std::vector<Comparison>& list) {
  CsvWriter t({"statistic", "label", "unit", "feedforward_n", "feedforward_mean", "feedforward_sd", "feedforward_se",
               "recurrent_n", "recurrent_mean", "recurrent_sd", "recurrent_se", "t", "df", "p", "stars"});
  for (const auto& c : list)
    t.add_row({c.key, c.label, c.unit, std::to_string(c.control.n), csv_number(c.control.mean),
               csv_number(c.control.sd), csv_number(c.control.se), std::to_string(c.experimental.n),
               csv_number(c.experimental.mean), csv_number(c.experimental.sd), csv_number(c.experimental.se),
               csv_number(c.test.t), csv_number(c.test.df), csv_number(c.test.p), c.stars});
  return t;
}

CsvWriter runs_table(const ExperimentAnalysis& a) {
  CsvWriter t({"log", "run_id", "regime", "seed", "population", "generations_requested", "generations_logged",
               "steps", "complete", "final_best_so_far", "has_best", "best_generation", "best_genome_id",
               "best_fitness", "best_outcome", "spheres", "leaves", "joints", "distance_sensors", "touch_sensors",
               "proprio_sensors", "time_sensors", "mean_radius", "radius_variance", "max_depth", "ground_known",
               "ground_spheres", "ground_fraction", "nodes", "hidden", "hidden_sigmoid", "hidden_cosine",
               "hidden_gaussian", "hidden_other", "link_genes", "links", "forward_links", "recurrent_links",
               "new_champions", "new_champions_topology_changed", "gains_not_simulated", "gains_unknown",
               "undecodable_messages"});
  for (const auto* side : {&a.control, &a.experimental})
    for (const auto& r : *side) {
      const auto& m = r.morphology;
      const auto& g = r.genotype;
      int changed = 0;
      for (const auto& c : r.changes.changes) changed += c.topology_changed;
      t.add_row({r.path, r.run_id, regime_label(r.regime), std::to_string(r.seed), std::to_string(r.population),
                 std::to_string(r.generations_requested), std::to_string(r.best_so_far.size()),
                 std::to_string(r.steps), r.complete ? "1" : "0",
                 r.best_so_far.empty() ? "nan" : csv_number(r.best_so_far.back()), r.has_best ? "1" : "0",
                 std::to_string(r.best_generation), std::to_string(r.best_genome_id), csv_number(r.best_fitness),
                 std::to_string(r.best_outcome), csv_number(m.spheres), csv_number(m.leaves), csv_number(m.joints),
                 csv_number(m.distance_sensors), csv_number(m.touch_sensors), csv_number(m.proprio_sensors),
                 csv_number(m.time_sensors), csv_number(m.mean_radius), csv_number(m.radius_variance),
                 csv_number(m.max_depth), m.ground_known ? "1" : "0", csv_number(m.ground_spheres),
                 csv_number(m.ground_fraction), csv_number(g.nodes), csv_number(g.hidden),
                 csv_number(g.hidden_sigmoid), csv_number(g.hidden_cosine), csv_number(g.hidden_gaussian),
                 csv_number(g.hidden_other), csv_number(g.link_genes), csv_number(g.links),
                 csv_number(g.forward_links), csv_number(g.recurrent_links),
                 std::to_string(r.changes.changes.size()), std::to_string(changed),
                 std::to_string(r.changes.not_simulated), std::to_string(r.changes.unknown),
                 std::to_string(r.undecodable)});
    }
  return t;
}

CsvWriter champion_change_table(const ExperimentAnalysis& a) {
  CsvWriter t({"run_id", "regime", "seed", "generation", "previous_genome_id", "genome_id", "previous_fitness",
               "fitness", "improvement", "topology_changed"});
  for (const auto* side : {&a.control, &a.experimental})
    for (const auto& r : *side)
      for (const auto& c : r.changes.changes)
        t.add_row({r.run_id, regime_label(r.regime), std::to_string(r.seed), std::to_string(c.generation),
                   std::to_string(c.previous_id), std::to_string(c.genome_id), csv_number(c.previous_fitness),
                   csv_number(c.fitness), csv_number(c.improvement), c.topology_changed ? "1" : "0"});
  return t;
}

}  // namespace robozoo
