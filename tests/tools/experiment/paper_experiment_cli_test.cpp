// tools/experiment/paper_experiment.sh at toy sizes (--bin: this build's programs): each
// milestone keeps its own compact results, a milestone finished on this machine
// is not run again (so its results are not rewritten from logs a later milestone
// extended), M3 and each sensitivity factor run with their own configuration in
// folders of their own, --collect copies every milestone's results, and on a new
// machine a milestone whose results are all committed is not run, while the rest
// runs again from generation 0 and repeats what the first machine computed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;
namespace fs = std::filesystem;

std::string script(const TempDir& t, const std::string& dir, const std::string& extra = "") {
  return "bash '" + std::string(ROBOZOO_SOURCE_DIR) + "/tools/experiment/paper_experiment.sh' --bin '" +
         std::string(ROBOZOO_BIN_DIR) + "' --paper '" + (t / "paper") + "' --dir '" + dir +
         "' --trials 1 --sensitivity-trials 1 --population 6 --steps 100 --generations 2,3,2,2,3,4,5 --workers 1 " +
         extra + " </dev/null";
}

nlohmann::json results(const std::string& path) { return nlohmann::json::parse(read_file(path)); }

/// Generations the result holds (its columns, one entry per generation).
size_t generations(const std::string& path) { return results(path).at("generations").at("generation").size(); }

/// The result without the run's wall time, which differs from run to run.
nlohmann::json timeless(const std::string& path) {
  nlohmann::json j = results(path);
  j.erase("evolve_seconds");
  return j;
}

