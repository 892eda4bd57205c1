#include "study/analysis/sensitivity/sensitivity_analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "evolve/config/run_config.hpp"
#include "study/analysis/compare/holm.hpp"
#include "tests/study/analysis/sensitivity/two_factors.hpp"

namespace robozoo {
namespace {

std::string config(double bias = 0.3, int generations = 3, bool contact_rule = true) {
  nlohmann::json j = config_to_json(RunConfig{});
  j["growth"]["bias_input"] = bias;
  j["generations"] = generations;
  j["sim"]["rolling_contact_rule"] = contact_rule;
  return j.dump();
}

// A run of `arm` and `seed` whose best-so-far fitness is `fitness` + g at generation
// record g (so that reading the wrong generation shows), with outcomes
// {seed, 100, 0, 0, 10, 0} in every generation.
RunSummary run(const std::string& arm, int64_t seed, double fitness, const std::string& config_json,
               int generations = 3, const std::string& version = "v1") {
  RunSummary r;
  r.run_id = arm + "-s" + std::to_string(seed);
  r.arm = arm;
  r.seed = seed;
  r.software_version = version;
  r.config_json = config_json;
  r.generations_requested = generations;
  for (int g = 0; g < generations; ++g) {
    GenerationRecord rec;
    rec.generation = g;
    rec.best_so_far_fitness = fitness + g;
    rec.outcomes = {static_cast<int32_t>(seed), 100, 0, 0, 10, 0};
    r.generations.push_back(rec);
  }
  return r;
}

// The reference: feed-forward seeds 1, 5, 9 and recurrent 2, 6, 10, run to 5 generations.
std::vector<RunSummary> reference() {
  return {run("feedforward", 1, 10, config(0.3, 5), 5), run("feedforward", 5, 12, config(0.3, 5), 5),
          run("feedforward", 9, 50, config(0.3, 5), 5), run("recurrent", 2, 9, config(0.3, 5), 5),
          run("recurrent", 6, 10, config(0.3, 5), 5),   run("recurrent", 10, -40, config(0.3, 5), 5)};
}

SensitivityParams at(int generation) {
  SensitivityParams p;
  p.generation = generation;
  return p;
}

TEST(SensitivityAnalysis, ComparesEachFactorsGapWithTheReferencesOnTheSameSeeds) {
  // bias-1.0 runs seeds 1, 5 (feed-forward) and 2, 6 (recurrent), to 3 generations.
  SensitivityFactor bias{"bias-1.0",
                         {run("feedforward", 1, 20, config(1.0)), run("feedforward", 5, 24, config(1.0)),
                          run("recurrent", 2, 10, config(1.0)), run("recurrent", 6, 12, config(1.0))}};
  const SensitivityAnalysis a = analyze_sensitivity(reference(), {bias}, at(3));
  ASSERT_EQ(a.factors.size(), 1u);
  const FactorResult& f = a.factors[0];
  EXPECT_EQ(f.name, "bias-1.0");
  ASSERT_EQ(f.changes.size(), 1u);
  EXPECT_EQ(f.changes[0].key, "growth.bias_input");
  EXPECT_EQ(f.changes[0].from, "0.3");
  EXPECT_EQ(f.changes[0].to, "1.0");
  EXPECT_EQ(f.control_seeds, (std::vector<int64_t>{1, 5}));
  EXPECT_EQ(f.experimental_seeds, (std::vector<int64_t>{2, 6}));
  // Generation 3 is record 2: fitness + 2. Factor: (22 + 26) / 2 - (12 + 14) / 2 = 11.
  EXPECT_DOUBLE_EQ(f.gap.mean_a, 24.0);
  EXPECT_DOUBLE_EQ(f.gap.mean_b, 13.0);
  EXPECT_DOUBLE_EQ(f.gap.gap, 11.0);
  EXPECT_EQ(f.gap.n_a, 2u);
  EXPECT_EQ(f.gap.df, 2.0);
  // The reference on seeds 1, 5 and 2, 6 alone (not 9 and 10): (12 + 14) / 2 - (11 + 12) / 2 = 1.5.
  EXPECT_DOUBLE_EQ(f.reference_gap.gap, 1.5);
  EXPECT_EQ(f.reference_gap.n_a, 2u);
  EXPECT_DOUBLE_EQ(f.difference.gap, 9.5);
  EXPECT_DOUBLE_EQ(f.difference.se, std::sqrt(f.gap.se * f.gap.se + f.reference_gap.se * f.reference_gap.se));
  // One factor: Holm's p is Student's.
  EXPECT_DOUBLE_EQ(f.holm_p, f.gap.p);
  // Outcomes of generation record 2, pooled: not simulated = the seeds' sum.
  EXPECT_EQ(f.control_outcomes.runs, 2u);
  EXPECT_EQ(f.control_outcomes.counts[0], 6);
  EXPECT_EQ(f.control_outcomes.counts[1], 200);
  EXPECT_EQ(f.control_outcomes.total(), 226);
  EXPECT_EQ(f.control_outcomes.simulated(), 200);
  EXPECT_EQ(f.experimental_outcomes.counts[0], 8);
  EXPECT_EQ(f.reference_experimental_outcomes.counts[0], 8);
  EXPECT_EQ(a.software_version, "v1");
}

TEST(SensitivityAnalysis, HolmAcrossTheFactorsAndTheReadings) {
  // The reference's gap on seeds 1, 5, 9 / 2, 6, 10 at record 2: 26 - (-5) = 31.
  // clear: feed-forward far fitter, little spread (gap 90). unclear: gap 27, s.d. 20 in each arm.
  SensitivityFactor clear{"clear",
                          {run("feedforward", 1, 100, config(1.0)), run("feedforward", 5, 101, config(1.0)),
                           run("feedforward", 9, 100.5, config(1.0)), run("recurrent", 2, 10, config(1.0)),
                           run("recurrent", 6, 11, config(1.0)), run("recurrent", 10, 10.5, config(1.0))}};
  SensitivityFactor unclear{
      "unclear",
      {run("feedforward", 1, 10, config(0.3, 3, false)), run("feedforward", 5, 50, config(0.3, 3, false)),
       run("feedforward", 9, 30, config(0.3, 3, false)), run("recurrent", 2, 25, config(0.3, 3, false)),
       run("recurrent", 6, -15, config(0.3, 3, false)), run("recurrent", 10, 5, config(0.3, 3, false))}};
  const SensitivityAnalysis a = analyze_sensitivity(reference(), {clear, unclear}, at(3));
  ASSERT_EQ(a.factors.size(), 2u);
  const auto holm = holm_adjust({a.factors[0].gap.p, a.factors[1].gap.p});
  EXPECT_DOUBLE_EQ(a.factors[0].holm_p, holm[0]);
  EXPECT_DOUBLE_EQ(a.factors[1].holm_p, holm[1]);
  EXPECT_TRUE(a.factors[0].significant);
  EXPECT_EQ(a.factors[0].reading.rfind("feedforward fitter, significant after Holm", 0), 0u) << a.factors[0].reading;
  EXPECT_NE(a.factors[0].reading.find("excludes the reference's gap"), std::string::npos) << a.factors[0].reading;
  EXPECT_FALSE(a.factors[1].significant);
  EXPECT_EQ(a.factors[1].changes[0].key, "sim.rolling_contact_rule");
  EXPECT_EQ(a.factors[1].reading, "inconclusive: the interval holds both 0 and the reference's gap");
}

TEST(SensitivityAnalysis, AnArmOfOneRunHasNoTest) {
  SensitivityFactor thin{"thin", {run("feedforward", 1, 20, config(1.0)), run("recurrent", 2, 10, config(1.0))}};
  const SensitivityAnalysis a = analyze_sensitivity(reference(), {thin}, at(2));
  EXPECT_DOUBLE_EQ(a.factors[0].gap.gap, 10.0);
  EXPECT_TRUE(std::isnan(a.factors[0].gap.p));
  EXPECT_TRUE(std::isnan(a.factors[0].holm_p));
  EXPECT_FALSE(a.factors[0].significant);
  EXPECT_EQ(a.factors[0].reading.rfind("no test", 0), 0u);
}

void expect_refused(const std::vector<RunSummary>& factor_runs, const std::string& words,
                    std::vector<RunSummary> ref = reference(), int generation = 3) {
  SCOPED_TRACE(words);
  try {
    analyze_sensitivity(ref, {SensitivityFactor{"f", factor_runs}}, at(generation));
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
  }
}

TEST(SensitivityAnalysis, RefusesRunsThatCannotBeCompared) {
  expect_refused({run("feedforward", 13, 1, config(1.0))}, "the reference has no feedforward run of seed 13");
  expect_refused({run("feedforward", 1, 1, config(1.0)), run("feedforward", 1, 2, config(1.0))},
                 "two feedforward runs of seed 1");
  expect_refused({run("recurrent-zero", 1, 1, config(1.0))}, "is of arm recurrent-zero");
  expect_refused({run("feedforward", 1, 1, config(0.3))}, "has the reference's configuration");
  expect_refused({run("feedforward", 1, 1, config(1.0)), run("recurrent", 2, 1, config(0.3, 3, false))},
                 "where the factor's other runs change growth.bias_input 0.3 -> 1.0");
  expect_refused({run("feedforward", 1, 1, config(1.0), 3, "v2")}, "ran robozoo v2");
  expect_refused({run("feedforward", 1, 1, config(1.0), 2)}, "holds 2 generations, fewer than the 3 compared");
  // The reference must reach the generation as well.
  expect_refused({run("feedforward", 1, 1, config(1.0), 8)}, "the reference run feedforward-s1 holds 5 generations",
                 reference(), 7);
  // A record out of place.
  RunSummary shuffled = run("feedforward", 1, 1, config(1.0));
  std::swap(shuffled.generations[1], shuffled.generations[2]);
  expect_refused({shuffled}, "its record 2 is generation 1");
  // A reference of two versions.
  std::vector<RunSummary> mixed = reference();
  mixed[3].software_version = "v0";
  expect_refused({run("feedforward", 1, 1, config(1.0))}, "different versions", mixed);
  EXPECT_THROW(analyze_sensitivity(reference(), {}, at(0)), std::invalid_argument);
}

TEST(SensitivityAnalysis, NamesTheFactorsWithFewerRunsThanTheOthers) {
  SensitivityAnalysis a = robozoo::testing::two_factors();
  EXPECT_TRUE(factors_with_fewer_runs(a).empty());
  a.factors[1].experimental_seeds = {2};
  EXPECT_EQ(factors_with_fewer_runs(a),
            std::vector<std::string>{"cap-100 (2 feedforward and 1 recurrent runs, against 2 and 2)"});
  a.factors[0].control_seeds = {1};
  EXPECT_EQ(factors_with_fewer_runs(a),
            (std::vector<std::string>{"bias-1.0 (1 feedforward and 2 recurrent runs, against 2 and 2)",
                                      "cap-100 (2 feedforward and 1 recurrent runs, against 2 and 2)"}));
}

}  // namespace
}  // namespace robozoo
