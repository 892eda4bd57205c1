// Compact results: a real run's log, reduced and written, reads back to the
// same analysis for every analysis option; bad files are refused naming the
// file and the field.
#include "evolve/record/run_results.hpp"

#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "study/analysis/measure/run_analysis.hpp"
#include "evolve/neat/population_json.hpp"
#include "evolve/run/evaluator.hpp"
#include "evolve/run/evolution.hpp"
#include "study/analysis/read/log_results.hpp"
#include "tests/support/small_run.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using nlohmann::json;
using robozoo::testing::TempDir;

/// A real run (5 generations of 24, champions simulated, pose streams logged).
struct RealRun {
  TempDir dir;
  std::string log = dir / "recurrent-s7.lcmlog";
  RealRun() { robozoo::testing::evolve_small_run(log, "recurrent-s7", 5); }
};

const RealRun& real_run() {
  static const RealRun* r = new RealRun();  // evolved once for the whole file
  return *r;
}

/// Every field of two analyses, doubles bit for bit (NaN equals NaN).
void expect_same(const RunAnalysis& a, const RunAnalysis& b) {
  auto same = [](double x, double y) { return (std::isnan(x) && std::isnan(y)) || x == y; };
  EXPECT_EQ(a.run_id, b.run_id);
  EXPECT_EQ(a.arm, b.arm);
  EXPECT_EQ(a.regime, b.regime);
  EXPECT_EQ(a.max_spheres, b.max_spheres);
  EXPECT_TRUE(same(a.max_d, b.max_d));
  EXPECT_TRUE(same(a.target_distance, b.target_distance));
  EXPECT_EQ(a.outcome_shares, b.outcome_shares);
  EXPECT_EQ(a.seed, b.seed);
  EXPECT_EQ(a.population, b.population);
  EXPECT_EQ(a.generations_requested, b.generations_requested);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.complete, b.complete);
  EXPECT_EQ(a.undecodable, b.undecodable);
  EXPECT_EQ(a.best_so_far, b.best_so_far);
  EXPECT_EQ(a.has_best, b.has_best);
  EXPECT_EQ(a.best_generation, b.best_generation);
  EXPECT_EQ(a.best_genome_id, b.best_genome_id);
  EXPECT_TRUE(same(a.best_fitness, b.best_fitness));
  EXPECT_EQ(a.best_outcome, b.best_outcome);
  const MorphologyStats &m = a.morphology, &n = b.morphology;
  for (auto f : {&MorphologyStats::spheres, &MorphologyStats::leaves, &MorphologyStats::joints,
                 &MorphologyStats::distance_sensors, &MorphologyStats::touch_sensors, &MorphologyStats::proprio_sensors,
                 &MorphologyStats::time_sensors, &MorphologyStats::mean_radius, &MorphologyStats::radius_variance,
                 &MorphologyStats::max_depth, &MorphologyStats::ground_spheres, &MorphologyStats::ground_fraction})
    EXPECT_TRUE(same(m.*f, n.*f));
  EXPECT_EQ(m.ground_known, n.ground_known);
  const GenotypeStats &g = a.genotype, &h = b.genotype;
  for (auto f : {&GenotypeStats::nodes, &GenotypeStats::hidden, &GenotypeStats::hidden_sigmoid,
                 &GenotypeStats::hidden_cosine, &GenotypeStats::hidden_gaussian, &GenotypeStats::hidden_other,
                 &GenotypeStats::link_genes, &GenotypeStats::links, &GenotypeStats::forward_links,
                 &GenotypeStats::recurrent_links, &GenotypeStats::cycle_links})
    EXPECT_TRUE(same(g.*f, h.*f));
  ASSERT_EQ(a.changes.changes.size(), b.changes.changes.size());
  for (size_t i = 0; i < a.changes.changes.size(); ++i) {
    const auto &x = a.changes.changes[i], &y = b.changes.changes[i];
    EXPECT_EQ(x.generation, y.generation);
    EXPECT_EQ(x.previous_id, y.previous_id);
    EXPECT_EQ(x.genome_id, y.genome_id);
    EXPECT_TRUE(same(x.fitness, y.fitness));
    EXPECT_TRUE(same(x.previous_fitness, y.previous_fitness));
    EXPECT_TRUE(same(x.improvement, y.improvement));
    EXPECT_EQ(x.topology_changed, y.topology_changed);
  }
  EXPECT_EQ(a.changes.not_simulated, b.changes.not_simulated);
  EXPECT_EQ(a.changes.unknown, b.changes.unknown);
}

