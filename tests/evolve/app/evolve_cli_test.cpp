// robozoo-evolve as a user runs it: determinism across worker counts, kill -9
// and resume, a worker killed on purpose, live publishing recorded by LCM's own
// lcm-logger inside a private network namespace, bad configuration.
#include <fcntl.h>
#include <gtest/gtest.h>

#include "evolve/io/event_log.hpp"
#include "evolve/io/log_compare.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/run/checkpoint.hpp"
#include "tests/support/evolve_runs.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;


int run_evolve(const std::string& log, int workers, std::vector<std::string> extra = {},
               const std::vector<std::string>& size = kSmall) {
  const auto o = run_shell(join(evolve_args(log, workers, std::move(extra), size)));
  EXPECT_EQ(o.status, 0) << o.output;
  return o.status;
}


TEST(EvolveCli, HelpDocumentsEveryFlag) {
  const auto o = run_shell(bin("robozoo-evolve") + " --help");
  EXPECT_EQ(o.status, 0);
  for (const char* flag : {"--regime", "--seed", "--population", "--generations", "--steps", "--workers", "--config",
                           "--log", "--lcm-url", "--pose-every", "--publish-all", "--resume"})
    EXPECT_NE(o.output.find(flag), std::string::npos) << flag;
}

TEST(EvolveCli, OneAndTwoWorkersGiveIdenticalLogs) {
  TempDir dir;
  ASSERT_EQ(run_evolve(dir / "w1.lcmlog", 1), 0);
  ASSERT_EQ(run_evolve(dir / "w2.lcmlog", 2), 0);
  const auto a = read_event_log(dir / "w1.lcmlog"), b = read_event_log(dir / "w2.lcmlog");
  EXPECT_EQ(first_log_difference(a, b), "");
  // The log holds what the issue asks for.
  EXPECT_EQ(count_channel(a, kChannelRun), 4u);
  EXPECT_EQ(count_channel(a, kChannelGeneration), 4u);
  EXPECT_EQ(count_channel(a, kChannelGenome), 4u);
  EXPECT_EQ(count_channel(a, kChannelMorphology), 4u);
  EXPECT_EQ(a.records.front().channel, kChannelRun);
  // Every event decodes with the generated types.
  for (const auto& r : a.records) {
    std::vector<uint8_t> norm;
    EXPECT_TRUE(normalize_message(r.channel, r.data, norm)) << r.channel;
  }
}

