#include "study/experiment/trial_plan.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

namespace robozoo {
namespace {

ExperimentParams small() {
  ExperimentParams p;
  p.trials = 2;
  p.generations = 3;
  p.population = 12;
  p.steps = 200;
  p.workers = 2;
  p.out_dir = "/tmp/x";
  return p;
}

bool has(const std::vector<std::string>& v, const std::vector<std::string>& seq) {
  return std::search(v.begin(), v.end(), seq.begin(), seq.end()) != v.end();
}

TEST(TrialPlan, TrialByTrialBothRegimesNeverSharingASeed) {
  // Trial k of arm a uses seed 4 (k - 1) + a + 1: feedforward 1, 5; recurrent 2, 6.
  const auto t = plan_trials(small());
  ASSERT_EQ(t.size(), 4u);
  EXPECT_EQ(t[0].name(), "feedforward-s1");
  EXPECT_EQ(t[1].name(), "recurrent-s2");
  EXPECT_EQ(t[2].name(), "feedforward-s5");
  EXPECT_EQ(t[3].name(), "recurrent-s6");
  EXPECT_EQ(t[3].number, 2);
  EXPECT_EQ(t[3].regime, Regime::Recurrent);
  EXPECT_EQ(t[3].log_path, "/tmp/x/recurrent-s6.lcmlog");
  EXPECT_EQ(t[3].output_path, "/tmp/x/recurrent-s6.out");
}

TEST(TrialPlan, FourArmsRunTrialByTrialWithSeedsFixedPerArm) {
  ExperimentParams p = small();
  p.trials = 30;
  p.arms = {Arm::FeedForward, Arm::Recurrent, Arm::RecurrentSparse, Arm::RecurrentZero};
  const auto t = plan_trials(p);
  ASSERT_EQ(t.size(), 120u);
  std::set<int64_t> seeds;
  for (size_t i = 0; i < t.size(); ++i) {
    // Trial 1 of every arm, then trial 2, ...
    EXPECT_EQ(t[i].number, static_cast<int>(i / 4) + 1);
    EXPECT_EQ(t[i].arm, p.arms[i % 4]);
    EXPECT_EQ(t[i].seed, 4 * (t[i].number - 1) + static_cast<int>(i % 4) + 1);
    EXPECT_TRUE(seeds.insert(t[i].seed).second) << "seed " << t[i].seed << " used twice";
  }
  // Seeds 1..120, each once.
  EXPECT_EQ(*seeds.begin(), 1);
  EXPECT_EQ(*seeds.rbegin(), 120);
  EXPECT_EQ(t[3].name(), "recurrent-zero-s4");
  EXPECT_EQ(t[7].name(), "recurrent-zero-s8");
  EXPECT_EQ(t[3].regime, Regime::Recurrent);
  const auto a = evolve_arguments(t[3], p, false);
  EXPECT_TRUE(has(a, {"--set", "neat.initial_links=all_allowed_recurrent_zero"}));
  EXPECT_TRUE(has(a, {"--regime", "recurrent"}));
  EXPECT_TRUE(has(a, {"--seed", "4"}));
  // Any subset, in any order: each trial keeps its seed.
  ExperimentParams some = p;
  some.arms = {Arm::RecurrentZero, Arm::FeedForward};
  const auto u = plan_trials(some);
  ASSERT_EQ(u.size(), 60u);
  EXPECT_EQ(u[0].name(), "recurrent-zero-s4");
  EXPECT_EQ(u[1].name(), "feedforward-s1");
  EXPECT_EQ(u[2].name(), "recurrent-zero-s8");
  for (const auto& x : u) EXPECT_EQ(x.seed, trial_seed(x.arm, x.number));
}

TEST(TrialPlan, ThirdArmHasItsOwnSeedsAndTheControlsStart) {
  ExperimentParams p = small();
  p.trials = 30;
  p.arms = {Arm::FeedForward, Arm::Recurrent, Arm::RecurrentSparse};
  const auto t = plan_trials(p);
  ASSERT_EQ(t.size(), 90u);
  std::set<int64_t> seeds;
  for (const auto& x : t) {
    EXPECT_TRUE(seeds.insert(x.seed).second) << "seed " << x.seed << " used twice";
    EXPECT_EQ(x.seed, trial_seed(x.arm, x.number));
  }
  EXPECT_EQ(*seeds.begin(), 1);
  EXPECT_EQ(*seeds.rbegin(), 4 * 29 + 3);
  EXPECT_EQ(t[2].name(), "recurrent-sparse-s3");
  EXPECT_EQ(t[5].name(), "recurrent-sparse-s7");
  EXPECT_EQ(t[2].regime, Regime::Recurrent);
  const auto a = evolve_arguments(t[2], p, false);
  EXPECT_TRUE(has(a, {"--set", "neat.initial_links=inputs_to_outputs"}));
  EXPECT_TRUE(has(a, {"--run-id", "recurrent-sparse-s3"}));
  EXPECT_FALSE(has(evolve_arguments(t[1], p, false), {"--set", "neat.initial_links=inputs_to_outputs"}));
  EXPECT_FALSE(has(evolve_arguments(t[1], p, false), {"--set"}));
  // The seeds of the first two arms do not depend on whether the third runs.
  ExperimentParams two = small();
  two.trials = 30;
  const auto u = plan_trials(two);
  for (size_t i = 0; i < u.size(); ++i) EXPECT_EQ(u[i].seed, t[i / 2 * 3 + i % 2].seed);
  p.arms = {Arm::Recurrent, Arm::Recurrent};
  EXPECT_THROW(plan_trials(p), std::invalid_argument);
}

TEST(TrialPlan, EvolveArgumentsCarryTheSizesAlsoOnResume) {
  const ExperimentParams p = small();
  const Trial t = plan_trials(p)[1];
  for (bool resume : {false, true}) {
    const auto a = evolve_arguments(t, p, resume);
    EXPECT_TRUE(has(a, {"--log", "/tmp/x/recurrent-s2.lcmlog"}));
    EXPECT_TRUE(has(a, {"--regime", "recurrent"}));
    EXPECT_TRUE(has(a, {"--seed", "2"}));
    EXPECT_TRUE(has(a, {"--population", "12"}));
    EXPECT_TRUE(has(a, {"--generations", "3"}));
    EXPECT_TRUE(has(a, {"--steps", "200"}));
    EXPECT_TRUE(has(a, {"--workers", "2"}));
    EXPECT_EQ(std::count(a.begin(), a.end(), "--resume"), resume ? 1 : 0);
  }
  ExperimentParams defaults = p;
  defaults.steps = 0;
  defaults.workers = 0;
  const auto a = evolve_arguments(t, defaults, false);
  EXPECT_EQ(std::count(a.begin(), a.end(), "--steps"), 0);
  EXPECT_EQ(std::count(a.begin(), a.end(), "--workers"), 0);
}

TEST(TrialPlan, BadSizesAreRefused) {
  ExperimentParams p = small();
  p.trials = 0;
  EXPECT_THROW(plan_trials(p), std::invalid_argument);
  p = small();
  p.population = 1;
  EXPECT_THROW(validate_experiment(p), std::invalid_argument);
  p = small();
  p.out_dir.clear();
  EXPECT_THROW(validate_experiment(p), std::invalid_argument);
}

TEST(TrialPlan, SetsGoToEveryTrialAlsoOnResume) {
  ExperimentParams p = small();
  p.sets = {"growth.bias_input=1.0", "sim.rolling_contact_rule=false"};
  for (const Trial& t : plan_trials(p))
    for (bool resume : {false, true}) {
      const auto a = evolve_arguments(t, p, resume);
      EXPECT_TRUE(has(a, {"--set", "growth.bias_input=1.0"}));
      EXPECT_TRUE(has(a, {"--set", "sim.rolling_contact_rule=false"}));
    }
}

TEST(TrialPlan, BadOrOwnSetsAreRefusedNamingThem) {
  auto error_of = [](const std::string& kv) {
    ExperimentParams p = small();
    p.sets = {kv};
    try {
      validate_experiment(p);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error_of("growth.bias_input").find("--set growth.bias_input"), std::string::npos);
  EXPECT_NE(error_of("growth.no_such_key=1").find("no_such_key"), std::string::npos);
  EXPECT_NE(error_of("growth.max_spheres=0").find("growth.max_spheres"), std::string::npos);
  EXPECT_NE(error_of("neat.population=20").find("the experiment's own"), std::string::npos);
  EXPECT_NE(error_of("neat.initial_links=inputs_to_outputs").find("the experiment's own"), std::string::npos);
  EXPECT_NE(error_of("sim.steps=20").find("the experiment's own"), std::string::npos);
  EXPECT_NE(error_of("seed=3").find("the experiment's own"), std::string::npos);
  EXPECT_EQ(error_of("growth.max_spheres=100"), "");
  EXPECT_EQ(error_of("neat.add_node_innovations=shared"), "");
}

TEST(TrialPlan, LocalTrialCommandIsTheProgramAndItsArguments) {
  const ExperimentParams p = small();
  const Trial t = plan_trials(p)[0];
  const auto cmd = trial_command(t, p, "/bin/robozoo-evolve", true);
  auto expected = evolve_arguments(t, p, true);
  expected.insert(expected.begin(), "/bin/robozoo-evolve");
  EXPECT_EQ(cmd, expected);
  EXPECT_EQ(std::count(cmd.begin(), cmd.end(), "--mpi"), 0);
}

TEST(TrialPlan, MpiTrialCommandWrapsRobozooEvolveInTheLauncher) {
  ExperimentParams p = small();
  p.workers = 0;
  p.mpi_ranks = 4;
  p.mpirun = {"/usr/bin/mpirun", "--oversubscribe"};
  const Trial t = plan_trials(p)[1];
  for (bool resume : {false, true}) {
    const auto cmd = trial_command(t, p, "/bin/robozoo-evolve", resume);
    ASSERT_GE(cmd.size(), 5u);
    EXPECT_EQ(std::vector<std::string>(cmd.begin(), cmd.begin() + 5),
              (std::vector<std::string>{"/usr/bin/mpirun", "--oversubscribe", "-np", "4", "/bin/robozoo-evolve"}));
    EXPECT_EQ(cmd.back(), "--mpi");
    EXPECT_TRUE(has(cmd, {"--log", "/tmp/x/recurrent-s2.lcmlog"}));
    EXPECT_TRUE(has(cmd, {"--steps", "200"}));
    EXPECT_EQ(std::count(cmd.begin(), cmd.end(), "--workers"), 0);
    EXPECT_EQ(std::count(cmd.begin(), cmd.end(), "--resume"), resume ? 1 : 0);
  }
}

TEST(TrialPlan, BadMpiSettingsAreRefused) {
  ExperimentParams p = small();
  p.workers = 0;
  p.mpi_ranks = 1;  // rank 0 alone would have nobody to evaluate
  EXPECT_THROW(validate_experiment(p), std::invalid_argument);
  p.mpi_ranks = 2;
  EXPECT_NO_THROW(validate_experiment(p));
  p.workers = 2;  // the ranks are the workers
  EXPECT_THROW(validate_experiment(p), std::invalid_argument);
  p.workers = 0;
  p.mpirun.clear();
  EXPECT_THROW(validate_experiment(p), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
