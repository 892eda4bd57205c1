// robozoo-evolve eval: look at one robot.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

nlohmann::json eval_json(const std::string& args) {
  const auto o = run_shell(bin("robozoo-evolve") + " eval --json " + args + " 2>/dev/null");
  EXPECT_EQ(o.status, 0) << o.output;
  return nlohmann::json::parse(o.output);
}

TEST(EvalCli, RandomGenomeReportsMorphologyOutcomeAndFitness) {
  // Seeds until one robot is simulated: its report carries the simulation's figures.
  bool simulated = false;
  for (int seed = 1; seed <= 60 && !simulated; ++seed) {
    const auto j = eval_json("--random " + std::to_string(seed) + " --mutations 30 --steps 300");
    ASSERT_TRUE(j.contains("morphology"));
    EXPECT_GE(j["morphology"]["spheres"].get<int>(), 1);
    EXPECT_GE(j["r"].get<double>(), 1.0);
    EXPECT_DOUBLE_EQ(j["fitness"].get<double>(), std::max(0.0, j["r"].get<double>() + j["d"].get<double>()));
    if (j["simulated"].get<bool>()) {
      simulated = true;
      EXPECT_GE(j["r"].get<double>(), 15.0);
      EXPECT_GE(j["morphology"]["sensors"]["distance"].get<int>(), 1);
      EXPECT_GT(j["simulation"]["steps_run"].get<int>(), 0);
      EXPECT_NE(j["outcome"], "not_simulated");
    } else {
      EXPECT_LT(j["r"].get<double>(), 15.0);
      EXPECT_EQ(j["outcome"], "not_simulated");
    }
  }
  EXPECT_TRUE(simulated);
}

TEST(EvalCli, SavedGenomeEvaluatesIdentically) {
  TempDir dir;
  const auto a =
      eval_json("--random 5 --mutations 25 --regime recurrent --steps 200 --save-genome " + (dir / "g.json"));
  const auto b = eval_json("--genome " + (dir / "g.json") + " --steps 200");
  EXPECT_EQ(a, b);
  // Text output names the outcome and the fitness.
  const auto t = run_shell(bin("robozoo-evolve") + " eval --genome " + (dir / "g.json") + " --steps 200");
  EXPECT_EQ(t.status, 0);
  EXPECT_NE(t.output.find("fitness"), std::string::npos);
  EXPECT_NE(t.output.find("outcome"), std::string::npos);
}

TEST(EvalCli, BadGenomeFilesExitTwo) {
  TempDir dir;
  std::ofstream(dir / "bad.json") << "{ nope";
  std::ofstream(dir / "dangling.json") << R"({"id": 1, "nodes": [], "links": []})";
  for (const std::string& f : {dir / "missing.json", dir / "bad.json", dir / "dangling.json"}) {
    const auto o = run_shell(bin("robozoo-evolve") + " eval --genome " + f);
    EXPECT_EQ(o.status, 2) << f << ": " << o.output;
    EXPECT_NE(o.output.find("robozoo-evolve eval:"), std::string::npos) << o.output;
  }
}

}  // namespace
}  // namespace robozoo
