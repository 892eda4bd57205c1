#include "study/analysis/figures/experiment_tables.hpp"

namespace robozoo {

namespace {

std::string regime_label(const RunAnalysis& r) { return r.arm; }

}  // namespace

CsvWriter fitness_curve_table(const ExperimentAnalysis& a) {
  const std::string c = arm_column(a.control_arm), e = arm_column(a.experimental_arm);
  CsvWriter t({"generation", c + "_n", c + "_mean", c + "_se", e + "_n", e + "_mean", e + "_se", "student_t",
               "student_df", "student_p"});
  for (const auto& p : a.fitness_curve)
    t.add_row({std::to_string(p.generation), std::to_string(p.control.n), csv_number(p.control.mean),
               csv_number(p.control.se), std::to_string(p.experimental.n), csv_number(p.experimental.mean),
               csv_number(p.experimental.se), csv_number(p.student.t), csv_number(p.student.df),
               csv_number(p.student.p)});
  return t;
}

CsvWriter comparison_table(const std::vector<Comparison>& list, const std::string& control,
                           const std::string& experimental) {
  const std::string c = arm_column(control), e = arm_column(experimental);
  CsvWriter t({"statistic",
               "label",
               "unit",
               "samples",
               c + "_n",
               c + "_mean",
               c + "_sd",
               c + "_se",
               e + "_n",
               e + "_mean",
               e + "_sd",
               e + "_se",
               "student_t",
               "student_df",
               "student_p",
               "welch_t",
               "welch_df",
               "welch_p",
               "cohens_d",
               "hedges_g",
               "d_ci95_low",
               "d_ci95_high",
               "stars",
               c + "_at_max_spheres",
               e + "_at_max_spheres"});
  for (const auto& c : list)
    t.add_row({c.key,
               c.label,
               c.unit,
               c.samples == Samples::Runs ? "runs" : "pooled_events",
               std::to_string(c.control.n),
               csv_number(c.control.mean),
               csv_number(c.control.sd),
               csv_number(c.control.se),
               std::to_string(c.experimental.n),
               csv_number(c.experimental.mean),
               csv_number(c.experimental.sd),
               csv_number(c.experimental.se),
               csv_number(c.student.t),
               csv_number(c.student.df),
               csv_number(c.student.p),
               csv_number(c.welch.t),
               csv_number(c.welch.df),
               csv_number(c.welch.p),
               csv_number(c.effect.d),
               csv_number(c.effect.g),
               csv_number(c.effect.d_low),
               csv_number(c.effect.d_high),
               c.stars,
               c.control_at_cap < 0 ? "" : std::to_string(c.control_at_cap),
               c.experimental_at_cap < 0 ? "" : std::to_string(c.experimental_at_cap)});
  return t;
}

CsvWriter claims_table(const ClaimsAssessment& claims) {
  CsvWriter t({"statistic", "section", "role", "paper", "paper_direction", "student_p", "holm_p", "paper_effect",
               "power_at_paper_effect", "direction", "verdict"});
  for (const auto& r : claims.rows) {
    const char* role = r.role == ClaimRole::Primary          ? "primary"
                       : r.role == ClaimRole::Secondary      ? "secondary"
                       : r.role == ClaimRole::ByConstruction ? "by_construction"
                                                             : "descriptive";
    t.add_row({r.comparison.key, r.section, role, r.paper,
               r.paper_direction == 2 ? "" : std::to_string(r.paper_direction), csv_number(r.comparison.student.p),
               csv_number(r.holm_p), csv_number(r.paper_effect), csv_number(r.power), r.direction, r.verdict});
  }
  return t;
}

std::vector<std::array<double, 6>> mean_outcome_shares(const std::vector<RunAnalysis>& runs) {
  std::vector<std::array<double, 6>> sum;
  std::vector<int> n;
  for (const auto& r : runs)
    for (size_t g = 0; g < r.outcome_shares.size(); ++g) {
      if (g >= sum.size()) {
        sum.resize(g + 1, std::array<double, 6>{});
        n.resize(g + 1, 0);
      }
      for (size_t k = 0; k < 6; ++k) sum[g][k] += r.outcome_shares[g][k];
      ++n[g];
    }
  for (size_t g = 0; g < sum.size(); ++g)
    for (auto& x : sum[g]) x /= n[g];
  return sum;
}

CsvWriter outcome_shares_table(const ExperimentAnalysis& a) {
  CsvWriter t({"arm", "generation", "runs", "not_simulated", "completed", "stopped_early", "accel_fault",
               "rolling_contact", "rolling_spin"});
  for (const auto* side : {&a.control, &a.experimental}) {
    if (side->empty()) continue;
    const std::string arm = side == &a.control ? a.control_arm : a.experimental_arm;
    const auto shares = mean_outcome_shares(*side);
    for (size_t g = 0; g < shares.size(); ++g) {
      int runs = 0;
      for (const auto& r : *side) runs += g < r.outcome_shares.size();
      std::vector<std::string> row = {arm, std::to_string(g), std::to_string(runs)};
      for (double x : shares[g]) row.push_back(csv_number(x));
      t.add_row(row);
    }
  }
  return t;
}

CsvWriter runs_table(const ExperimentAnalysis& a) {
  CsvWriter t({"log",
               "run_id",
               "regime",
               "seed",
               "population",
               "generations_requested",
               "generations_logged",
               "steps",
               "complete",
               "final_best_so_far",
               "has_best",
               "best_generation",
               "best_genome_id",
               "best_fitness",
               "best_outcome",
               "spheres",
               "leaves",
               "joints",
               "distance_sensors",
               "touch_sensors",
               "proprio_sensors",
               "time_sensors",
               "mean_radius",
               "radius_variance",
               "max_depth",
               "ground_known",
               "ground_spheres",
               "ground_fraction",
               "nodes",
               "hidden",
               "hidden_sigmoid",
               "hidden_cosine",
               "hidden_gaussian",
               "hidden_other",
               "link_genes",
               "links",
               "forward_links",
               "recurrent_links",
               "new_champions",
               "new_champions_topology_changed",
               "gains_not_simulated",
               "gains_unknown",
               "undecodable_messages",
               "max_spheres",
               "max_d"});
  for (const auto* side : {&a.control, &a.experimental})
    for (const auto& r : *side) {
      const auto& m = r.morphology;
      const auto& g = r.genotype;
      int changed = 0;
      for (const auto& c : r.changes.changes) changed += c.topology_changed;
      t.add_row({r.path,
                 r.run_id,
                 regime_label(r),
                 std::to_string(r.seed),
                 std::to_string(r.population),
                 std::to_string(r.generations_requested),
                 std::to_string(r.best_so_far.size()),
                 std::to_string(r.steps),
                 r.complete ? "1" : "0",
                 r.best_so_far.empty() ? "nan" : csv_number(r.best_so_far.back()),
                 r.has_best ? "1" : "0",
                 std::to_string(r.best_generation),
                 std::to_string(r.best_genome_id),
                 csv_number(r.best_fitness),
                 std::to_string(r.best_outcome),
                 csv_number(m.spheres),
                 csv_number(m.leaves),
                 csv_number(m.joints),
                 csv_number(m.distance_sensors),
                 csv_number(m.touch_sensors),
                 csv_number(m.proprio_sensors),
                 csv_number(m.time_sensors),
                 csv_number(m.mean_radius),
                 csv_number(m.radius_variance),
                 csv_number(m.max_depth),
                 m.ground_known ? "1" : "0",
                 csv_number(m.ground_spheres),
                 csv_number(m.ground_fraction),
                 csv_number(g.nodes),
                 csv_number(g.hidden),
                 csv_number(g.hidden_sigmoid),
                 csv_number(g.hidden_cosine),
                 csv_number(g.hidden_gaussian),
                 csv_number(g.hidden_other),
                 csv_number(g.link_genes),
                 csv_number(g.links),
                 csv_number(g.forward_links),
                 csv_number(g.recurrent_links),
                 std::to_string(r.changes.changes.size()),
                 std::to_string(changed),
                 std::to_string(r.changes.not_simulated),
                 std::to_string(r.changes.unknown),
                 std::to_string(r.undecodable),
                 std::to_string(r.max_spheres),
                 csv_number(r.max_d)});
    }
  return t;
}

CsvWriter champion_change_table(const ExperimentAnalysis& a) {
  CsvWriter t({"run_id", "regime", "seed", "generation", "previous_genome_id", "genome_id", "previous_fitness",
               "fitness", "improvement", "topology_changed"});
  for (const auto* side : {&a.control, &a.experimental})
    for (const auto& r : *side)
      for (const auto& c : r.changes.changes)
        t.add_row({r.run_id, regime_label(r), std::to_string(r.seed), std::to_string(c.generation),
                   std::to_string(c.previous_id), std::to_string(c.genome_id), csv_number(c.previous_fitness),
                   csv_number(c.fitness), csv_number(c.improvement), c.topology_changed ? "1" : "0"});
  return t;
}

}  // namespace robozoo
