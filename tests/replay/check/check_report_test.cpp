#include "replay/check/check_report.hpp"

#include <gtest/gtest.h>

namespace robozoo::replay {
namespace {

ChampionResult ok(int gen) {
  ChampionResult c;
  c.run_id = "r";
  c.generation = gen;
  c.genome_id = 100 + gen;
  c.spheres = 12;
  c.morphology_logged = c.morphology_ok = true;
  c.poses_logged = c.poses_compared = c.poses_expected = 101;
  c.fitness_compared = true;
  c.logged_fitness = c.recomputed_fitness = 15.25;
  c.recomputed_outcome = 1;
  return c;
}

ChampionResult diverged(int gen) {
  ChampionResult c = ok(gen);
  c.status = ChampionResult::Status::Diverged;
  Mismatch m;
  m.what = "pose";
  m.step = 240;
  m.element = "body 2";
  m.field = "body_position[2][0]";
  m.logged = "0.5";
  m.recomputed = "0.50000000000000011";
  m.error = 1.1e-16;
  c.mismatches = {m};
  c.mismatch_count = 37;
  c.max_error = 3e-9;
  c.poses_diverged = 4;
  c.first_divergent_step = 240;
  return c;
}

TEST(CheckReport, ExitCodes) {
  CheckReport r;
  r.champions = {ok(0), ok(1)};
  EXPECT_EQ(r.exit_code(), 0);
  r.input_problems.push_back({-1, -1, "", "garbage"});
  EXPECT_EQ(r.exit_code(), 2);
  r.champions.push_back(diverged(2));
  EXPECT_EQ(r.exit_code(), 1);  // a divergence is the finding that matters most
  r.fatal = "no ROBOZOO_RUN";
  EXPECT_EQ(r.exit_code(), 2);
  CheckReport u;
  u.champions = {ok(0)};
  u.champions[0].status = ChampionResult::Status::Unusable;
  EXPECT_EQ(u.exit_code(), 2);
}

TEST(CheckReport, ADivergedLineSaysWhereAndHowFar) {
  const std::string line = champion_line(diverged(3), false);
  for (const char* part :
       {"DIVERGED", "gen 3", "genome 103", "pose step 240 body 2 body_position[2][0]", "logged 0.5",
        "recomputed 0.50000000000000011", "max error 3e-09", "37 values differ", "4 of 101 poses from step 240"})
    EXPECT_NE(line.find(part), std::string::npos) << part << " not in: " << line;
}

TEST(CheckReport, AnOkLineAndAnUnusableLine) {
  const std::string line = champion_line(ok(1), true);
  for (const char* part : {"ok", "run r", "gen 1", "genome 101", "spheres 12", "poses 101", "fitness 15.25"})
    EXPECT_NE(line.find(part), std::string::npos) << part << " not in: " << line;
  ChampionResult u = ok(2);
  u.status = ChampionResult::Status::Unusable;
  u.problems = {"its genome cannot be used: link 5 comes from missing node 99"};
  const std::string bad = champion_line(u, false);
  EXPECT_NE(bad.find("UNUSABLE"), std::string::npos) << bad;
  EXPECT_NE(bad.find("missing node 99"), std::string::npos) << bad;
}

TEST(CheckReport, TextHasAHeaderALinePerChampionProblemsAndASummary) {
  CheckReport r;
  r.log_path = "x.lcmlog";
  r.events = 50;
  r.runs = {{"r", "0.1.0", 7, "feedforward", 24, 4}};
  r.champions = {ok(0), diverged(1)};
  r.input_problems = {{3, 7, "ROBOZOO_POSE", "not a valid ROBOZOO_POSE message: wrong fingerprint"}};
  const std::string t = format_text(r);
  EXPECT_NE(t.find("x.lcmlog: 50 events"), std::string::npos) << t;
  EXPECT_NE(t.find("run r: robozoo 0.1.0, feedforward, seed 7"), std::string::npos) << t;
  EXPECT_NE(t.find("input: event 7 (ROBOZOO_POSE): not a valid"), std::string::npos) << t;
  EXPECT_NE(t.find("summary: 2 genomes checked: 1 ok, 1 diverged, 0 unusable"), std::string::npos) << t;
  EXPECT_NE(t.find("bit for bit"), std::string::npos) << t;
  EXPECT_NE(t.find("exit 1"), std::string::npos) << t;
  r.tolerance = 1e-9;
  EXPECT_NE(format_text(r).find("within a relative error of 1e-09"), std::string::npos);
}

TEST(CheckReport, JsonCarriesTheSameReport) {
  CheckReport r;
  r.log_path = "x.lcmlog";
  r.runs = {{"r", "0.1.0", 7, "recurrent", 24, 4}};
  r.champions = {ok(0), diverged(1)};
  r.champions[1].mismatches[0].error = std::numeric_limits<double>::infinity();
  const nlohmann::json j = nlohmann::json::parse(to_json(r).dump());
  EXPECT_EQ(j["log"], "x.lcmlog");
  EXPECT_EQ(j["bit_for_bit"], true);
  EXPECT_TRUE(j["fatal"].is_null());
  EXPECT_EQ(j["runs"][0]["regime"], "recurrent");
  ASSERT_EQ(j["champions"].size(), 2u);
  EXPECT_EQ(j["champions"][0]["status"], "ok");
  EXPECT_EQ(j["champions"][1]["status"], "diverged");
  EXPECT_EQ(j["champions"][1]["first_divergent_step"], 240);
  EXPECT_EQ(j["champions"][1]["mismatches"][0]["field"], "body_position[2][0]");
  EXPECT_EQ(j["champions"][1]["mismatches"][0]["recomputed"], "0.50000000000000011");
  EXPECT_TRUE(j["champions"][1]["mismatches"][0]["error"].is_null());  // infinite: an exact field
  EXPECT_EQ(j["champions"][0]["logged_fitness"], "15.25");
  EXPECT_EQ(j["summary"]["diverged"], 1);
  EXPECT_EQ(j["summary"]["exit_code"], 1);
}

}  // namespace
}  // namespace robozoo::replay