std::vector<AnalysisParams> every_option() {
  std::vector<AnalysisParams> out(4);
  out[1].morphology.ground_epsilon = 0.05;
  out[2].changes.topology.joints = true;
  out[3].changes.simulated_only = false;
  return out;
}

TEST(RunResults, CompactSummaryAnalysesAsTheWholeLog) {
  const RunSummary full = summarize_run_file(real_run().log);
  ASSERT_TRUE(full.complete());
  const RunSummary compact = compact_summary(full);
  // The run exercises what the analysis reads: a simulated best-of-run robot with its pose stream.
  const RunAnalysis a = analyze_run(full);
  ASSERT_TRUE(a.has_best);
  ASSERT_TRUE(a.morphology.ground_known);
  ASSERT_GT(a.genotype.links, 0);
  EXPECT_EQ(compact.min_center_z.size(), 1u);  // the best-of-run's stream only
  EXPECT_LT(compact.min_center_z.size(), full.min_center_z.size() + 1);
  for (const auto& p : every_option()) expect_same(analyze_run(full, p), analyze_run(compact, p));
}

TEST(RunResults, WrittenResultsReadBackToTheSameAnalysisAndTheSameFile) {
  TempDir out;
  const RunResults r = results_from_log(real_run().log);
  EXPECT_TRUE(r.has_evolve_seconds);  // the run's checkpoint is next to its log
  EXPECT_GT(r.evolve_seconds, 0.0);
  const std::string path = out / "recurrent-s7.results.json";
  write_run_results(path, r);
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  const RunResults back = read_run_results(path);
  EXPECT_EQ(back.run.path, out / "recurrent-s7.lcmlog");  // the log it came from, as if in the same folder
  EXPECT_EQ(back.evolve_seconds, r.evolve_seconds);
  EXPECT_EQ(back.run.config_json, r.run.config_json);
  EXPECT_EQ(back.run.software_version, r.run.software_version);
  ASSERT_EQ(back.run.generations.size(), 5u);
  EXPECT_EQ(back.run.generations[3].num_species, r.run.generations[3].num_species);
  EXPECT_EQ(back.run.generations[3].evaluations, 4 * 24);
  for (const auto& p : every_option()) expect_same(analyze_run(r.run, p), analyze_run(back.run, p));
  // A fixed point: what is read writes the same text.
  EXPECT_EQ(run_results_to_json(back).dump(), run_results_to_json(r).dump());
  // The best-of-run genome is in the genome JSON format robozoo-evolve eval --genome reads.
  const json j = json::parse(testing::read_file(path));
  EXPECT_EQ(genome_from_json(j["best"]["genome"]).id, analyze_run(r.run).best_genome_id);
}

TEST(RunResults, NonFiniteNumbersRoundTrip) {
  RunResults r = results_from_log(real_run().log);
  r.run.max_d = std::numeric_limits<double>::infinity();
  r.run.generations[1].mean_fitness = std::numeric_limits<double>::quiet_NaN();
  r.run.generations[2].stderr_fitness = -std::numeric_limits<double>::infinity();
  const RunResults back = run_results_from_json(run_results_to_json(r), "x/r.results.json");
  EXPECT_TRUE(std::isinf(back.run.max_d) && back.run.max_d > 0);
  EXPECT_TRUE(std::isnan(back.run.generations[1].mean_fitness));
  EXPECT_TRUE(std::isinf(back.run.generations[2].stderr_fitness) && back.run.generations[2].stderr_fitness < 0);
}

