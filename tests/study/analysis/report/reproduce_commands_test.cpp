// The reproduce commands come from the runs found: trials per arm, sizes, seeds.
#include "study/analysis/report/reproduce_commands.hpp"

#include <gtest/gtest.h>

#include "study/experiment/trial_plan.hpp"

namespace robozoo {
namespace {

RunAnalysis run(const std::string& arm, int64_t seed, int32_t population = 100, int32_t generations = 30,
                int32_t steps = 2500) {
  RunAnalysis r;
  r.arm = arm;
  r.seed = seed;
  r.population = population;
  r.generations_requested = generations;
  r.steps = steps;
  return r;
}

ExperimentAnalysis arms(const std::string& c, int nc, const std::string& x, int nx) {
  ExperimentAnalysis a;
  a.control_arm = c;
  a.experimental_arm = x;
  for (int k = 1; k <= nc; ++k) a.control.push_back(run(c, trial_seed(arm_from_name(c), k)));
  for (int k = 1; k <= nx; ++k) a.experimental.push_back(run(x, trial_seed(arm_from_name(x), k)));
  return a;
}

TEST(ReproduceCommands, OneExperimentLineWhenBothArmsAgree) {
  const auto lines = reproduce_commands(arms("feedforward", 10, "recurrent", 10), "runs/reduced",
                                        "build/bin/robozoo-stats runs/reduced --compare feedforward,recurrent");
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lines[1],
            "build/bin/robozoo-experiment --trials 10 --arms feedforward,recurrent --generations 30 "
            "--population 100 --out runs/reduced");
  EXPECT_EQ(lines[2], "build/bin/robozoo-stats runs/reduced --compare feedforward,recurrent");
  EXPECT_EQ(lines[3].rfind("# not run", 0), 0u);
}

TEST(ReproduceCommands, OneLinePerArmWithItsOwnTrials) {
  // 10 feed-forward trials against 5 of the sparse start: not "--trials 10" for both.
  const auto lines = reproduce_commands(arms("feedforward", 10, "recurrent-sparse", 5), "runs/reduced", "stats");
  EXPECT_EQ(lines[1],
            "build/bin/robozoo-experiment --trials 10 --arms feedforward --generations 30 --population 100 "
            "--out runs/reduced");
  EXPECT_EQ(lines[2],
            "build/bin/robozoo-experiment --trials 5 --arms recurrent-sparse --generations 30 "
            "--population 100 --out runs/reduced");
  EXPECT_EQ(lines[3], "stats");
}

TEST(ReproduceCommands, OtherSeedsOrSizesGetOneEvolveLinePerRun) {
  ExperimentAnalysis a = arms("feedforward", 2, "recurrent-sparse", 0);
  a.experimental = {run("recurrent-sparse", 40, 50, 7, 1000), run("recurrent-sparse", 3, 50, 7, 1000)};
  const auto lines = reproduce_commands(a, "d", "stats");
  EXPECT_EQ(lines[1],
            "build/bin/robozoo-experiment --trials 2 --arms feedforward --generations 30 --population 100 "
            "--out d");
  EXPECT_EQ(lines[2].rfind("# recurrent-sparse: seeds other than", 0), 0u) << lines[2];
  // By seed, each with its own seed, sizes and the sparse start.
  EXPECT_EQ(lines[3],
            "build/bin/robozoo-evolve --log d/recurrent-sparse-s3.lcmlog --quiet --regime recurrent --seed 3 "
            "--population 50 --generations 7 --run-id recurrent-sparse-s3 --set "
            "neat.initial_links=inputs_to_outputs --steps 1000");
  EXPECT_NE(lines[4].find("--seed 40 "), std::string::npos);
  EXPECT_EQ(lines[5], "stats");
  // Runs of one arm with different sizes are not one experiment either.
  ExperimentAnalysis b = arms("feedforward", 2, "recurrent", 2);
  b.control[1].population = 90;
  const auto mixed = reproduce_commands(b, "d", "stats");
  EXPECT_EQ(mixed[1].rfind("# feedforward:", 0), 0u) << mixed[1];
  EXPECT_NE(mixed[3].find("--population 90"), std::string::npos) << mixed[3];
  EXPECT_EQ(mixed[4],
            "build/bin/robozoo-experiment --trials 2 --arms recurrent --generations 30 --population 100 --out d");
}

}  // namespace
}  // namespace robozoo
