// robozoo-evolve --mpi as a user runs it under Open MPI's mpirun on one machine:
// the log equals --workers 1 and --workers 2 message by message; a worker rank
// killed mid-run (kill -9) or a cancelled job ends the job with a line that says
// how to resume, the checkpoint intact; resuming locally or under another number
// of ranks gives the uninterrupted run's log.
#include <gtest/gtest.h>

#include <algorithm>

#include "evolve/io/event_log.hpp"
#include "evolve/io/log_compare.hpp"
#include "evolve/record/checkpoint.hpp"
#include "tests/support/evolve_runs.hpp"
#include "tests/support/mpirun.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

/// robozoo-evolve --mpi under mpirun -np `np`; `workers` is passed too (and ignored).
std::vector<std::string> mpi_evolve_args(int np, const std::string& log, std::vector<std::string> extra = {},
                                         const std::vector<std::string>& size = kSmall) {
  extra.push_back("--mpi");
  return under_mpirun(np, evolve_args(log, 1, extra, size));
}

Outcome run_logged(const std::vector<std::string>& argv) { return run_shell("timeout 300 " + join(argv)); }

std::string log_difference(const std::string& a, const std::string& b) {
  return first_log_difference(read_event_log(a), read_event_log(b));
}

/// Generations finished according to a run's checkpoint (-1: none readable yet).
int generations_done(const std::string& log) {
  if (!file_exists(log + ".checkpoint")) return -1;
  try {
    return read_checkpoint(log + ".checkpoint").population.generation;
  } catch (const std::exception&) {
    return -1;
  }
}

