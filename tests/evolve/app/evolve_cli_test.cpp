// robozoo-evolve as a user runs it: determinism across worker counts, kill -9
// and resume, a worker killed on purpose, live publishing recorded by LCM's own
// lcm-logger inside a private network namespace, bad configuration.
#include <fcntl.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "evolve/io/event_log.hpp"
#include "evolve/io/log_compare.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"
#include "evolve/neat/population.hpp"
#include "evolve/record/checkpoint.hpp"
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

TEST(EvolveCli, PrintConfigShowsTheAuthorsDefaultsAndExplainsThem) {
  const auto o = run_shell(bin("robozoo-evolve") + " --print-config");
  ASSERT_EQ(o.status, 0) << o.output;
  const nlohmann::json j = nlohmann::json::parse(o.output);
  EXPECT_EQ(j.at("growth").at("bias_input"), 0.3);
  EXPECT_EQ(j.at("growth").at("weight_mapping"), "rescaled");
  EXPECT_EQ(j.at("neat").at("add_node_innovations"), "fresh");
  const auto e = run_shell(bin("robozoo-evolve") + " --print-config --explain --set growth.bias_input=1.0");
  ASSERT_EQ(e.status, 0) << e.output;
  EXPECT_NE(e.output.find("growth.bias_input = 1.0  # value of the CPPN's constant bias input (dimensionless)"),
            std::string::npos)
      << e.output;
  EXPECT_NE(e.output.find("growth.weight_mapping = \"rescaled\"  # how a CPPN weight output"), std::string::npos);
  EXPECT_NE(e.output.find("neat.add_node_innovations = \"fresh\"  # numbers of an add-node split"), std::string::npos);
  EXPECT_NE(e.output.find("sim.dt = 0.01  # physics step (s)"), std::string::npos);
  const auto bad = run_shell(bin("robozoo-evolve") + " --explain");
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("--explain only applies to --print-config"), std::string::npos) << bad.output;
}