TEST(PaperExperimentCli, MilestonesKeepTheirOwnResultsAndAreNotRunTwice) {
  TempDir t;
  const std::string d = t / "d";
  const Outcome first = run_shell(script(t, d));
  ASSERT_EQ(first.status, 0) << first.output;
  for (const char* trial : {"feedforward-s1", "recurrent-s2", "recurrent-sparse-s3", "recurrent-zero-s4"})
    EXPECT_EQ(generations(d + "/results/" + trial + ".results.json"), 2u) << trial;
  const char* factors[] = {"bias-1.0", "proportional-weights", "shared-add-node", "no-contact-rule", "cap-100"};
  for (const char* trial : {"feedforward-s1", "recurrent-s2"}) {
    const std::string name = std::string(trial) + ".results.json";
    EXPECT_EQ(generations(d + "/m2/results/" + name), 3u) << trial;
    EXPECT_EQ(generations(d + "/m3/results/" + name), 2u) << trial;
    EXPECT_EQ(generations(d + "/m3/g100/results/" + name), 3u) << trial;
    EXPECT_EQ(generations(d + "/m3/g150/results/" + name), 4u) << trial;
    EXPECT_EQ(generations(d + "/m3/g500/results/" + name), 5u) << trial;
    // M1 and M2 ran with what this build records (--bin); M3 says its settings in full.
    const nlohmann::json m3 = results(d + "/m3/results/" + name).at("run").at("config");
    EXPECT_EQ(m3.at("growth").at("bias_input"), 0.3);
    EXPECT_EQ(m3.at("growth").at("weight_mapping"), "rescaled");
    EXPECT_EQ(m3.at("neat").at("add_node_innovations"), "fresh");
    for (const char* f : factors) EXPECT_EQ(generations(d + "/sensitivity/" + f + "/results/" + name), 2u) << f;
    // Each factor changes one key from M3's configuration, on M3's seeds.
    auto config = [&](const char* f) {
      return results(d + "/sensitivity/" + f + "/results/" + name).at("run").at("config");
    };
    EXPECT_EQ(config("bias-1.0").at("growth").at("bias_input"), 1.0);
    EXPECT_EQ(config("proportional-weights").at("growth").at("weight_mapping"), "proportional");
    EXPECT_EQ(config("shared-add-node").at("neat").at("add_node_innovations"), "shared");
    EXPECT_EQ(config("no-contact-rule").at("sim").at("rolling_contact_rule"), false);
    EXPECT_EQ(config("no-contact-rule").at("sim").at("rolling_spin_rule"), true);
    EXPECT_EQ(config("cap-100").at("growth").at("max_spheres"), 100);
    nlohmann::json bias = config("bias-1.0");
    bias["growth"]["bias_input"] = 0.3;
    EXPECT_EQ(bias, m3) << "only the factor differs";
  }
  EXPECT_TRUE(fs::exists(d + "/m3/runs/recurrent-s2.lcmlog")) << "M3's logs are not M1's and M2's";
  EXPECT_FALSE(fs::exists(d + "/m2/results/recurrent-sparse-s3.results.json"));
  for (const char* m : {"M1", "M2", "M3", "S-bias-1.0", "S-cap-100", "M3-100", "M3-150", "M3-500"})
    EXPECT_TRUE(fs::exists(d + "/" + m + ".done")) << m;

  // Again: nothing runs, and M1's results stay those of generation 2 although the
  // logs beside them now reach generation 4.
  const std::string m1_before = read_file(d + "/results/feedforward-s1.results.json");
  const Outcome again = run_shell(script(t, d));
  ASSERT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("M1 finished before on this machine"), std::string::npos) << again.output;
  EXPECT_NE(again.output.find("M3 finished before on this machine"), std::string::npos) << again.output;
  EXPECT_EQ(generations(d + "/results/feedforward-s1.results.json"), 2u);
  EXPECT_TRUE(read_file(d + "/results/feedforward-s1.results.json") == m1_before) << "M1's result was rewritten";

  // --collect: every milestone's results, byte for byte, in its own folder.
  const Outcome collect = run_shell(script(t, d, "--collect"));
  ASSERT_EQ(collect.status, 0) << collect.output;
  EXPECT_NE(collect.output.find("M1: 4 compact results"), std::string::npos) << collect.output;
  EXPECT_NE(collect.output.find("M2: 2 compact results"), std::string::npos) << collect.output;
  EXPECT_TRUE(read_file(t / "paper/results/feedforward-s1.results.json") == m1_before);
  EXPECT_TRUE(read_file(t / "paper/m2/results/recurrent-s2.results.json") ==
              read_file(d + "/m2/results/recurrent-s2.results.json"));
  EXPECT_EQ(generations(t / "paper/m3/results/recurrent-s2.results.json"), 2u);
  EXPECT_EQ(generations(t / "paper/m3/g500/results/recurrent-s2.results.json"), 5u);
  EXPECT_EQ(generations(t / "paper/sensitivity/cap-100/results/recurrent-s2.results.json"), 2u);
  // ... and each later milestone's trials repeat the earlier one's generations.
  EXPECT_NE(collect.output.find("M2: 2 trials in both folders agree over the generations both hold (M1's)"),
            std::string::npos)
      << collect.output;
  EXPECT_NE(collect.output.find("M3-100: 2 trials in both folders agree over the generations both hold (M3's)"),
            std::string::npos)
      << collect.output;
  EXPECT_NE(collect.output.find("M3-500: 2 trials in both folders agree over the generations both hold (M3-150's)"),
            std::string::npos)
      << collect.output;

  // A collected M2 result that does not repeat M1's generation 1 is found and named.
  nlohmann::json changed = results(d + "/m2/results/recurrent-s2.results.json");
  changed["generations"]["mean_fitness"][1] = changed["generations"]["mean_fitness"][1].get<double>() + 1e-6;
  std::ofstream(d + "/m2/results/recurrent-s2.results.json") << changed.dump();
  const Outcome differ = run_shell(script(t, d, "--collect"));
  EXPECT_EQ(differ.status, 1) << differ.output;
  EXPECT_NE(differ.output.find("M2: its results do not repeat M1's generations"), std::string::npos) << differ.output;
  EXPECT_NE(differ.output.find("recurrent-s2: generations 0-1 (3 and 2 held) DIFFER at generation 1: mean_fitness"),
            std::string::npos)
      << differ.output;
}

