#include "study/analysis/compare/experiment_analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "study/analysis/read/log_results.hpp"
#include "tests/study/analysis/hand_made_experiment.hpp"
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
  // Recurrent {18, 16.5} against feed-forward {16, 17}: ss 1.125 and 0.5,
  // s_p^2 = 1.625 / 2, se = sqrt(0.8125), t = 0.75 / se, df 2.
  EXPECT_NEAR(best.student.t, 0.75 / std::sqrt(0.8125), 1e-12);
  EXPECT_EQ(best.student.df, 2.0);
  // Welch: v = 1.125 / 2 + 0.5 / 2 = 0.8125 (equal n: the same t); df = 0.8125^2 /
  // (0.5625^2 + 0.25^2) = 0.66015625 / 0.37890625 = 1.7422680412371134.
  EXPECT_NEAR(best.welch.t, best.student.t, 1e-12);
  EXPECT_NEAR(best.welch.df, 0.66015625 / 0.37890625, 1e-12);
  // Cohen's d = 0.75 / sqrt(0.8125) (s_p, not the standard error).
  EXPECT_NEAR(best.effect.d, 0.75 / std::sqrt(0.8125), 1e-12);
  EXPECT_EQ(best.samples, Samples::Runs);
  // The last generation is 2; at generation 0 feed-forward {4, 15} against recurrent {15, 15}.
  EXPECT_EQ(e.last_generation, 2);
  EXPECT_NEAR(e.fitness_curve[0].student.t, ttest_ind({15, 15}, {4, 15}).t, 1e-15);
  EXPECT_GT(e.fitness_curve[0].student.t, 0);
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
  // Feed-forward new champions: s1 C (same, +0.5), s2 E (changed, +2.0); B's gain
  // over the unsimulated A is left out. Recurrent: s1 G (changed, +1.0), H
  // (changed, +2.0); s2 J (changed, +0.5), K (same, +1.0).
  EXPECT_EQ(e.control[0].changes.not_simulated, 1);
  // Pooled events: described, never tested.
  const Comparison& share = get(e.champion, "topology_changed");
  EXPECT_EQ(share.samples, Samples::PooledEvents);
  EXPECT_EQ(share.control.n, 2u);
  EXPECT_EQ(share.experimental.n, 4u);
  EXPECT_DOUBLE_EQ(share.control.mean, 0.5);
  EXPECT_DOUBLE_EQ(share.experimental.mean, 0.75);
  EXPECT_TRUE(std::isnan(share.student.p));
  EXPECT_TRUE(std::isnan(share.welch.p));
  EXPECT_TRUE(std::isnan(share.effect.d));
  EXPECT_EQ(share.stars, "");
  EXPECT_NEAR(get(e.champion, "improvement_changed").experimental.mean, 3.5 / 3.0, 1e-15);
  // Per run, the tested samples: shares ff {0/1, 1/1}, recurrent {2/2, 1/2}.
  const Comparison& per_run = get(e.champion, "topology_changed_per_run");
  EXPECT_EQ(per_run.samples, Samples::Runs);
  EXPECT_EQ(per_run.control.n, 2u);
  EXPECT_DOUBLE_EQ(per_run.control.mean, 0.5);
  EXPECT_DOUBLE_EQ(per_run.experimental.mean, 0.75);
  // {1, 0.5} against {0, 1}: ss 0.125 and 0.5, s_p^2 = 0.3125, t = 0.25 / sqrt(0.3125).
  EXPECT_NEAR(per_run.student.t, 0.25 / std::sqrt(0.3125), 1e-12);
  EXPECT_EQ(per_run.student.df, 2.0);
  // Mean gain of topology-changing new champions per run: ff s2 2.0 (s1 has none);
  // recurrent s1 (1 + 2) / 2 = 1.5, s2 0.5.
  const Comparison& changed = get(e.champion, "improvement_changed_per_run");
  EXPECT_EQ(changed.control.n, 1u);
  EXPECT_DOUBLE_EQ(changed.control.mean, 2.0);
  EXPECT_EQ(changed.experimental.n, 2u);
  EXPECT_DOUBLE_EQ(changed.experimental.mean, 1.0);
  // Student's test has df = 1: s_p^2 = (0 + 0.5) / 1, t = (1 - 2) / sqrt(0.5 (1 + 1/2)).
  EXPECT_EQ(changed.student.df, 1.0);
  EXPECT_NEAR(changed.student.t, -1.0 / std::sqrt(0.75), 1e-12);
  // Welch's test and d need two runs on each side.
  EXPECT_TRUE(std::isnan(changed.welch.p));
  EXPECT_TRUE(std::isnan(changed.effect.d));
  // Same topology: ff s1 0.5; recurrent s2 1.0: one run each, no test.
  const Comparison& same = get(e.champion, "improvement_same_per_run");
  EXPECT_DOUBLE_EQ(same.control.mean, 0.5);
  EXPECT_DOUBLE_EQ(same.experimental.mean, 1.0);
  EXPECT_TRUE(std::isnan(same.student.p));
  EXPECT_DOUBLE_EQ(get(e.champion, "new_champions_per_run").experimental.mean, 2.0);
}

