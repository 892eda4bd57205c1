// tools/experiment/paper_experiment.sh --save-checkpoints at toy sizes (--bin:
// this build's programs): a trial in progress on one machine goes into the
// repository folder as a portable checkpoint, and the run on a new machine
// continues it from there instead of generation 0; its compact results, in
// every milestone (the later ones extend the continued log), are those of a
// machine that never stopped, wall time aside. A finished trial's portable
// checkpoint is removed by the next --save-checkpoints. The trials a later
// milestone continues travel too, once the milestone they are in has finished
// them: in the later milestone's checkpoints/ folder.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

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
  // done here (none is in progress to save), and says so; the trial's compact results come
  // into the repository in its place, without a --collect.
  ASSERT_FALSE(fs::exists(paper + "/results/feedforward-s1.results.json"));
  const auto cleaned = run_shell(script(paper, second, "--save-checkpoints"));
  EXPECT_EQ(cleaned.status, 0) << cleaned.output;
  EXPECT_FALSE(fs::exists(file)) << cleaned.output;
  for (const char* folder : {"results", "m2/results"})
    EXPECT_EQ(timeless(paper + "/" + folder + "/feedforward-s1.results.json"),
              timeless(second + "/" + folder + "/feedforward-s1.results.json"))
        << folder;
  EXPECT_NE(cleaned.output.find("M1: 4 compact results finished here -> "), std::string::npos) << cleaned.output;
  EXPECT_NE(cleaned.output.find("M1: feedforward-s1 finished: removed"), std::string::npos) << cleaned.output;
  EXPECT_NE(cleaned.output.find("every milestone finished on this machine"), std::string::npos) << cleaned.output;
}

/// A machine whose run stopped after the milestones named: the markers of the others make
/// the script pass them by, and are removed afterwards (those milestones have not started).
void run_until(const std::string& paper, const std::string& dir, const std::vector<std::string>& not_yet) {
  fs::create_directories(dir);
  for (const auto& name : not_yet) std::ofstream(dir + "/" + name + ".done") << "not yet\n";
  const auto run = run_shell(script(paper, dir));
  ASSERT_EQ(run.status, 0) << run.output;
  for (const auto& name : not_yet) fs::remove(dir + "/" + name + ".done");
}

/// The script's output from the line that starts `milestone` to the one that ends it.
std::string section(const std::string& output, const std::string& milestone) {
  const size_t from = output.find("paper_experiment.sh: " + milestone + ": ");
  if (from == std::string::npos) return "";
  const size_t to = output.find("paper_experiment.sh: " + milestone + " done", from);
  return output.substr(from, to == std::string::npos ? std::string::npos : to - from);
}

