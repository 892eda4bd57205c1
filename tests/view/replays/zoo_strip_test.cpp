// The experiment page's thumbnail strips: every trial's best-of-run robot,
// read from its log while it runs (its champion so far) or from its compact
// result, made again by this build and checked; a trial's robot is made again
// only when its best so far changes.
#include "view/replays/zoo_strip.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <fstream>
#include <map>

#include "evolve/run/evaluator.hpp"
#include "evolve/run/evolution.hpp"
#include "evolve/record/run_results.hpp"
#include "study/analysis/read/log_results.hpp"
#include "tests/support/small_run.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo::view {
namespace {

using namespace robozoo::testing;

/// The robot called `name` in /zoo.json, or null.
nlohmann::json robot(const nlohmann::json& zoo, const std::string& name) {
  for (const auto& a : zoo["arms"])
    for (const auto& r : a["robots"])
      if (r["name"] == name) return r;
  return nullptr;
}

/// The trial's best fitness so far, as the watch read it.
double best_of(const ExperimentWatch& watch, const std::string& name) {
  for (const TrialProgress& t : watch.trials())
    if (t.name == name && !t.best_so_far.empty()) return t.best_so_far.back();
  ADD_FAILURE() << "no trial " << name << " with a generation";
  return 0;
}

TEST(ZooStrips, EveryTrialsRobotFromItsLogAndFromItsResult) {
  TempDir runs, elsewhere, results;
  // Here: a finished trial, two in progress (2 of 4 generations), one whose log is still empty.
  evolve_small_run(runs / "feedforward-s1.lcmlog", "feedforward-s1", 2, 1, Regime::FeedForward);
  const auto start = [&](int64_t seed, int generations) {
    RunConfig c = small_run_config(4);
    c.seed = seed;
    InProcessEvaluator evaluator(c.eval);
    EvolveOptions o;
    o.log_path = runs / ("recurrent-s" + std::to_string(seed) + ".lcmlog");
    o.run_id = "recurrent-s" + std::to_string(seed);
    o.resume = generations == 0;
    Evolution evo(c, o, evaluator);
    if (generations == 0) evo.run();
    for (int g = 0; g < generations; ++g) evo.step();
  };
  start(2, 2);
  start(4, 2);
  std::ofstream(runs / "recurrent-s6.lcmlog") << "";
  // Elsewhere: a trial known here from its compact result alone.
  evolve_small_run(elsewhere / "feedforward-s5.lcmlog", "feedforward-s5", 2, 5, Regime::FeedForward);
  write_run_results(results / "feedforward-s5.results.json", results_from_log(elsewhere / "feedforward-s5.lcmlog"));

  ExperimentWatchOptions wo;
  wo.results_dirs = {results.path};
  ExperimentWatch watch(runs.path, wo);
  ZooStrips strips;
  const nlohmann::json zoo = nlohmann::json::parse(strips.json(watch));
  EXPECT_EQ(zoo["refused"], nlohmann::json::array()) << zoo["refused"];
  ASSERT_EQ(zoo["arms"].size(), 2u) << zoo.dump().substr(0, 400);
  EXPECT_EQ(zoo["arms"][0]["arm"], "feedforward");
  EXPECT_EQ(zoo["arms"][0]["robots"].size(), 2u);
  EXPECT_EQ(zoo["arms"][1]["arm"], "recurrent");
  EXPECT_EQ(zoo["arms"][1]["robots"].size(), 2u);  // the empty log has no robot yet
  for (const char* name : {"feedforward-s1", "feedforward-s5", "recurrent-s2", "recurrent-s4"}) {
    const nlohmann::json r = robot(zoo, name);
    ASSERT_FALSE(r.is_null()) << name;
    EXPECT_EQ(r["fitness"].get<double>(), best_of(watch, name)) << name;
    EXPECT_EQ(r["r"].size() * 3, r["c"].size()) << name;
    EXPECT_EQ(r["leaf"].size(), r["r"].size()) << name;
  }
  EXPECT_EQ(robot(zoo, "recurrent-s2")["generations"], 2);
  EXPECT_EQ(robot(zoo, "recurrent-s2")["planned"], 4);
  EXPECT_EQ(robot(zoo, "feedforward-s1")["generations"], robot(zoo, "feedforward-s1")["planned"]);
  const std::vector<double> f = {robot(zoo, "feedforward-s1")["fitness"], robot(zoo, "feedforward-s5")["fitness"]};
  EXPECT_GE(zoo["arms"][0]["robots"][0]["fitness"].get<double>(), std::max(f[0], f[1]));  // by fitness

  // The trials in progress go on to their 4 generations: a robot is made
  // again when its trial's best so far changed, and kept (made at 2
  // generations) when not. (Seed 4's best changes, seed 2's does not.)
  std::map<std::string, double> before;
  for (const char* name : {"recurrent-s2", "recurrent-s4"}) before[name] = best_of(watch, name);
  start(2, 0);
  start(4, 0);
  watch.poll();
  const nlohmann::json later = nlohmann::json::parse(strips.json(watch));
  int made_again = 0, kept = 0;
  for (const char* name : {"recurrent-s2", "recurrent-s4"}) {
    const double after = best_of(watch, name);
    EXPECT_EQ(robot(later, name)["fitness"].get<double>(), after) << name;
    EXPECT_EQ(robot(later, name)["generations"], after != before[name] ? 4 : 2) << name;
    (after != before[name] ? made_again : kept) += 1;
  }
  EXPECT_EQ(made_again, 1) << "the seeds should give one trial a new best and not the other";
  EXPECT_EQ(kept, 1);
  // Asked again with nothing changed: the same answer.
  EXPECT_EQ(strips.json(watch), strips.json(watch));
}

TEST(ZooStrips, ARobotThisBuildDoesNotReproduceIsRefusedWithItsReason) {
  TempDir runs, elsewhere, results;
  std::ofstream(runs / "recurrent-s9.lcmlog") << "";
  evolve_small_run(elsewhere / "recurrent-s7.lcmlog", "recurrent-s7", 2);
  RunResults r = results_from_log(elsewhere / "recurrent-s7.lcmlog");
  for (auto& c : r.run.champions) c.genome.fitness += 1;
  write_run_results(results / "recurrent-s7.results.json", r);
  ExperimentWatchOptions wo;
  wo.results_dirs = {results.path};
  const ExperimentWatch watch(runs.path, wo);
  ZooStrips strips;
  const nlohmann::json zoo = nlohmann::json::parse(strips.json(watch));
  EXPECT_EQ(zoo["arms"], nlohmann::json::array());
  ASSERT_EQ(zoo["refused"].size(), 1u) << zoo.dump();
  EXPECT_EQ(zoo["refused"][0].get<std::string>().rfind("recurrent-s7: ", 0), 0u) << zoo["refused"][0];
  EXPECT_NE(zoo["refused"][0].get<std::string>().find("fitness"), std::string::npos) << zoo["refused"][0];
}

}  // namespace
}  // namespace robozoo::view
