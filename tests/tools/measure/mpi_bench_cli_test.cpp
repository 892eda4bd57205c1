// robozoo-mpi-bench --resume: measures the next generations of a logged,
// unfinished run (robots as evolution made them) on a copy, leaving the run's own
// files untouched; refuses a finished run and the flags that would set another run.
#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>
#include <signal.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "evolve/record/checkpoint.hpp"
#include "tests/support/mpirun.hpp"
#include "tests/support/evolve_runs.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

const std::vector<std::string> kSizes = {"--population", "10", "--steps", "200"};

/// A run of 1000 generations stopped once its checkpoint holds two: unfinished.
void write_unfinished_run(const std::string& log, const TempDir& dir) {
  std::vector<std::string> a = {bin("robozoo-evolve"), "--log", log,       "--regime",      "recurrent", "--seed", "4",
                                "--workers",           "1",     "--quiet", "--generations", "1000"};
  a.insert(a.end(), kSizes.begin(), kSizes.end());
  const pid_t pid = spawn(a, dir / "evolve.txt");
  bool two = false;
  for (int i = 0; i < 12000 && !two; ++i) {
    ::usleep(10000);
    try {
      two = file_exists(log + ".checkpoint") && read_checkpoint(log + ".checkpoint").evaluations >= 20;
    } catch (const std::exception&) {
      // written atomically, so only a missing file: keep waiting
    }
  }
  kill_process(pid, SIGKILL);
  ASSERT_TRUE(two) << read_file(dir / "evolve.txt");
}

TEST(MpiBenchCli, ResumeMeasuresTheNextGenerationsOfALoggedRunOnACopy) {
  TempDir dir;
  const std::string log = dir / "run.lcmlog";
  write_unfinished_run(log, dir);
  const Checkpoint before = read_checkpoint(log + ".checkpoint");
  const int at = static_cast<int>(before.evaluations / 10);
  const std::string log_bytes = read_file(log), checkpoint_bytes = read_file(log + ".checkpoint");

  const auto r = run_shell(join(under_mpirun(2, {bin("robozoo-mpi-bench"), "--resume", log, "--generations", "2",
                                                 "--project", "4", "--json", dir / "b.json"})));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("generations " + std::to_string(at) + "-" + std::to_string(at + 1) + " of " + log),
            std::string::npos)
      << r.output;
  std::ifstream in(dir / "b.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["setup"]["resumed_at_generation"], at);
  EXPECT_EQ(j["setup"]["generations"], 2);
  EXPECT_EQ(j["setup"]["population"], 10);  // the run's own settings
  EXPECT_EQ(j["setup"]["steps"], 200);
  EXPECT_EQ(j["setup"]["regime"], "recurrent");
  EXPECT_EQ(j["jobs"]["count"], 20);
  EXPECT_GT(j["rank0_per_generation"]["serial_seconds"].get<double>(), 0.0);
  EXPECT_GT(j["rank0_per_generation"]["serial_share"].get<double>(), 0.0);
  EXPECT_LT(j["rank0_per_generation"]["serial_share"].get<double>(), 1.0);
  // The run itself is untouched: it can still be resumed where it stopped.
  EXPECT_EQ(read_file(log), log_bytes);
  EXPECT_EQ(read_file(log + ".checkpoint"), checkpoint_bytes);
}

TEST(MpiBenchCli, ResumeRefusesAFinishedRunAndFlagsOfAnotherRun) {
  TempDir dir;
  const std::string log = dir / "done.lcmlog";
  std::vector<std::string> a = {bin("robozoo-evolve"), "--log", log, "--workers", "1", "--quiet", "--generations", "1"};
  a.insert(a.end(), kSizes.begin(), kSizes.end());
  ASSERT_EQ(run_shell(join(a)).status, 0);
  const auto finished = run_shell(join(under_mpirun(2, {bin("robozoo-mpi-bench"), "--resume", log})));
  EXPECT_NE(finished.status, 0);
  EXPECT_NE(finished.output.find("finished run"), std::string::npos) << finished.output;

  const auto seed = run_shell(join(under_mpirun(2, {bin("robozoo-mpi-bench"), "--resume", log, "--seed", "3"})));
  EXPECT_NE(seed.status, 0);
  EXPECT_NE(seed.output.find("excludes"), std::string::npos) << seed.output;
  const auto missing = run_shell(join(under_mpirun(2, {bin("robozoo-mpi-bench"), "--resume", dir / "none.lcmlog"})));
  EXPECT_NE(missing.status, 0);
  EXPECT_NE(missing.output.find("no file"), std::string::npos) << missing.output;
  // --log names where the copy goes: an existing file there is not overwritten.
  const std::string before = read_file(log);
  const auto onto = run_shell(join(under_mpirun(2, {bin("robozoo-mpi-bench"), "--resume", log, "--log", log})));
  EXPECT_NE(onto.status, 0);
  EXPECT_NE(onto.output.find("exists already"), std::string::npos) << onto.output;
  EXPECT_EQ(read_file(log), before);
}

}  // namespace
}  // namespace robozoo
