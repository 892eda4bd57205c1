// tools/experiment/paper_experiment.sh --save-checkpoints at toy sizes (--bin:
// this build's programs): a trial in progress on one machine goes into the
// repository folder as a portable checkpoint, and the run on a new machine
// continues it from there instead of generation 0; its compact results, in
// every milestone (the later ones extend the continued log), are those of a
// machine that never stopped, wall time aside. A finished trial's portable
// checkpoint is removed by the next --save-checkpoints.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "evolve/run/evaluator.hpp"
#include "evolve/run/evolution.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;
namespace fs = std::filesystem;

std::string script(const std::string& paper, const std::string& dir, const std::string& extra = "") {
  return "bash '" + std::string(ROBOZOO_SOURCE_DIR) + "/tools/experiment/paper_experiment.sh' --bin '" +
         std::string(ROBOZOO_BIN_DIR) + "' --paper '" + paper + "' --dir '" + dir +
         "' --trials 1 --sensitivity-trials 1 --population 6 --steps 100 --generations 2,3,2,2,3,4,5 --workers 1 " +
         extra + " </dev/null";
}

/// The result without the run's wall time, which differs from run to run.
std::string timeless(const std::string& path) {
  nlohmann::json j = nlohmann::json::parse(read_file(path));
  j.erase("evolve_seconds");
  return j.dump();
}

TEST(PaperExperimentCheckpointsCli, ATrialInProgressContinuesOnANewMachineFromTheRepository) {
  TempDir t;
  // The first machine stopped during M1's feedforward-s1, after its generation 0.
  const std::string first = t / "first";
  fs::create_directories(first + "/runs");
  {
    RunConfig c;
    c.regime = Regime::FeedForward;
    c.seed = 1;
    c.neat.population = 6;
    c.generations = 2;
    c.eval.sim.steps = 100;
    InProcessEvaluator evaluator(c.eval);
    EvolveOptions o;
    o.log_path = first + "/runs/feedforward-s1.lcmlog";
    o.run_id = "feedforward-s1";
    Evolution evo(c, o, evaluator);
    ASSERT_TRUE(evo.step());
  }
  const std::string paper = t / "paper";
  const auto saved = run_shell(script(paper, first, "--save-checkpoints"));
  ASSERT_EQ(saved.status, 0) << saved.output;
  const std::string file = paper + "/checkpoints/feedforward-s1.portable-checkpoint";
  ASSERT_TRUE(fs::exists(file)) << saved.output;

  // A new machine with the repository folder only.
  const std::string second = t / "second";
  const auto run = run_shell(script(paper, second));
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("feedforward-s1: continues from the portable checkpoint"), std::string::npos) << run.output;
  // A machine that never stopped.
  const std::string whole = t / "whole";
  const auto reference = run_shell(script(t / "other-paper", whole));
  ASSERT_EQ(reference.status, 0) << reference.output;
  for (const char* folder : {"results", "m2/results"})
    EXPECT_EQ(timeless(second + "/" + folder + "/feedforward-s1.results.json"),
              timeless(whole + "/" + folder + "/feedforward-s1.results.json"))
        << folder;

  // Finished now: the next --save-checkpoints removes its file, though every milestone is
  // done here (none is in progress to save), and says so.
  const auto cleaned = run_shell(script(paper, second, "--save-checkpoints"));
  EXPECT_EQ(cleaned.status, 0) << cleaned.output;
  EXPECT_FALSE(fs::exists(file)) << cleaned.output;
  EXPECT_NE(cleaned.output.find("M1: feedforward-s1 finished: removed"), std::string::npos) << cleaned.output;
  EXPECT_NE(cleaned.output.find("every milestone finished on this machine"), std::string::npos) << cleaned.output;
}

}  // namespace
}  // namespace robozoo