/// The error of reading `j` as "bad.results.json"; empty when it reads.
std::string error_of(const json& j) {
  try {
    run_results_from_json(j, "dir/bad.results.json");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(RunResults, BadFilesAreRefusedNamingTheFileAndTheField) {
  const json good = run_results_to_json(results_from_log(real_run().log));
  ASSERT_EQ(error_of(good), "");
  struct Case {
    std::function<void(json&)> edit;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {[](json& j) { j["format"] = "robozoo-checkpoint"; }, "results.format: not robozoo-run-results"},
      {[](json& j) { j["version"] = 2; }, "results.version: 2 (this robozoo reads version 1)"},
      {[](json& j) { j.erase("generations"); }, "results.generations: missing"},
      {[](json& j) { j["generations"]["mean_fitness"].erase(0); },
       "results.generations.mean_fitness: has 4 entries, expected 5"},
      {[](json& j) {
         j["generations"]["outcomes"][2] = json::array({1, 2, 3});
       },
       "results.generations.outcomes[2]: has 3 counts, expected 6"},
      {[](json& j) { j["generations"]["generation"][3] = 1; },
       "results.generations.generation[3]: generations must increase"},
      {[](json& j) { j["generations"]["best_fitness"][0] = "many"; },
       "results.generations.best_fitness[0]: not a number"},
      {[](json& j) { j["champions"][1]["genome_id"] = 999999; },
       "results.champions[1].genome_id: 999999, but generation 1"},
      {[](json& j) { j["champions"][1]["parents"][0] = 0; }, "results.champions[1].parents[0]"},
      {[](json& j) { j["champions"][0]["joints"] = "01"; }, "results.champions[0].joints: has 2 flags"},
      {[](json& j) { j["run"]["arm"] = "feedforward"; }, "results.run.arm: 'feedforward', but its regime"},
      {[](json& j) { j["run"]["log"] = "../x.lcmlog"; }, "results.run.log: must be a file name"},
      {[](json& j) { j["best"]["min_center_z"].erase(0); }, "results.best.min_center_z: has"},
      {[](json& j) { j["best"]["genome"]["id"] = 5; }, "results.best.genome.id: 5, but the champion is"},
      {[](json& j) { j["best"] = nullptr; }, "results.best: missing, but there are champions"},
      {[](json& j) { j["undecodable"] = -1; }, "results.undecodable"},
  };
  for (const auto& c : cases) {
    json j = good;
    c.edit(j);
    const std::string e = error_of(j);
    EXPECT_EQ(e.rfind("dir/bad.results.json: ", 0), 0u) << e;
    EXPECT_NE(e.find(c.expected), std::string::npos) << "expected '" << c.expected << "' in: " << e;
  }
  EXPECT_THROW(run_results_from_text("{\"format\": ", "x"), std::invalid_argument);
  EXPECT_THROW(read_run_results("/nonexistent/r.results.json"), std::runtime_error);
}

TEST(RunResults, ItsSizeIsTheBestGenomeAndAFewHundredBytesPerGeneration) {
  const RunResults r = results_from_log(real_run().log);
  const json j = run_results_to_json(r);
  const size_t bytes = j.dump().size(), genome = j["best"]["genome"].dump().size();
  const size_t links = j["best"]["genome"]["links"].size();
  // The genome JSON format: about 100 bytes per link gene.
  EXPECT_LT(genome, 120 * links + 2000) << genome << " bytes for " << links << " links";
  // Everything else: the run's configuration (under 3 kB) and under 700 bytes per generation.
  EXPECT_LT(bytes - genome, 3000 + 700 * r.run.generations.size()) << bytes << " bytes in all";
}

}  // namespace
}  // namespace robozoo
