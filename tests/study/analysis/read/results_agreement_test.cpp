// Agreement of two compact results of one trial: a real run of 3 generations
// and the same seed run for 5 agree over the first 3, and a change of one bit,
// one setting or one champion is found and named.
#include "study/analysis/read/results_agreement.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "study/analysis/read/log_results.hpp"
#include "tests/support/small_run.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using robozoo::testing::TempDir;

RunResults evolve_results(const TempDir& dir, int generations, int64_t seed = 7) {
  robozoo::testing::evolve_small_run(dir / "recurrent-s7.lcmlog", "recurrent-s7", generations, seed);
  return results_from_log(dir / "recurrent-s7.lcmlog");
}

struct Runs {
  TempDir a, b;
  RunResults short_run = evolve_results(a, 3);
  RunResults long_run = evolve_results(b, 5);
};

const Runs& runs() {
  static const Runs* r = new Runs();  // evolved once for the whole file
  return *r;
}

TEST(ResultsAgreement, AShortRunAgreesWithALongerRunOfTheSameSeedOverItsGenerations) {
  const Runs& r = runs();
  ASSERT_EQ(r.short_run.run.generations.size(), 3u);
  ASSERT_EQ(r.long_run.run.generations.size(), 5u);
  EXPECT_EQ(first_disagreement(r.short_run, r.long_run), std::nullopt);
  EXPECT_EQ(first_disagreement(r.long_run, r.short_run), std::nullopt);
  EXPECT_EQ(first_disagreement(r.long_run, r.long_run), std::nullopt);
}

TEST(ResultsAgreement, TheLastBitOfOneGenerationsMeanIsADifference) {
  const Runs& r = runs();
  RunResults changed = r.long_run;
  double& m = changed.run.generations[2].mean_fitness;
  m = std::nextafter(m, 1e300);
  const auto d = first_disagreement(r.short_run, changed);
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(d->rfind("generation 2: mean_fitness: ", 0), 0u) << *d;
  // Generation 3 is beyond the short run: a change there is no disagreement.
  RunResults later = r.long_run;
  later.run.generations[3].mean_fitness += 1;
  EXPECT_EQ(first_disagreement(r.short_run, later), std::nullopt);
}

TEST(ResultsAgreement, OutcomeCountsAndChampionsAreCompared) {
  const Runs& r = runs();
  RunResults changed = r.long_run;
  changed.run.generations[1].outcomes[1] += 1;
  auto d = first_disagreement(r.short_run, changed);
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(d->rfind("generation 1: outcomes: ", 0), 0u) << *d;

  ASSERT_FALSE(r.long_run.run.champions.empty());
  changed = r.long_run;
  changed.run.champions[0].genome.d_term += 1e-9;
  d = first_disagreement(r.short_run, changed);
  ASSERT_TRUE(d.has_value());
  const std::string where =
      "champion of generation " + std::to_string(r.long_run.run.champions[0].generation) + ": d_term: ";
  EXPECT_EQ(d->rfind(where, 0), 0u) << *d;

  changed = r.long_run;
  changed.run.champions.erase(changed.run.champions.begin());
  d = first_disagreement(r.short_run, changed);
  ASSERT_TRUE(d.has_value());
  EXPECT_NE(d->find("champion"), std::string::npos) << *d;
}

TEST(ResultsAgreement, TheRunsIdentityAndSettingsOtherThanTheGenerationsMustBeEqual) {
  const Runs& r = runs();
  RunResults changed = r.long_run;
  changed.run.seed = 8;
  auto d = first_disagreement(r.short_run, changed);
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(*d, "run.seed: 7 != 8");

  changed = r.long_run;
  changed.run.software_version = "0123456789ab";
  d = first_disagreement(r.short_run, changed);
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(d->rfind("run.software_version: ", 0), 0u) << *d;

  changed = r.long_run;
  const std::string from = "\"max_spheres\":50";
  const auto at = changed.run.config_json.find(from);
  ASSERT_NE(at, std::string::npos) << changed.run.config_json.substr(0, 400);
  changed.run.config_json.replace(at, from.size(), "\"max_spheres\":49");
  d = first_disagreement(r.short_run, changed);
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(*d, "run.config/growth/max_spheres: 50 != 49");
}

TEST(ResultsAgreement, AnotherSeedDiffersInItsGenerationsToo) {
  const Runs& r = runs();
  TempDir dir;
  RunResults other = evolve_results(dir, 3, 8);
  // Pretend it is the same trial: its numbers still give it away.
  other.run.seed = 7;
  nlohmann::json config = nlohmann::json::parse(other.run.config_json);
  config["seed"] = 7;
  other.run.config_json = config.dump();
  const auto d = first_disagreement(r.short_run, other);
  ASSERT_TRUE(d.has_value());
  EXPECT_EQ(d->rfind("generation 0: ", 0), 0u) << *d;
}

TEST(ResultsAgreement, FoldersAreComparedTrialByTrial) {
  const Runs& r = runs();
  TempDir a, b;
  write_run_results(a / "recurrent-s7.results.json", r.short_run);
  write_run_results(b / "recurrent-s7.results.json", r.long_run);
  write_run_results(a / "feedforward-s1.results.json", r.short_run);  // only in a
  FolderAgreement f = compare_results_folders(a.path, b.path);
  ASSERT_EQ(f.trials.size(), 1u);
  EXPECT_EQ(f.trials[0].trial, "recurrent-s7");
  EXPECT_EQ(f.trials[0].generations_a, 3u);
  EXPECT_EQ(f.trials[0].generations_b, 5u);
  EXPECT_EQ(f.only_a, std::vector<std::string>{"feedforward-s1"});
  EXPECT_TRUE(f.only_b.empty());
  EXPECT_TRUE(f.agree());
  std::ostringstream out;
  print_agreement(f, "A", "B", out);
  EXPECT_NE(out.str().find("recurrent-s7: generations 0-2 (3 and 5 held) agree"), std::string::npos) << out.str();

  RunResults changed = r.long_run;
  changed.run.generations[0].best_fitness += 1;
  write_run_results(b / "recurrent-s7.results.json", changed);
  f = compare_results_folders(a.path, b.path);
  EXPECT_FALSE(f.agree());
  std::ostringstream out2;
  print_agreement(f, "A", "B", out2);
  EXPECT_NE(out2.str().find("DIFFER at generation 0: best_fitness"), std::string::npos) << out2.str();
  EXPECT_NE(out2.str().find("1 of 1 trials in both folders differ"), std::string::npos) << out2.str();

  // Nothing in common: no agreement to claim.
  TempDir empty;
  EXPECT_FALSE(compare_results_folders(a.path, empty.path).agree());
}

}  // namespace
}  // namespace robozoo
