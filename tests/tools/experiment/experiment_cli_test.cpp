// robozoo-experiment as a user runs it: a finished experiment is not redone, a
// stopped one (Ctrl-C) resumes where it stopped and ends as an uninterrupted
// one would, and a folder of another experiment is refused.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>

#include "evolve/io/event_log.hpp"
#include "evolve/io/log_compare.hpp"
#include "evolve/record/checkpoint.hpp"
#include "tests/support/evolve_runs.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

std::vector<std::string> driver(const std::string& out, const std::vector<std::string>& sizes) {
  std::vector<std::string> a = {bin("robozoo-experiment"), "--out", out, "--workers", "1", "--progress-interval", "0"};
  a.insert(a.end(), sizes.begin(), sizes.end());
  return a;
}

struct FileStamp {
  std::string content;
  int64_t mtime_ns = 0;
  bool operator==(const FileStamp& o) const { return content == o.content && mtime_ns == o.mtime_ns; }
};
FileStamp stamp(const std::string& path) {
  struct stat st {};
  ::stat(path.c_str(), &st);
  return {read_file(path), static_cast<int64_t>(st.st_mtim.tv_sec) * 1000000000 + st.st_mtim.tv_nsec};
}

const std::vector<std::string> kTiny = {"--trials", "1", "--population", "10", "--generations", "2", "--steps", "200"};

TEST(ExperimentCli, AFinishedExperimentIsNotRedone) {
  TempDir dir;
  const auto first = run_shell(join(driver(dir.path, kTiny)));
  ASSERT_EQ(first.status, 0) << first.output;
  EXPECT_NE(first.output.find("0 finished (skipped), 0 to resume, 2 to start"), std::string::npos) << first.output;
  EXPECT_NE(first.output.find("experiment 100.0%"), std::string::npos) << first.output;
  const FileStamp ff = stamp(dir / "feedforward-s1.lcmlog"), rec = stamp(dir / "recurrent-s2.lcmlog");
  ASSERT_FALSE(ff.content.empty());
  ASSERT_TRUE(read_checkpoint(dir / "recurrent-s2.lcmlog.checkpoint").finished);

  const auto again = run_shell(join(driver(dir.path, kTiny)));
  EXPECT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("2 finished (skipped), 0 to resume, 0 to start"), std::string::npos) << again.output;
  EXPECT_EQ(again.output.find("starting"), std::string::npos) << again.output;
  EXPECT_TRUE(stamp(dir / "feedforward-s1.lcmlog") == ff);
  EXPECT_TRUE(stamp(dir / "recurrent-s2.lcmlog") == rec);

  // More trials later: only the new ones run.
  std::vector<std::string> more = kTiny;
  more[1] = "2";
  const auto extended = run_shell(join(driver(dir.path, more)));
  EXPECT_EQ(extended.status, 0) << extended.output;
  EXPECT_NE(extended.output.find("2 finished (skipped), 0 to resume, 2 to start"), std::string::npos);
  EXPECT_TRUE(stamp(dir / "feedforward-s1.lcmlog") == ff);
  EXPECT_TRUE(file_exists(dir / "recurrent-s6.lcmlog"));

  const auto status = run_shell(join(driver(dir.path, more)) + " --status");
  EXPECT_EQ(status.status, 0);
  EXPECT_NE(status.output.find("recurrent-s6          finished         2/2"), std::string::npos) << status.output;

  // Other sizes in the same folder: refused before anything runs.
  std::vector<std::string> other = kTiny;
  other[3] = "12";
  const auto refused = run_shell(join(driver(dir.path, other)));
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.output.find("belongs to another experiment: it was started with population 10, not 12"),
            std::string::npos)
      << refused.output;
}

TEST(ExperimentCli, AStoppedExperimentResumesWithoutRedoingFinishedTrials) {
  TempDir dir, ref;
  const std::vector<std::string> sizes = {"--trials",      "1", "--population", "16",
                                          "--generations", "4", "--steps",      "300"};
  const pid_t pid = spawn(driver(dir.path, sizes), dir / "driver1.txt");
  // Stop it (as Ctrl-C would) once the first trial is finished and the second has begun.
  const std::string ff_cp = dir / "feedforward-s1.lcmlog.checkpoint";
  const std::string rec_cp = dir / "recurrent-s2.lcmlog.checkpoint";
  for (int i = 0; i < 6000; ++i) {
    if (file_exists(rec_cp)) break;
    ::usleep(5000);
  }
  ASSERT_TRUE(file_exists(rec_cp)) << read_file(dir / "driver1.txt");
  kill_process(pid, SIGINT);
  EXPECT_EQ(wait_status(pid), 128 + SIGINT);
  EXPECT_NE(read_file(dir / "driver1.txt").find("Run the same command again to resume"), std::string::npos);
  ASSERT_TRUE(read_checkpoint(ff_cp).finished);
  ASSERT_FALSE(read_checkpoint(rec_cp).finished) << "the recurrent trial finished before the signal";
  const FileStamp ff = stamp(dir / "feedforward-s1.lcmlog");
  // No robozoo-evolve is left running on the folder.
  EXPECT_EQ(processes_left(dir.path + "/[r]ecurrent-s1.lcmlog"), "");

  const auto resumed = run_shell(join(driver(dir.path, sizes)));
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("1 finished (skipped), 1 to resume, 0 to start"), std::string::npos) << resumed.output;
  EXPECT_NE(resumed.output.find("recurrent-s2: resuming after generation"), std::string::npos) << resumed.output;
  EXPECT_EQ(resumed.output.find("feedforward-s1: starting"), std::string::npos);
  EXPECT_TRUE(stamp(dir / "feedforward-s1.lcmlog") == ff);
  EXPECT_TRUE(read_checkpoint(rec_cp).finished);

  // The resumed trial equals an uninterrupted run, message for message.
  const auto reference =
      run_shell(join({bin("robozoo-evolve"), "--log", ref / "rec.lcmlog", "--regime", "recurrent", "--seed", "2",
                      "--population", "16", "--generations", "4", "--steps", "300", "--workers", "1", "--quiet"}));
  ASSERT_EQ(reference.status, 0) << reference.output;
  EXPECT_EQ(first_log_difference(read_event_log(dir / "recurrent-s2.lcmlog"), read_event_log(ref / "rec.lcmlog")), "");
}

TEST(ExperimentCli, UsageErrors) {
  TempDir dir;
  const Outcome no_out = run_shell(bin("robozoo-experiment") + " --trials 2");
  EXPECT_EQ(no_out.status, 2);
  EXPECT_NE(no_out.output.find("robozoo-experiment: --out is required (see --help)"), std::string::npos)
      << no_out.output;
  const auto no_evolve = run_shell(join(driver(dir.path, kTiny)) + " --evolve /nonexistent/robozoo-evolve");
  EXPECT_EQ(no_evolve.status, 2);
  EXPECT_NE(no_evolve.output.find("cannot run /nonexistent/robozoo-evolve"), std::string::npos);
  const auto help = run_shell(bin("robozoo-experiment") + " --help");
  for (const char* flag : {"--trials", "--generations", "--population", "--out", "--workers", "--steps", "--status"})
    EXPECT_NE(help.output.find(flag), std::string::npos) << flag;
}

}  // namespace
}  // namespace robozoo