/// Starts the run under mpirun, waits until `after` generations are checkpointed,
/// then does `stop` to the job; returns mpirun's exit status and output.
/// `own_stderr`: each rank's stderr goes to `out`.rankN (a shell redirects it,
/// then execs the program) and rank 0's is added to the output. For mpirun sent
/// SIGTERM itself: it sometimes exits without relaying what rank 0 wrote
/// (measured: CancelledJobThenResumedOnOtherRankCounts got no output at all from
/// mpirun in 1 run of 5-7, while rank 0 wrote its line to a file in 15 of 15).
Outcome interrupt(std::vector<std::string> argv, const std::string& log, int after,
                  const std::function<void(pid_t mpirun)>& stop, const std::string& out, bool own_stderr = false) {
  if (own_stderr) {
    const auto program = std::find(argv.begin(), argv.end(), bin("robozoo-evolve"));
    argv.insert(program, {"/bin/sh", "-c", "exec \"$0\" \"$@\" 2>>'" + out + ".rank'\"$OMPI_COMM_WORLD_RANK\""});
  }
  const pid_t mpirun = spawn(argv, out);
  for (int i = 0; i < 3000 && generations_done(log) < after; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  stop(mpirun);
  Outcome o;
  o.status = wait_status(mpirun);
  o.output = read_file(out);
  if (own_stderr) o.output += "\n[rank 0's stderr]\n" + (file_exists(out + ".rank0") ? read_file(out + ".rank0") : "");
  return o;
}

/// The resumed run said (even with --quiet) that it took the run over at
/// `generation` and evaluated only the remaining generations (kLonger: 8 x 40).
void expect_resumed_at(const Outcome& o, int generation) {
  ASSERT_GT(generation, 0) << "a resume at generation 0 cannot be told from a restart";
  EXPECT_NE(o.output.find("resumed run feedforward-s7 at generation " + std::to_string(generation) + " of 8"),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find(std::to_string((8 - generation) * 40) + " evaluations in this process (320 in the run)"),
            std::string::npos)
      << o.output;
}

void expect_resume_line(const Outcome& o, const std::string& log) {
  EXPECT_NE(o.output.find("the run can be resumed with: robozoo-evolve --log " + log + " --resume"), std::string::npos)
      << "mpirun's status " << o.status << ", checkpoint at generation " << generations_done(log) << ", output:\n"
      << o.output;
  EXPECT_NE(o.status, 0) << o.output;
}

TEST(EvolveMpi, LogEqualsOneAndTwoLocalWorkers) {
  TempDir dir;
  const Outcome o = run_logged(mpi_evolve_args(3, dir / "mpi.lcmlog", {"--lcm-url", "memq://"}));
  ASSERT_EQ(o.status, 0) << o.output;
  ASSERT_EQ(run_logged(evolve_args(dir / "w1.lcmlog", 1)).status, 0);
  ASSERT_EQ(run_logged(evolve_args(dir / "w2.lcmlog", 2)).status, 0);
  EXPECT_EQ(log_difference(dir / "mpi.lcmlog", dir / "w2.lcmlog"), "");
  EXPECT_EQ(log_difference(dir / "mpi.lcmlog", dir / "w1.lcmlog"), "");
  const auto log = read_event_log(dir / "mpi.lcmlog");
  EXPECT_EQ(count_channel(log, "ROBOZOO_GENERATION"), 4u);
  EXPECT_GT(count_channel(log, "ROBOZOO_POSE"), 0u);  // robots were simulated, champions re-simulated
}

TEST(EvolveMpi, RankKilledMidRunThenResumedLocally) {
  TempDir dir;
  ASSERT_EQ(run_logged(evolve_args(dir / "whole.lcmlog", 2, {}, kLonger)).status, 0);
  const std::string log = dir / "cut.lcmlog";
  pid_t victim = -1;
  const Outcome o = interrupt(
      mpi_evolve_args(3, log, {}, kLonger), log, 2,
      [&](pid_t mpirun) {
        victim = rank_pid(mpirun, 2);
        kill_process(victim, SIGKILL);
      },
      dir / "out.txt");
  ASSERT_GT(victim, 0) << "rank 2 not found among mpirun's children\n" << o.output;
  {
    SCOPED_TRACE("first interrupt");
    expect_resume_line(o, log);
  }
  EXPECT_NE(o.output.find("an MPI rank died or the job was cancelled"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("cut.lcmlog.checkpoint is intact after "), std::string::npos) << o.output;
  // The checkpoint reads back, mid-run.
  const Checkpoint c = read_checkpoint(log + ".checkpoint");
  EXPECT_FALSE(c.finished);
  EXPECT_GE(c.population.generation, 2);
  EXPECT_LT(c.population.generation, 8);
  const Outcome resumed = run_logged(evolve_args(log, 2, {"--resume"}, kLonger));
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expect_resumed_at(resumed, c.population.generation);
  EXPECT_EQ(log_difference(dir / "whole.lcmlog", log), "");
}

TEST(EvolveMpi, CancelledJobThenResumedOnOtherRankCounts) {
  TempDir dir;
  ASSERT_EQ(run_logged(evolve_args(dir / "whole.lcmlog", 2, {}, kLonger)).status, 0);
  const std::string log = dir / "cut.lcmlog";
  // As Slurm's scancel does: SIGTERM to mpirun, which stops every rank.
  const Outcome o = interrupt(
      mpi_evolve_args(3, log, {}, kLonger), log, 1, [](pid_t mpirun) { kill_process(mpirun, SIGTERM); },
      dir / "out.txt", true);
  {
    SCOPED_TRACE("first interrupt");
    expect_resume_line(o, log);
  }
  EXPECT_FALSE(read_checkpoint(log + ".checkpoint").finished);
  // Resume under 2 ranks, kill a worker rank again, finish under 4 ranks.
  // Interrupt the resumed job one generation after where it resumes, so that it is
  // surely still running (a fixed generation may already be behind it).
  const int resumed_at = generations_done(log);
  ASSERT_LT(resumed_at, 7) << "the cancelled job got too far for a second interruption";
  const Outcome again = interrupt(
      mpi_evolve_args(2, log, {"--resume"}, kLonger), log, resumed_at + 1,
      [](pid_t mpirun) { kill_process(rank_pid(mpirun, 1), SIGKILL); }, dir / "out2.txt");
  {
    SCOPED_TRACE("second interrupt: a worker rank killed");
    expect_resume_line(again, log);
  }
  const int last_resume = generations_done(log);
  const Outcome resumed = run_logged(mpi_evolve_args(4, log, {"--resume"}, kLonger));
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expect_resumed_at(resumed, last_resume);
  EXPECT_EQ(log_difference(dir / "whole.lcmlog", log), "");
}

TEST(EvolveMpi, RefusesAJobOfOneRank) {
  TempDir dir;
  const Outcome o = run_logged(mpi_evolve_args(1, dir / "one.lcmlog"));
  EXPECT_NE(o.status, 0);
  EXPECT_NE(o.output.find("--mpi needs at least 2 ranks"), std::string::npos) << o.output;
  EXPECT_FALSE(file_exists(dir / "one.lcmlog"));
}

TEST(EvolveMpi, BadConfigurationEndsEveryRank) {
  TempDir dir;
  const Outcome o = run_logged(mpi_evolve_args(3, dir / "bad.lcmlog", {"--config", dir / "missing.toml"}));
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("cannot read"), std::string::npos) << o.output;
  // Only rank 0 speaks.
  size_t said = 0;
  for (size_t p = 0; (p = o.output.find("robozoo-evolve:", p)) != std::string::npos; ++p) ++said;
  EXPECT_EQ(said, 1u) << o.output;
  EXPECT_FALSE(file_exists(dir / "bad.lcmlog"));
}

}  // namespace
}  // namespace robozoo