std::vector<std::string> files_in(const std::string& folder) {
  std::vector<std::string> names;
  if (fs::is_directory(folder))
    for (const auto& f : fs::directory_iterator(folder)) names.push_back(f.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

const std::vector<std::string> kExtensions = {"M3-100", "M3-150", "M3-500"};

void expect_same_results(const std::string& dir, const std::string& reference) {
  for (const char* folder : {"m3/g100/results", "m3/g150/results", "m3/g500/results"})
    for (const char* trial : {"feedforward-s1", "recurrent-s2"}) {
      const std::string name = std::string(folder) + "/" + trial + ".results.json";
      ASSERT_TRUE(fs::exists(dir + "/" + name)) << name;
      EXPECT_EQ(timeless(dir + "/" + name), timeless(reference + "/" + name)) << name;
    }
}

TEST(PaperExperimentCheckpointsCli, TrialsAFinishedMilestoneLeavesToTheNextTravelInTheNextOnesFolder) {
  TempDir t;
  // The first machine stopped before the last sensitivity factor began, after M3: M3-100 will
  // continue M3's trials, whose logs only this machine has.
  const std::string paper = t / "paper", first = t / "first";
  std::vector<std::string> not_yet = kExtensions;
  not_yet.push_back("S-cap-100");
  run_until(paper, first, not_yet);
  fs::remove_all(first + "/sensitivity/cap-100");
  const auto saved = run_shell(script(paper, first, "--save-checkpoints"));
  ASSERT_EQ(saved.status, 0) << saved.output;
  EXPECT_NE(saved.output.find("M3-100: portable checkpoints of the trials M3 finished here"), std::string::npos)
      << saved.output;
  EXPECT_EQ(files_in(paper + "/m3/g100/checkpoints"),
            (std::vector<std::string>{"feedforward-s1.portable-checkpoint", "recurrent-s2.portable-checkpoint"}))
      << saved.output;
  // M3-150 continues M3-100, which has not started: nothing of it yet.
  EXPECT_FALSE(fs::exists(paper + "/m3/g150/checkpoints")) << saved.output;
  const auto collected = run_shell(script(paper, first, "--collect"));
  ASSERT_EQ(collected.status, 0) << collected.output;

  // A new machine with the repository folder only: M3-100 continues M3's trials from there.
  const std::string second = t / "second";
  const auto run = run_shell(script(paper, second));
  ASSERT_EQ(run.status, 0) << run.output;
  const std::string m3_100 = section(run.output, "M3-100");
  EXPECT_NE(m3_100.find("feedforward-s1: continues from the portable checkpoint"), std::string::npos) << run.output;
  EXPECT_NE(m3_100.find("recurrent-s2: continues from the portable checkpoint"), std::string::npos) << run.output;
  const std::string whole = t / "whole";
  const auto reference = run_shell(script(t / "other-paper", whole));
  ASSERT_EQ(reference.status, 0) << reference.output;
  expect_same_results(second, whole);
}

TEST(PaperExperimentCheckpointsCli, ATrialStillRunningInTheMilestoneBeingRunTravelsInItsFolderOnly) {
  TempDir t;
  // The first machine stopped during M3-100: it had continued feedforward-s1 to generation 3,
  // and recurrent-s2 not yet (its log is as M3 left it, at generation 2).
  const std::string paper = t / "paper", after_m3 = t / "after-m3", first = t / "first";
  run_until(t / "paper-a", after_m3, kExtensions);
  run_until(t / "paper-b", first, {"M3-150", "M3-500"});
  for (const char* ext : {".lcmlog", ".lcmlog.checkpoint", ".out"})
    fs::copy_file(after_m3 + "/m3/runs/recurrent-s2" + ext, first + "/m3/runs/recurrent-s2" + ext,
                  fs::copy_options::overwrite_existing);
  fs::remove(first + "/m3/g100/results/recurrent-s2.results.json");
  fs::remove(first + "/M3-100.done");

  const auto saved = run_shell(script(paper, first, "--save-checkpoints"));
  ASSERT_EQ(saved.status, 0) << saved.output;
  EXPECT_EQ(files_in(paper + "/m3/g100/checkpoints"), (std::vector<std::string>{"recurrent-s2.portable-checkpoint"}))
      << saved.output;
  EXPECT_EQ(files_in(paper + "/m3/g150/checkpoints"), (std::vector<std::string>{"feedforward-s1.portable-checkpoint"}))
      << saved.output;
  EXPECT_NE(saved.output.find("M3-150: recurrent-s2 is still running in M3-100: removed"), std::string::npos)
      << saved.output;
  const auto collected = run_shell(script(paper, first, "--collect"));
  ASSERT_EQ(collected.status, 0) << collected.output;

  // A new machine: M3-100 continues recurrent-s2 from its folder, M3-150 feedforward-s1 from its own.
  const std::string second = t / "second";
  const auto run = run_shell(script(paper, second));
  ASSERT_EQ(run.status, 0) << run.output;
  EXPECT_NE(section(run.output, "M3-100").find("recurrent-s2: continues from the portable checkpoint"),
            std::string::npos)
      << run.output;
  EXPECT_NE(section(run.output, "M3-150").find("feedforward-s1: continues from the portable checkpoint"),
            std::string::npos)
      << run.output;
  const std::string whole = t / "whole";
  const auto reference = run_shell(script(t / "other-paper", whole));
  ASSERT_EQ(reference.status, 0) << reference.output;
  expect_same_results(second, whole);
}

}  // namespace
}  // namespace robozoo