TEST(EvolveCli, OneAndTwoWorkersGiveIdenticalLogs) {
  TempDir dir;
  ASSERT_EQ(run_evolve(dir / "w1.lcmlog", 1), 0);
  ASSERT_EQ(run_evolve(dir / "w2.lcmlog", 2), 0);
  const auto a = read_event_log(dir / "w1.lcmlog"), b = read_event_log(dir / "w2.lcmlog");
  EXPECT_EQ(first_log_difference(a, b), "");
  // The log holds, per generation, the run, the generation, the champion's genome and morphology.
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

// Decodes every message of `channel` in `log` as T (failing the test on one that does not).
template <class T>
std::vector<T> decode_all(const LogContents& log, const std::string& channel) {
  std::vector<T> out;
  for (const auto& r : log.records) {
    if (r.channel != channel) continue;
    T m;
    std::string why;
    EXPECT_TRUE(safe_decode(r.data.data(), r.data.size(), m, &why)) << why;
    out.push_back(m);
  }
  return out;
}

TEST(EvolveCli, LogsCarryTheRegimesTopologyTheVersionAndTruthfulFigures) {
  TempDir dir;
  ASSERT_EQ(run_evolve(dir / "ff.lcmlog", 2, {"--regime", "feedforward", "--publish-all"}), 0);
  ASSERT_EQ(run_evolve(dir / "rec.lcmlog", 2, {"--regime", "recurrent", "--publish-all"}), 0);
  const auto ff = read_event_log(dir / "ff.lcmlog"), rec = read_event_log(dir / "rec.lcmlog");
  NeatParams p;
  // Every logged genome of the control regime holds forward links only; every
  // generation-0 genome of the experimental regime holds the 209 start links.
  for (const auto& m : decode_all<cppn_genome_t>(ff, kChannelGenome)) {
    const Genome g = genome_from_message(m, robot_layout());
    EXPECT_NO_THROW(validate_regime_links(g, Regime::FeedForward, p)) << "genome " << g.id;
    EXPECT_EQ(count_recurrent_links(g), 0);
    if (m.generation == 0) {
      EXPECT_EQ(g.links.size(), 99u);
    }
  }
  int gen0 = 0;
  for (const auto& m : decode_all<cppn_genome_t>(rec, kChannelGenome)) {
    const Genome g = genome_from_message(m, robot_layout());
    EXPECT_NO_THROW(validate_regime_links(g, Regime::Recurrent, p));
    if (m.generation != 0) continue;
    ++gen0;
    EXPECT_EQ(g.links.size(), 209u);
    EXPECT_EQ(count_recurrent_links(g), 110);
  }
  EXPECT_EQ(gen0, 24);
  // The version is the program's, the threshold the one each generation was speciated with.
  const auto version = run_shell(bin("robozoo-evolve") + " --version");
  const auto runs = decode_all<run_t>(rec, kChannelRun);
  ASSERT_FALSE(runs.empty());
  EXPECT_NE(version.output.find("git " + runs.front().software_version), std::string::npos) << version.output;
  EXPECT_EQ(runs.front().software_version, software_version());
  const auto gens = decode_all<generation_t>(rec, kChannelGeneration);
  ASSERT_EQ(gens.size(), 4u);
  EXPECT_EQ(gens[0].compatibility_threshold, 6.0);
  for (size_t g = 1; g < gens.size(); ++g) {
    const double step = gens[g].compatibility_threshold - gens[g - 1].compatibility_threshold;
    // The threshold moves by 0.3 after each speciation, towards 8 species.
    EXPECT_TRUE(std::fabs(std::fabs(step) - 0.3) < 1e-12 || step == 0.0) << "generation " << g << ": " << step;
    EXPECT_EQ(step > 0, gens[g - 1].num_species > 8) << "generation " << g;
  }
  for (const auto& g : gens) {
    EXPECT_GE(g.generation_seconds, g.eval_seconds);
    EXPECT_EQ(g.n_not_simulated + g.n_completed + g.n_stopped_early + g.n_accel_fault + g.n_rolling_contact +
                  g.n_rolling_spin,
              24);
  }
}

TEST(EvolveCli, ResumeRefusesAnotherVersionsCheckpointUnlessForced) {
  TempDir dir;
  const std::string log = dir / "v.lcmlog";
  const pid_t pid = spawn(evolve_args(log, 1, {}, kSmall), dir / "out.txt");
  for (int i = 0; i < 2000 && !file_exists(log + ".checkpoint"); ++i) ::usleep(10000);
  ASSERT_TRUE(file_exists(log + ".checkpoint"));
  kill_process(pid, SIGKILL);
  wait_status(pid);
  Checkpoint c = read_checkpoint(log + ".checkpoint");
  c.software_version = "0123456789ab";
  write_checkpoint(log + ".checkpoint", c);
  const auto refused = run_shell(join(evolve_args(log, 1, {"--resume"}, kSmall)));
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("written by robozoo 0123456789ab"), std::string::npos) << refused.output;
  EXPECT_NE(refused.output.find("--force"), std::string::npos) << refused.output;
  const auto forced = run_shell(join(evolve_args(log, 1, {"--resume", "--force"}, kSmall)));
  EXPECT_EQ(forced.status, 0) << forced.output;
  EXPECT_TRUE(read_checkpoint(log + ".checkpoint").finished);
  const auto alone = run_shell(join(evolve_args(dir / "other.lcmlog", 1, {"--force"}, kSmall)));
  EXPECT_EQ(alone.status, 2) << alone.output;
}

