// tools/experiment/slurm/robozoo-trials.sbatch without Slurm: SLURM_ARRAY_TASK_ID set by
// hand, mpirun on this machine. Which trial each array task runs, and a real trial
// under mpirun -np 3 that equals a local run and resumes when run again.
#include <gtest/gtest.h>

#include "evolve/io/event_log.hpp"
#include "evolve/io/log_compare.hpp"
#include "tests/support/evolve_runs.hpp"
#include "tests/support/mpirun.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

const std::string kScript = std::string(ROBOZOO_SOURCE_DIR) + "/tools/experiment/slurm/robozoo-trials.sbatch";

Outcome trial(const std::string& env, const std::string& args = "") {
  return run_shell("env " + env + " ROBOZOO_BIN='" + std::string(ROBOZOO_BIN_DIR) + "' timeout 300 bash " + kScript +
                   " " + args);
}

TEST(RobozooTrials, ArrayTasksMapToRegimeAndSeed) {
  TempDir dir;
  const std::string env = "ROBOZOO_DRY_RUN=1 ROBOZOO_RUNS=" + dir.path;
  const std::vector<std::pair<int, std::string>> cases = {
      {0, "feedforward-s1"}, {29, "feedforward-s117"}, {30, "recurrent-s2"}, {59, "recurrent-s118"}};
  for (const auto& [task, run] : cases) {
    const Outcome o = trial(env + " SLURM_ARRAY_TASK_ID=" + std::to_string(task), "--preset short");
    EXPECT_EQ(o.status, 0) << o.output;
    EXPECT_NE(o.output.find("robozoo-evolve --mpi --log " + dir.path + "/" + run + ".lcmlog"), std::string::npos)
        << o.output;
    const std::string regime = run.substr(0, run.find("-s")), seed = run.substr(run.find("-s") + 2);
    EXPECT_NE(o.output.find("--regime " + regime + " --seed " + seed + " --preset short"), std::string::npos)
        << o.output;
    EXPECT_EQ(o.output.find("--resume"), std::string::npos) << o.output;
  }
  const Outcome few = trial(env + " ROBOZOO_SEEDS=2 SLURM_ARRAY_TASK_ID=3");
  EXPECT_NE(few.output.find("recurrent-s6.lcmlog"), std::string::npos) << few.output;  // trial 2: 4 + 1 + 1
  const Outcome outside = trial(env + " SLURM_ARRAY_TASK_ID=60");
  EXPECT_EQ(outside.status, 2);
  EXPECT_NE(outside.output.find("outside 0-59"), std::string::npos) << outside.output;
  EXPECT_NE(trial("ROBOZOO_DRY_RUN=1").status, 0);  // no array task: refused
}

TEST(RobozooTrials, ATrialRunsUnderMpirunEqualsALocalRunAndResumes) {
  TempDir dir;
  std::string launcher;
  for (const auto& a : mpirun_args(3)) launcher += a + " ";
  const std::string env =
      "ROBOZOO_RUNS=" + dir.path + " ROBOZOO_SEEDS=1 SLURM_ARRAY_TASK_ID=1 ROBOZOO_MPIRUN='" + launcher + "'";
  const std::string size = "--population 24 --generations 3 --steps 300 --quiet";
  const Outcome o = trial(env, size);
  ASSERT_EQ(o.status, 0) << o.output;
  const std::string log = dir / "recurrent-s2.lcmlog";
  ASSERT_TRUE(file_exists(log)) << o.output;
  const Outcome local = run_shell(bin("robozoo-evolve") + " --workers 2 --regime recurrent --seed 2 --log '" +
                                  (dir / "local.lcmlog") + "' " + size);
  ASSERT_EQ(local.status, 0) << local.output;
  EXPECT_EQ(first_log_difference(read_event_log(log), read_event_log(dir / "local.lcmlog")), "");
  // Run again (a requeued task): it resumes, finds the run complete, changes nothing.
  const std::string before = read_file(log);
  const Outcome again = trial(env, size);
  EXPECT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("--resume"), std::string::npos) << again.output;
  EXPECT_NE(again.output.find("already complete"), std::string::npos) << again.output;
  EXPECT_EQ(read_file(log), before);
}

}  // namespace
}  // namespace robozoo