TEST(ExperimentAnalysis, CountsRobotsAtTheSphereCapBesideTheCountsItCensors) {
  ExperimentAnalysis in;
  std::vector<RunAnalysis> runs;
  for (int i = 0; i < 5; ++i) {
    RunAnalysis r;
    r.arm = i < 2 ? "feedforward" : "recurrent-zero";
    r.seed = i + 1;
    r.has_best = true;
    r.max_spheres = 50;
    r.morphology.spheres = i == 0 || i == 2 || i == 3 ? 50 : 20;  // ff: 1 of 2 at the cap; zero: 2 of 3
    r.best_so_far = {15.0 + i};
    runs.push_back(r);
  }
  const ExperimentAnalysis e = analyze_experiment(runs, "feedforward", "recurrent-zero");
  EXPECT_EQ(e.control_at_cap, 1);
  EXPECT_EQ(e.experimental_at_cap, 2);
  for (const char* key : {"spheres", "leaves", "joints", "ground_spheres", "max_depth"}) {
    EXPECT_EQ(get(e.morphology, key).control_at_cap, 1) << key;
    EXPECT_EQ(get(e.morphology, key).experimental_at_cap, 2) << key;
  }
  // Shares and radii are not bounded by the count: not flagged.
  EXPECT_EQ(get(e.morphology, "ground_fraction").control_at_cap, -1);
  EXPECT_EQ(get(e.morphology, "mean_radius").control_at_cap, -1);
  EXPECT_EQ(arm_title("recurrent-zero"), "recurrent (zero-weight start)");
}

TEST(ExperimentAnalysis, OtherArmsFitnessAgainstTheControl) {
  std::vector<RunAnalysis> runs;
  auto add = [&runs](const std::string& arm, int64_t seed, double best) {
    RunAnalysis r;
    r.arm = arm;
    r.seed = seed;
    r.best_so_far = {10.0, best};
    runs.push_back(r);
  };
  add("feedforward", 1, 20);
  add("feedforward", 4, 22);
  add("recurrent", 2, 30);
  add("recurrent", 5, 31);
  add("recurrent-zero", 7, 25);
  add("recurrent-sparse", 3, 23);
  add("recurrent-zero", 4, 27);
  const ExperimentAnalysis e = analyze_experiment(runs, "feedforward", "recurrent");
  ASSERT_EQ(e.other_arms.size(), 2u);  // by arm name
  EXPECT_EQ(e.other_arms[0].arm, "recurrent-sparse");
  EXPECT_EQ(e.other_arms[0].fitness.experimental.n, 1u);
  EXPECT_EQ(e.other_arms[1].arm, "recurrent-zero");
  const Comparison& z = e.other_arms[1].fitness;
  EXPECT_DOUBLE_EQ(z.control.mean, 21.0);
  EXPECT_DOUBLE_EQ(z.experimental.mean, 26.0);
  // {25, 27} against {20, 22}: s_p^2 = 2, t = 5 / sqrt(2 (1/2 + 1/2)) = 5 / sqrt(2).
  EXPECT_NEAR(z.student.t, 5.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(z.effect.d, 5.0 / std::sqrt(2.0), 1e-12);
}

}  // namespace
}  // namespace robozoo