TEST(PaperExperimentCli, ANewMachineCountsCommittedResultsAndRepeatsTheRest) {
  TempDir t;
  const std::string d = t / "d";
  ASSERT_EQ(run_shell(script(t, d)).status, 0);
  ASSERT_EQ(run_shell(script(t, d, "--collect")).status, 0);
  // Only M1 and M3 were committed: M1 and M3 are not run at all; M2's trials (known
  // here from their generation-2 results alone) run again from generation 0, and so do
  // M3's for its extensions.
  fs::remove_all(t / "paper/m2");
  fs::remove_all(t / "paper/m3/g100");
  fs::remove_all(t / "paper/m3/g150");
  fs::remove_all(t / "paper/m3/g500");
  fs::remove_all(t / "paper/sensitivity");
  const std::string other = t / "other";
  // --status asks and runs nothing: the committed milestones are named as such.
  const Outcome status = run_shell(script(t, other, "--status"));
  ASSERT_EQ(status.status, 0) << status.output;
  EXPECT_NE(status.output.find("M1: every trial's compact result is in"), std::string::npos) << status.output;
  EXPECT_NE(status.output.find("M2: feedforward,recurrent to generation 3, 1 trials each"), std::string::npos)
      << status.output;
  EXPECT_FALSE(fs::exists(other + "/runs"));
  const Outcome o = run_shell(script(t, other));
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("M1: every trial's compact result is in"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("M3: every trial's compact result is in"), std::string::npos) << o.output;
  EXPECT_FALSE(fs::exists(other + "/runs/recurrent-sparse-s3.lcmlog"));  // M1's trials ran nowhere here
  EXPECT_TRUE(fs::exists(other + "/runs/recurrent-s2.lcmlog"));
  for (const char* trial : {"feedforward-s1", "recurrent-s2"}) {
    const std::string name = std::string(trial) + ".results.json";
    EXPECT_TRUE(read_file(other + "/results/" + name) == read_file(d + "/results/" + name)) << trial;
    // A run is deterministic: run afresh, each milestone repeats the first machine's.
    EXPECT_EQ(timeless(other + "/m2/results/" + name), timeless(d + "/m2/results/" + name)) << trial;
    EXPECT_TRUE(read_file(other + "/m3/results/" + name) == read_file(d + "/m3/results/" + name)) << trial;
    EXPECT_EQ(timeless(other + "/m3/g500/results/" + name), timeless(d + "/m3/g500/results/" + name)) << trial;
    EXPECT_EQ(timeless(other + "/sensitivity/shared-add-node/results/" + name),
              timeless(d + "/sensitivity/shared-add-node/results/" + name))
        << trial;
  }
}

TEST(PaperExperimentCli, AVersionWithoutPortableCheckpointsIsNotAskedForThem) {
  // M1 and M2's pinned version predates --checkpoints and --save-checkpoints: stand-ins for its
  // programs record how they are called.
  TempDir t;
  const std::string bin = t / "bin", calls = t / "calls.txt";
  fs::create_directories(bin);
  auto stub = [&](const std::string& name, const std::string& help) {
    std::ofstream(bin + "/" + name) << "#!/bin/sh\n"
                                    << "case \"$1\" in --help) echo '" << help
                                    << "'; exit 0 ;; --version) echo old; exit 0 ;; esac\n"
                                    << "echo \"$*\" >> '" << calls << "'\n";
    fs::permissions(bin + "/" + name, fs::perms::owner_all);
  };
  stub("robozoo-evolve", "robozoo-evolve --log --resume");
  stub("robozoo-experiment", "robozoo-experiment --out --results --trials --status");
  const std::string base = "bash '" + std::string(ROBOZOO_SOURCE_DIR) +
                           "/tools/experiment/paper_experiment.sh' --bin '" + bin + "' --paper '" + (t / "paper") +
                           "' --dir '" + (t / "dir") + "' --trials 1 ";
  const Outcome status = run_shell(base + "--status </dev/null");
  EXPECT_EQ(status.status, 0) << status.output;
  const std::string called = read_file(calls);
  EXPECT_NE(called.find("--status"), std::string::npos) << called;
  EXPECT_EQ(called.find("--checkpoints"), std::string::npos) << called;
  const Outcome save = run_shell(base + "--save-checkpoints </dev/null");
  EXPECT_EQ(save.status, 2) << save.output;
  EXPECT_NE(save.output.find("M1 runs a robozoo version without portable checkpoints"), std::string::npos)
      << save.output;
  // This build's robozoo-experiment has them: they are passed.
  stub("robozoo-experiment", "robozoo-experiment --out --checkpoints --save-checkpoints");
  fs::remove(calls);
  EXPECT_EQ(run_shell(base + "--status </dev/null").status, 0);
  EXPECT_NE(read_file(calls).find("--checkpoints " + (t / "paper") + "/checkpoints"), std::string::npos)
      << read_file(calls);
}

TEST(PaperExperimentCli, RefusesBadSizes) {
  TempDir t;
  const Outcome o =
      run_shell("bash '" + std::string(ROBOZOO_SOURCE_DIR) + "/tools/experiment/paper_experiment.sh' --dir '" +
                (t / "d") + "' --generations 30,60,60 </dev/null");
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("not a positive count"), std::string::npos) << o.output;
}

}  // namespace
}  // namespace robozoo