TEST(EvolveCli, KillNineThenResumeEqualsUninterruptedRun) {
  TempDir dir;
  ASSERT_EQ(run_evolve(dir / "whole.lcmlog", 2, {}, kLonger), 0);
  const std::string log = dir / "cut.lcmlog";
  // Kill at several moments: at start, early and mid-run; then once more while resuming.
  for (int delay_ms : {20, 300, 800}) {
    const pid_t pid = spawn(evolve_args(log, 2, {}, kLonger), dir / "out.txt");
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    kill_process(pid, SIGKILL);
    EXPECT_EQ(wait_status(pid), 128 + SIGKILL) << "the run ended before the kill at " << delay_ms << " ms";
    // Its workers die with it (they watch their parent); give them a moment.
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    if (file_exists(log + ".checkpoint")) {
      const pid_t again = spawn(evolve_args(log, 2, {"--resume"}, kLonger), dir / "out2.txt");
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      kill_process(again, SIGKILL);
      wait_status(again);
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    ASSERT_EQ(run_evolve(log, 2, {"--resume"}, kLonger), 0);
    EXPECT_EQ(first_log_difference(read_event_log(dir / "whole.lcmlog"), read_event_log(log)), "")
        << "killed after " << delay_ms << " ms";
    std::remove(log.c_str());
    std::remove((log + ".checkpoint").c_str());
  }
}

TEST(EvolveCli, ResumeUsesTheCheckpointsConfigurationNotTheCommandLines) {
  // Killed early, then resumed with no size flags at all: the workers must
  // evaluate with the run's own settings (--steps 1000 etc.), not the defaults.
  TempDir dir;
  ASSERT_EQ(run_evolve(dir / "whole.lcmlog", 2, {}, kLonger), 0);
  const std::string log = dir / "cut.lcmlog";
  const pid_t pid = spawn(evolve_args(log, 2, {}, kLonger), dir / "out.txt");
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  kill_process(pid, SIGKILL);
  wait_status(pid);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const auto o = run_shell(join({bin("robozoo-evolve"), "--log", log, "--resume", "--workers", "2", "--quiet"}));
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(first_log_difference(read_event_log(dir / "whole.lcmlog"), read_event_log(log)), "");
}

TEST(EvolveCli, ResumeOfAFinishedRunChangesNothing) {
  TempDir dir;
  ASSERT_EQ(run_evolve(dir / "a.lcmlog", 1), 0);
  const std::string before = read_file(dir / "a.lcmlog");
  const auto o = run_shell(join(evolve_args(dir / "a.lcmlog", 1, {"--resume"})));
  EXPECT_EQ(o.status, 0);
  EXPECT_EQ(read_file(dir / "a.lcmlog"), before);
}

TEST(EvolveCli, RefusesToOverwriteAResumableRun) {
  TempDir dir;
  ASSERT_EQ(run_evolve(dir / "a.lcmlog", 1), 0);
  const auto o = run_shell(join(evolve_args(dir / "a.lcmlog", 1)));
  EXPECT_EQ(o.status, 2);
  EXPECT_NE(o.output.find("--resume"), std::string::npos);
}

TEST(EvolveCli, WorkerKilledOnPurposeChangesNothing) {
  TempDir dir;
  ASSERT_EQ(run_evolve(dir / "whole.lcmlog", 2, {}, kLonger), 0);
  const std::string log = dir / "hit.lcmlog";
  const pid_t pid = spawn(evolve_args(log, 2, {}, kLonger), dir / "out.txt");
  int killed = 0;
  for (int i = 0; i < 40 && killed < 3; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const auto kids = children_of(pid);
    if (kids.size() == 2 && i % 3 == 2) {
      kill_process(kids[killed % 2], SIGKILL);
      ++killed;
    }
  }
  ASSERT_EQ(wait_status(pid), 0) << read_file(dir / "out.txt");
  EXPECT_GE(killed, 1);
  EXPECT_EQ(first_log_difference(read_event_log(dir / "whole.lcmlog"), read_event_log(log)), "");
}

TEST(EvolveCli, LogReplaysThroughLcmLogplayer) {
  TempDir dir;
  ASSERT_EQ(run_evolve(dir / "a.lcmlog", 2), 0);
  const std::string out = dir / "played.lcmlog";
  const auto o = run_shell("lcm-logplayer -s 1000 -l 'file://" + out + "?mode=w' '" + (dir / "a.lcmlog") + "'");
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(first_log_difference(read_event_log(dir / "a.lcmlog"), read_event_log(out)), "");
}

TEST(EvolveCli, BadConfigurationIsOneLineAndExitTwoAndLeavesNothing) {
  TempDir dir;
  const std::string unknown = dir / "unknown.toml", range = dir / "range.json";
  std::ofstream(unknown) << "[neat]\nwobble = 1\n";
  std::ofstream(range) << R"({"growth": {"t_matter": 1.5}})";
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--config", unknown}, "neat.wobble: unknown key"},
      {{"--config", range}, "growth.t_matter"},
      {{"--config", dir / "missing.toml"}, "cannot read"},
      {{"--population", "-5"}, "population"},
      {{"--regime", "sideways"}, "regime"},
  };
  for (const auto& [args, expect] : cases) {
    const std::string log = dir / "bad.lcmlog";
    std::vector<std::string> a = {bin("robozoo-evolve"), "--log", log};
    a.insert(a.end(), args.begin(), args.end());
    const auto o = run_shell(join(a));
    EXPECT_EQ(o.status, 2) << o.output;
    EXPECT_NE(o.output.find(expect), std::string::npos) << o.output;
    EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << o.output;
    EXPECT_FALSE(file_exists(log));
    EXPECT_FALSE(file_exists(log + ".checkpoint"));
  }
}

}  // namespace
}  // namespace robozoo
