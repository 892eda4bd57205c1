#include "replay/log/logged_config.hpp"

#include <gtest/gtest.h>

#include "evolve/messages/build.hpp"

namespace robozoo::replay {
namespace {

RunConfig unusual() {
  RunConfig c;
  c.regime = Regime::Recurrent;
  c.seed = -3;
  c.generations = 12;
  c.neat.population = 33;
  c.eval.sim.steps = 777;
  c.eval.sim.dt = 0.005;
  c.eval.growth.t_matter = 0.65;
  c.pose_every = 3;
  return c;
}

void expect_error_mentions(const run_t& m, const std::string& text) {
  try {
    config_from_run_message(m);
    FAIL() << "accepted; expected an error mentioning " << text;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

TEST(LoggedConfig, ComesBackExactlyFromTheRunMessage) {
  const run_t m = make_run_message("r1", unusual(), 0);
  const RunConfig c = config_from_run_message(m);
  EXPECT_EQ(config_to_json(c), config_to_json(unusual()));
  EXPECT_EQ(c.eval.growth.t_matter, 0.65);
  EXPECT_EQ(c.pose_every, 3);
}

TEST(LoggedConfig, AMissingKeyIsNotTakenFromDefaults) {
  run_t m = make_run_message("r1", unusual(), 0);
  nlohmann::json j = nlohmann::json::parse(m.config_json);
  j["growth"].erase("t_matter");
  m.config_json = j.dump();
  expect_error_mentions(m, "growth.t_matter");
}

TEST(LoggedConfig, BadJsonBadValuesAndDisagreementsAreRefused) {
  run_t m = make_run_message("r1", unusual(), 0);
  run_t bad = m;
  bad.config_json = "{not json";
  expect_error_mentions(bad, "not JSON");
  bad = m;
  nlohmann::json j = nlohmann::json::parse(m.config_json);
  j["neat"]["population"] = -5;
  bad.config_json = j.dump();
  expect_error_mentions(bad, "neat.population");
  bad = m;
  bad.seed = 4;
  expect_error_mentions(bad, "run_t.seed");
  bad = m;
  bad.dt = 0.01;
  expect_error_mentions(bad, "run_t.dt");
  bad = m;
  bad.regime = 0;
  expect_error_mentions(bad, "run_t.regime");
}

TEST(LoggedConfig, AnotherSoftwareVersionIsRefused) {
  run_t m = make_run_message("r1", RunConfig{}, 0);
  EXPECT_EQ(version_refusal(m), "");
  m.software_version = "0.0.1-other";
  const std::string why = version_refusal(m);
  EXPECT_NE(why.find("0.0.1-other"), std::string::npos) << why;
  EXPECT_NE(why.find(software_version()), std::string::npos) << why;
  EXPECT_NE(why.find("--force"), std::string::npos) << why;
}

}  // namespace
}  // namespace robozoo::replay
