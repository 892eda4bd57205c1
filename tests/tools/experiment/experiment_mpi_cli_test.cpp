// robozoo-experiment --mpi: each trial runs as an MPI job (mpirun -np N
// robozoo-evolve --mpi), and gives the same log as a local trial; a stopped MPI
// experiment leaves no rank behind and resumes, on another rank count, to the
// identical run; bad MPI settings are refused before anything runs.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>

#include <fstream>

#include "evolve/io/event_log.hpp"
#include "evolve/io/log_compare.hpp"
#include "evolve/record/checkpoint.hpp"
#include "tests/support/mpirun.hpp"
#include "tests/support/evolve_runs.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

/// The tests' mpirun and its options, as one --mpirun value (without -np N).
std::string launcher() {
  std::vector<std::string> a = mpirun_args(2);
  a.resize(a.size() - 2);
  std::string s;
  for (const auto& w : a) s += (s.empty() ? "" : " ") + w;
  return s;
}

std::vector<std::string> mpi_driver(const std::string& out, int ranks, const std::vector<std::string>& sizes) {
  std::vector<std::string> a = {
      bin("robozoo-experiment"), "--out", out, "--mpi", std::to_string(ranks), "--mpirun", launcher(),
      "--progress-interval",     "0"};
  a.insert(a.end(), sizes.begin(), sizes.end());
  return a;
}

/// The same trial run locally by robozoo-evolve with one worker.
LogContents local_trial(const TempDir& dir, const std::string& regime, const std::vector<std::string>& sizes) {
  std::vector<std::string> a = {bin("robozoo-evolve"),
                                "--log",
                                dir / (regime + ".lcmlog"),
                                "--regime",
                                regime,
                                "--seed",
                                regime == "recurrent" ? "2" : "1",
                                "--workers",
                                "1",
                                "--quiet"};
  a.insert(a.end(), sizes.begin(), sizes.end());
  const auto r = run_shell(join(a));
  EXPECT_EQ(r.status, 0) << r.output;
  return read_event_log(dir / (regime + ".lcmlog"));
}

