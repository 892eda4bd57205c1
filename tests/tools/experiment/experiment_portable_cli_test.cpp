// robozoo-experiment with portable checkpoints: a trial in progress, written
// into a folder with --save-checkpoints and committed to a git repository,
// continues on a fresh clone (no log, no checkpoint) with --checkpoints, in a
// new log that begins at the checkpoint's generation, and ends with the compact
// result of the uninterrupted trial, bit for bit but for evolve_seconds
// (robozoo-evolve's wall time, which differs between any two runs). A damaged
// file, one of another configuration and one of another software version are
// refused before anything runs.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "evolve/io/event_log.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/messages/log_continuation.hpp"
#include "evolve/messages/safe_decode.hpp"
#include "evolve/record/checkpoint.hpp"
#include "evolve/run/evaluator.hpp"
#include "evolve/run/evolution.hpp"
#include "study/experiment/portable_checkpoint.hpp"
#include "tests/support/evolve_runs.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;
namespace fs = std::filesystem;

constexpr int kGenerations = 5;
constexpr int kStopAt = 2;  // the portable checkpoint is written after generations 0 and 1

std::vector<std::string> driver(const std::string& out, const std::vector<std::string>& extra = {},
                                int population = 12) {
  std::vector<std::string> a = {bin("robozoo-experiment"),
                                "--out",
                                out,
                                "--workers",
                                "1",
                                "--progress-interval",
                                "0",
                                "--trials",
                                "1",
                                "--arms",
                                "recurrent",
                                "--population",
                                std::to_string(population),
                                "--steps",
                                "300",
                                "--generations",
                                std::to_string(kGenerations)};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

/// Trial recurrent-s2 of the experiment above, stopped after kStopAt generations (in-process, as
/// robozoo-evolve runs it: the same configuration, run id and log).
void run_until_stopped(const std::string& out) {
  fs::create_directories(out);
  RunConfig c;
  c.regime = Regime::Recurrent;
  c.seed = 2;
  c.neat.population = 12;
  c.generations = kGenerations;
  c.eval.sim.steps = 300;
  InProcessEvaluator evaluator(c.eval);
  EvolveOptions o;
  o.log_path = out + "/recurrent-s2.lcmlog";
  o.run_id = "recurrent-s2";
  Evolution evo(c, o, evaluator);
  for (int g = 0; g < kStopAt; ++g) ASSERT_TRUE(evo.step());
}

/// The compact result's JSON without evolve_seconds (wall time), as text.
std::string without_wall_time(const std::string& path) {
  nlohmann::json j = nlohmann::json::parse(read_file(path));
  EXPECT_TRUE(j.at("evolve_seconds").is_number()) << path;
  j.erase("evolve_seconds");
  return j.dump();
}

TEST(ExperimentPortableCli, ATrialContinuedOnAFreshCloneEndsAsTheUninterruptedOne) {
  TempDir ref, here, repo, clone, fresh;
  const auto whole = run_shell(join(driver(ref.path)));
  ASSERT_EQ(whole.status, 0) << whole.output;

  run_until_stopped(here.path);
  const auto saved = run_shell("cd '" + repo.path + "' && git init -q . && " +
                               join(driver(here.path, {"--save-checkpoints", repo / "checkpoints"})));
  ASSERT_EQ(saved.status, 0) << saved.output;
  EXPECT_NE(saved.output.find("recurrent-s2: generation 2"), std::string::npos) << saved.output;
  const std::string file = "checkpoints/recurrent-s2.portable-checkpoint";
  ASSERT_TRUE(file_exists(repo / file));
  const auto committed = run_shell("cd '" + repo.path + "' && git add " + file +
                                   " && git -c user.name=t -c user.email=t@t commit -q -m t" + " && git clone -q '" +
                                   repo.path + "' '" + clone.path + "/r'");
  ASSERT_EQ(committed.status, 0) << committed.output;

  // The fresh machine: only the clone.
  const std::string out = fresh / "exp";
  const auto continued = run_shell(join(driver(out, {"--checkpoints", clone / "r/checkpoints"})));
  ASSERT_EQ(continued.status, 0) << continued.output;
  EXPECT_NE(continued.output.find("0 finished (skipped), 1 to resume, 0 to start"), std::string::npos)
      << continued.output;
  EXPECT_NE(continued.output.find("continues from the portable checkpoint"), std::string::npos) << continued.output;
  EXPECT_EQ(without_wall_time(out + "/results/recurrent-s2.results.json"),
            without_wall_time(ref / "results/recurrent-s2.results.json"));

  // The new log begins at generation 2, and every run message says so.
  const LogContents log = read_event_log(out + "/recurrent-s2.lcmlog");
  int runs = 0, first_generation = -1;
  for (const auto& r : log.records) {
    if (r.channel == kChannelRun) {
      run_t m;
      ASSERT_TRUE(safe_decode(r.data.data(), r.data.size(), m));
      const auto c = split_run_config(m.config_json).continues;
      ASSERT_TRUE(c.has_value());
      EXPECT_EQ(c->from_generation, kStopAt);
      EXPECT_EQ(c->evaluations_before, 12 * kStopAt);
      ++runs;
    } else if (r.channel == kChannelGeneration && first_generation < 0) {
      generation_t m;
      ASSERT_TRUE(safe_decode(r.data.data(), r.data.size(), m));
      first_generation = m.generation;
    }
  }
  EXPECT_EQ(runs, kGenerations - kStopAt);
  EXPECT_EQ(first_generation, kStopAt);
  // robozoo-replay checks the continued log as the rest of a run.
  const auto check = run_shell(join({bin("robozoo-replay"), "check", out + "/recurrent-s2.lcmlog"}));
  EXPECT_EQ(check.status, 0) << check.output;

  // Finished: its portable checkpoint is no longer needed.
  const auto cleaned = run_shell(join(driver(out, {"--save-checkpoints", clone / "r/checkpoints"})));
  EXPECT_EQ(cleaned.status, 0) << cleaned.output;
  EXPECT_FALSE(file_exists(clone / ("r/" + file))) << cleaned.output;
}

TEST(ExperimentPortableCli, DamagedOtherConfigurationAndOtherVersionAreRefused) {
  TempDir here, dir, fresh;
  run_until_stopped(here.path);
  const std::string folder = dir / "checkpoints";
  ASSERT_EQ(run_shell(join(driver(here.path, {"--save-checkpoints", folder}))).status, 0);
  const std::string file = folder + "/recurrent-s2.portable-checkpoint";
  const std::string good = read_file(file);

  // Damaged: one bit of the compressed bytes.
  std::string bad = good;
  bad[kPortableHeaderBytes + 40] ^= 0x10;
  write_file_atomic(file, bad);
  auto r = run_shell(join(driver(fresh / "a", {"--checkpoints", folder})));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(file + ": not a usable portable checkpoint: its compressed bytes are damaged"),
            std::string::npos)
      << r.output;
  // Cut short.
  write_file_atomic(file, good.substr(0, good.size() - 7));
  r = run_shell(join(driver(fresh / "a", {"--checkpoints", folder})));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("cut short"), std::string::npos) << r.output;
  EXPECT_FALSE(file_exists(fresh / "a/recurrent-s2.lcmlog.checkpoint"));

  // Another configuration: population 12 is not 14.
  write_file_atomic(file, good);
  r = run_shell(join(driver(fresh / "b", {"--checkpoints", folder}, 14)));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(file + " belongs to another experiment: it was started with population 12, not 14"),
            std::string::npos)
      << r.output;

  // Another software version: refused, even with --force (the result would be two versions' run).
  PortableCheckpoint p = decode_portable_checkpoint(reinterpret_cast<const uint8_t*>(good.data()), good.size(), file);
  nlohmann::json c = nlohmann::json::parse(p.checkpoint_text), res = nlohmann::json::parse(p.results_text);
  c["software_version"] = "0000000older";
  res["run"]["software_version"] = "0000000older";
  p.checkpoint_text = c.dump();
  p.results_text = res.dump();
  const std::vector<uint8_t> older = encode_portable_checkpoint(p);
  write_file_atomic(file, std::string(older.begin(), older.end()));
  r = run_shell(join(driver(fresh / "c", {"--checkpoints", folder})));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(file + " was written by robozoo 0000000older, this is robozoo " + software_version()),
            std::string::npos)
      << r.output;
  r = run_shell(join(driver(fresh / "c", {"--checkpoints", folder, "--force"})));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--force does not apply here"), std::string::npos) << r.output;
  EXPECT_FALSE(file_exists(fresh / "c/recurrent-s2.lcmlog")) << r.output;
}

}  // namespace
}  // namespace robozoo
