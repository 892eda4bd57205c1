#include "evolve/analysis/experiment_analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/evolve/analysis/hand_made_experiment.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

ExperimentAnalysis analyse_hand_made() {
  TempDir dir;
  write_hand_made_experiment(dir.path);
  std::vector<RunAnalysis> runs;
  // Read in an order other than the regimes': the analysis sorts them.
  for (const char* name : {"recurrent-s2", "feedforward-s1", "recurrent-s1", "feedforward-s2"})
    runs.push_back(analyze_run(summarize_run_file(dir / (std::string(name) + ".lcmlog"))));
  return analyze_experiment(runs);
}

const Comparison& get(const std::vector<Comparison>& list, const std::string& key) {
  const Comparison* c = find_comparison(list, key);
  if (!c) throw std::logic_error("no comparison " + key);
  return *c;
}

TEST(ExperimentAnalysis, FitnessCurveByHand) {
  const ExperimentAnalysis e = analyse_hand_made();
  ASSERT_EQ(e.control.size(), 2u);
  ASSERT_EQ(e.experimental.size(), 2u);
  EXPECT_EQ(e.control[0].seed, 1);
  ASSERT_EQ(e.fitness_curve.size(), 3u);
  // Best so far, feed-forward: {4, 15}, {15.5, 15}, {16, 17}; recurrent: {15, 15}, {16, 15.5}, {18, 16.5}.
  EXPECT_DOUBLE_EQ(e.fitness_curve[0].control.mean, 9.5);
  EXPECT_NEAR(e.fitness_curve[0].control.se, 5.5, 1e-12);  // sd sqrt(60.5) / sqrt(2)
  EXPECT_DOUBLE_EQ(e.fitness_curve[1].control.mean, 15.25);
  EXPECT_DOUBLE_EQ(e.fitness_curve[2].control.mean, 16.5);
  EXPECT_DOUBLE_EQ(e.fitness_curve[0].experimental.mean, 15.0);
  EXPECT_DOUBLE_EQ(e.fitness_curve[0].experimental.se, 0.0);
  EXPECT_DOUBLE_EQ(e.fitness_curve[1].experimental.mean, 15.75);
  EXPECT_DOUBLE_EQ(e.fitness_curve[2].experimental.mean, 17.25);
  const Comparison& best = get(e.fitness, "best_fitness");
  EXPECT_DOUBLE_EQ(best.control.mean, 16.5);
  EXPECT_DOUBLE_EQ(best.experimental.mean, 17.25);
  // {16, 17} vs {18, 16.5}: ss 0.5 and 1.125, s_p^2 = 1.625 / 2, se = sqrt(0.8125), t = -0.75 / se.
  EXPECT_NEAR(best.test.t, -0.75 / std::sqrt(0.8125), 1e-12);
}

TEST(ExperimentAnalysis, BestOfRunBodyPlansByHand) {
  const ExperimentAnalysis e = analyse_hand_made();
  EXPECT_EQ(e.control[0].best_genome_id, 12);
  EXPECT_EQ(e.control[1].best_genome_id, 22);
  EXPECT_EQ(e.experimental[0].best_genome_id, 32);
  EXPECT_EQ(e.experimental[1].best_genome_id, 42);
  EXPECT_DOUBLE_EQ(get(e.morphology, "spheres").control.mean, 3.0);
  EXPECT_DOUBLE_EQ(get(e.morphology, "spheres").experimental.mean, 3.5);
  EXPECT_DOUBLE_EQ(get(e.morphology, "leaves").control.mean, 1.5);
  EXPECT_DOUBLE_EQ(get(e.morphology, "leaves").experimental.mean, 2.0);
  EXPECT_DOUBLE_EQ(get(e.morphology, "max_depth").control.mean, 1.5);
  EXPECT_DOUBLE_EQ(get(e.morphology, "max_depth").experimental.mean, 1.5);
  // Ground: C 3 of 3, E unknown (0 of 3); H 1 of 4, K 3 of 3.
  EXPECT_DOUBLE_EQ(get(e.morphology, "ground_spheres").control.mean, 1.5);
  EXPECT_DOUBLE_EQ(get(e.morphology, "ground_spheres").experimental.mean, 2.0);
  EXPECT_DOUBLE_EQ(get(e.morphology, "ground_fraction").control.mean, 0.5);
  EXPECT_DOUBLE_EQ(get(e.morphology, "ground_fraction").experimental.mean, 0.625);
  EXPECT_EQ(e.control_without_poses, 1);
  EXPECT_EQ(e.experimental_without_poses, 0);
  // Mean radius: C (0.1 + 0.3 + 0.2) / 3 = 0.2, E 0.1; H 0.1, K 0.2.
  EXPECT_NEAR(get(e.morphology, "mean_radius").control.mean, 0.15, 1e-15);
  EXPECT_NEAR(get(e.morphology, "mean_radius").experimental.mean, 0.15, 1e-15);
}