TEST(ExperimentMpiCli, TrialsRunAsMpiJobsAndEqualLocalTrials) {
  TempDir dir, ref;
  // M1/M2's bias input, so that the feed-forward trial's robots reach the simulator too.
  const auto r = run_shell(join(mpi_driver(dir.path, 3,
                                           {"--trials", "1", "--population", "10", "--generations", "2", "--steps",
                                            "200", "--set", "growth.bias_input=1.0"})));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("MPI jobs of 3 ranks"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("-np 3 " + bin("robozoo-evolve") + " --log"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--mpi"), std::string::npos) << r.output;
  const std::vector<std::string> sizes = {"--population", "10",  "--generations", "2",
                                          "--steps",      "200", "--set",         "growth.bias_input=1.0"};
  for (const std::string regime : {"feedforward", "recurrent"}) {
    // Trial 1: feedforward seed 1, recurrent seed 2.
    const std::string name = regime + (regime == "recurrent" ? "-s2" : "-s1");
    ASSERT_TRUE(read_checkpoint(dir / (name + ".lcmlog.checkpoint")).finished) << regime;
    const auto mpi = read_event_log(dir / (name + ".lcmlog"));
    EXPECT_GT(mpi.records.size(), 20u) << regime;
    EXPECT_EQ(first_log_difference(mpi, local_trial(ref, regime, sizes)), "") << regime;
  }
}

TEST(ExperimentMpiCli, AStoppedMpiExperimentLeavesNoRankAndResumesOnOtherRanks) {
  TempDir dir, ref;
  const std::vector<std::string> evolve_sizes = {"--population", "16", "--generations", "8", "--steps", "500"};
  std::vector<std::string> sizes = {"--trials", "1"};
  sizes.insert(sizes.end(), evolve_sizes.begin(), evolve_sizes.end());
  const pid_t pid = spawn(mpi_driver(dir.path, 2, sizes), dir / "driver1.txt");
  // Stop it (as Ctrl-C would) once the first trial has finished and the second
  // has checkpointed its first generation.
  const std::string ff_cp = dir / "feedforward-s1.lcmlog.checkpoint";
  const std::string rec_cp = dir / "recurrent-s2.lcmlog.checkpoint";
  for (int i = 0; i < 12000 && !file_exists(rec_cp); ++i) ::usleep(5000);
  ASSERT_TRUE(file_exists(rec_cp)) << read_file(dir / "driver1.txt");
  kill_process(pid, SIGINT);
  EXPECT_EQ(wait_status(pid), 128 + SIGINT);
  EXPECT_NE(read_file(dir / "driver1.txt").find("Run the same command again to resume"), std::string::npos)
      << read_file(dir / "driver1.txt");
  ASSERT_TRUE(read_checkpoint(ff_cp).finished);
  ASSERT_FALSE(read_checkpoint(rec_cp).finished) << "the trial finished before the signal";
  // Neither mpirun nor any rank of the stopped trial is left running.
  EXPECT_EQ(processes_left(dir.path + "/[r]ecurrent-s1.lcmlog"), "");

  // Resumed with 3 ranks: the stopped trial ends equal to an uninterrupted local run.
  const auto resumed = run_shell(join(mpi_driver(dir.path, 3, sizes)));
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("1 finished (skipped), 1 to resume, 0 to start"), std::string::npos) << resumed.output;
  EXPECT_NE(resumed.output.find("recurrent-s2: resuming after generation"), std::string::npos) << resumed.output;
  EXPECT_TRUE(read_checkpoint(rec_cp).finished);
  EXPECT_EQ(
      first_log_difference(read_event_log(dir / "recurrent-s2.lcmlog"), local_trial(ref, "recurrent", evolve_sizes)),
      "");
}

TEST(ExperimentMpiCli, BadMpiSettingsAreRefusedBeforeAnythingRuns) {
  TempDir dir;
  const std::vector<std::string> tiny = {"--trials", "1", "--population", "10", "--generations", "2"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = {bin("robozoo-experiment"), "--out", dir.path};
    a.insert(a.end(), tiny.begin(), tiny.end());
    a.insert(a.end(), extra.begin(), extra.end());
    return run_shell(join(a));
  };
  const auto one_rank = with({"--mpi", "1"});
  EXPECT_NE(one_rank.status, 0);
  EXPECT_NE(one_rank.output.find("--mpi"), std::string::npos) << one_rank.output;
  const auto both = with({"--mpi", "2", "--workers", "2"});
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.output.find("--workers and --mpi exclude each other"), std::string::npos) << both.output;
  const auto no_launcher = with({"--mpi", "2", "--mpirun", "no-such-mpirun --oversubscribe"});
  EXPECT_EQ(no_launcher.status, 2);
  EXPECT_NE(no_launcher.output.find("cannot run the MPI launcher no-such-mpirun"), std::string::npos)
      << no_launcher.output;
  const auto launcher_alone = with({"--mpirun", "mpirun"});
  EXPECT_EQ(launcher_alone.status, 2);
  EXPECT_NE(launcher_alone.output.find("--mpirun only applies with --mpi"), std::string::npos);
  EXPECT_FALSE(file_exists(dir / "feedforward-s1.lcmlog"));
  const auto help = run_shell(bin("robozoo-experiment") + " --help");
  EXPECT_NE(help.output.find("--mpi"), std::string::npos);
  EXPECT_NE(help.output.find("--mpirun"), std::string::npos);
}

TEST(ExperimentMpiCli, AFailedMpiJobIsReportedWithItsLastWords) {
  TempDir dir;
  const std::string fake = dir / "fake-mpirun";
  {
    std::ofstream f(fake);
    f << "#!/bin/sh\necho \"fake-mpirun: not enough slots for $2 ranks\"\nexit 1\n";
  }
  ::chmod(fake.c_str(), 0755);
  const auto r = run_shell(join({bin("robozoo-experiment"), "--out", dir / "exp", "--trials", "1", "--population", "10",
                                 "--generations", "2", "--mpi", "4", "--mpirun", fake}));
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("the MPI job of robozoo-evolve failed on feedforward-s1 (exit status 1)"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("fake-mpirun: not enough slots for 4 ranks"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("recurrent-s2: starting"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace robozoo