TEST(EvolveCli, KillNineThenResumeEqualsUninterruptedRun) {
  TempDir dir;
  ASSERT_EQ(run_evolve(dir / "whole.lcmlog", 2, {}, kLonger), 0);
  const std::string log = dir / "cut.lcmlog";
  bool resumed_later = false;  // one resume at least took over after generation 0
  // Kill at several moments: at start, early, and mid-run (once the checkpoint holds
  // a finished generation: a fixed 800 ms was still inside generation 0 under the
  // sanitizers on a loaded machine, and then no kill proved a resume); then once
  // more while resuming.
  for (int delay_ms : {20, 300, -1}) {
    const pid_t pid = spawn(evolve_args(log, 2, {}, kLonger), dir / "out.txt");
    if (delay_ms >= 0) {
      std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    } else {
      bool past_zero = false;
      for (int i = 0; i < 12000 && !past_zero; ++i) {
        ::usleep(10000);
        try {
          past_zero = file_exists(log + ".checkpoint") && read_checkpoint(log + ".checkpoint").evaluations > 0;
        } catch (const std::exception&) {
          // written atomically: only a missing file, keep waiting
        }
      }
      EXPECT_TRUE(past_zero) << "no checkpoint past generation 0 within 120 s";
    }
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
    // The resume must be a resume: it says where it took the run over (even with
    // --quiet), that is where the checkpoint was, and it evaluates only the rest.
    const bool checkpointed = file_exists(log + ".checkpoint");
    const int64_t done_before = checkpointed ? read_checkpoint(log + ".checkpoint").evaluations : 0;
    const auto o = run_shell(join(evolve_args(log, 2, {"--resume"}, kLonger)));
    ASSERT_EQ(o.status, 0) << o.output;
    const int64_t whole = 8 * 40;
    if (checkpointed) {
      const std::string line = "resumed run feedforward-s7 at generation " + std::to_string(done_before / 40) +
                               " of 8 (" + std::to_string(done_before) + " evaluations before)";
      EXPECT_NE(o.output.find(line), std::string::npos) << o.output;
      resumed_later = resumed_later || done_before > 0;
    } else {
      EXPECT_NE(o.output.find("starts at generation 0"), std::string::npos) << o.output;
    }
    EXPECT_NE(o.output.find(std::to_string(whole - done_before) + " evaluations in this process (" +
                            std::to_string(whole) + " in the run)"),
              std::string::npos)
        << o.output;
    EXPECT_EQ(first_log_difference(read_event_log(dir / "whole.lcmlog"), read_event_log(log)), "")
        << "killed after " << delay_ms << " ms";
    std::remove(log.c_str());
    std::remove((log + ".checkpoint").c_str());
  }
  EXPECT_TRUE(resumed_later) << "no kill left a checkpoint past generation 0: the test proved no resume";
}

TEST(EvolveCli, ResumeUsesTheCheckpointsConfigurationNotTheCommandLines) {
  // Killed early, then resumed with no size flags at all: the workers must
  // evaluate with the run's own settings (--steps 1000 etc.), not the defaults.
  TempDir dir;
  ASSERT_EQ(run_evolve(dir / "whole.lcmlog", 2, {}, kLonger), 0);
  const std::string log = dir / "cut.lcmlog";
  const pid_t pid = spawn(evolve_args(log, 2, {}, kLonger), dir / "out.txt");
  // Killed once its first checkpoint exists, not after a fixed time: a run slower to
  // start (a sanitized build, a loaded machine) killed before its first checkpoint
  // left nothing to resume, and --resume then ran a new run of the default size.
  for (int i = 0; i < 6000 && !file_exists(log + ".checkpoint"); ++i) ::usleep(10000);
  ASSERT_TRUE(file_exists(log + ".checkpoint")) << read_file(dir / "out.txt");
  kill_process(pid, SIGKILL);
  EXPECT_EQ(wait_status(pid), 128 + SIGKILL) << "the run ended before the kill";
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_TRUE(file_exists(log + ".checkpoint"));
  const int64_t done_before = read_checkpoint(log + ".checkpoint").evaluations;
  const auto o = run_shell(join({bin("robozoo-evolve"), "--log", log, "--resume", "--workers", "2", "--quiet"}));
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("resumed run feedforward-s7 at generation " + std::to_string(done_before / 40)),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find(std::to_string(320 - done_before) + " evaluations in this process"), std::string::npos)
      << o.output;
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