TEST(ExperimentAnalysis, BestOfRunCppnsByHand) {
  const ExperimentAnalysis e = analyse_hand_made();
  EXPECT_DOUBLE_EQ(get(e.genotype, "nodes").control.mean, 2.5);
  EXPECT_DOUBLE_EQ(get(e.genotype, "nodes").experimental.mean, 2.5);
  EXPECT_DOUBLE_EQ(get(e.genotype, "hidden_sigmoid").control.mean, 0.5);
  EXPECT_DOUBLE_EQ(get(e.genotype, "hidden_cosine").experimental.mean, 0.5);
  EXPECT_DOUBLE_EQ(get(e.genotype, "links").control.mean, 1.5);
  EXPECT_DOUBLE_EQ(get(e.genotype, "links").experimental.mean, 2.5);
  EXPECT_DOUBLE_EQ(get(e.genotype, "forward_links").control.mean, 1.5);
  // Forward by drawing position: 0 -> 20 and 20 -> 9 (0 -> 0.5 -> 1) but not 9 -> 20; 9 -> 9 is recurrent.
  EXPECT_DOUBLE_EQ(get(e.genotype, "forward_links").experimental.mean, 1.5);
  EXPECT_DOUBLE_EQ(get(e.genotype, "recurrent_links").experimental.mean, 1.0);
  EXPECT_DOUBLE_EQ(get(e.genotype, "cycle_links").experimental.mean, 1.5);
}

TEST(ExperimentAnalysis, ChampionChangesByHand) {
  const ExperimentAnalysis e = analyse_hand_made();
  // Feed-forward new champions: C (same, +0.5), E (changed, +2.0); B's gain
  // over the unsimulated A is left out. Recurrent: G (changed, +1.0), H
  // (changed, +2.0), J (changed, +0.5), K (same, +1.0).
  EXPECT_EQ(e.control[0].changes.not_simulated, 1);
  const Comparison& share = get(e.champion, "topology_changed");
  EXPECT_EQ(share.control.n, 2u);
  EXPECT_EQ(share.experimental.n, 4u);
  EXPECT_DOUBLE_EQ(share.control.mean, 0.5);
  EXPECT_DOUBLE_EQ(share.experimental.mean, 0.75);
  // {0, 1} vs {1, 1, 1, 0}: ss 0.5 and 0.75, df 4, s_p^2 = 0.3125,
  // se = sqrt(0.3125 * (1/2 + 1/4)), t = -0.25 / se = -0.5163977794943222.
  EXPECT_NEAR(share.test.t, -0.25 / std::sqrt(0.3125 * 0.75), 1e-12);
  EXPECT_EQ(share.test.df, 4.0);
  const Comparison& changed = get(e.champion, "improvement_changed");
  EXPECT_DOUBLE_EQ(changed.control.mean, 2.0);
  EXPECT_NEAR(changed.experimental.mean, 3.5 / 3.0, 1e-15);
  const Comparison& same = get(e.champion, "improvement_same");
  EXPECT_DOUBLE_EQ(same.control.mean, 0.5);
  EXPECT_DOUBLE_EQ(same.experimental.mean, 1.0);
  EXPECT_TRUE(std::isnan(same.test.p));  // one observation each: no test
  const Comparison& per_run = get(e.champion, "topology_changed_per_run");
  EXPECT_DOUBLE_EQ(per_run.control.mean, 0.5);          // runs: 0 of 1, 1 of 1
  EXPECT_DOUBLE_EQ(per_run.experimental.mean, 0.75);    // runs: 2 of 2, 1 of 2
  EXPECT_DOUBLE_EQ(get(e.champion, "new_champions_per_run").experimental.mean, 2.0);
}

}  // namespace
}  // namespace robozoo
