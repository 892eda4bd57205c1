#include "study/analysis/sensitivity/config_difference.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "evolve/config/run_config.hpp"

namespace robozoo {
namespace {

std::string config_text(void (*change)(nlohmann::json&) = nullptr) {
  nlohmann::json j = config_to_json(RunConfig{});
  if (change) change(j);
  return j.dump();
}

TEST(ConfigDifference, NamesEachChangedKeyWithBothValues) {
  const std::string a = config_text();
  const std::string b = config_text([](nlohmann::json& j) {
    j["growth"]["bias_input"] = 1.0;
    j["sim"]["rolling_contact_rule"] = false;
    j["generations"] = 30;
  });
  const auto d = config_difference(a, b, {}, "test");
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[0].key, "generations");
  EXPECT_EQ(d[1].key, "growth.bias_input");
  EXPECT_EQ(d[1].from, "0.3");
  EXPECT_EQ(d[1].to, "1.0");
  EXPECT_EQ(d[2].key, "sim.rolling_contact_rule");
  EXPECT_EQ(d[2].from, "true");
  EXPECT_EQ(d[2].to, "false");
  const auto ignoring = config_difference(a, b, {"generations"}, "test");
  ASSERT_EQ(ignoring.size(), 2u);
  EXPECT_EQ(describe_changes(ignoring), "growth.bias_input 0.3 -> 1.0; sim.rolling_contact_rule true -> false");
  EXPECT_EQ(describe_changes({}), "none");
  EXPECT_TRUE(config_difference(a, a, {}, "test").empty());
}

TEST(ConfigDifference, AnArrayIsOneValue) {
  const auto d = config_difference(
      config_text(), config_text([](nlohmann::json& j) { j["neat"]["hidden_activations"] = {"signed_sigmoid"}; }), {},
      "test");
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].key, "neat.hidden_activations");
  EXPECT_EQ(d[0].to, "[\"signed_sigmoid\"]");
}

TEST(ConfigDifference, AKeyAnOlderRobozooDidNotWriteIsItsLegacyValue) {
  // A configuration recorded before growth.bias_input existed ran with bias 1.0.
  const std::string old = config_text([](nlohmann::json& j) { j["growth"].erase("bias_input"); });
  const std::string unit_bias = config_text([](nlohmann::json& j) { j["growth"]["bias_input"] = 1.0; });
  const auto d = config_difference(old, unit_bias, {}, "test");
  for (const auto& c : d) EXPECT_NE(c.key, "growth.bias_input") << describe_changes(d);
  const auto against_new = config_difference(old, config_text(), {}, "test");
  bool named = false;
  for (const auto& c : against_new) named = named || c.key == "growth.bias_input";
  EXPECT_TRUE(named) << describe_changes(against_new);
}

TEST(ConfigDifference, RefusesWhatIsNotAConfiguration) {
  try {
    config_difference("{not json", config_text(), {}, "factor x run y");
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("factor x run y"), std::string::npos) << e.what();
  }
  EXPECT_THROW(config_difference(config_text(), "{\"growth\": {\"bias_input\": \"high\"}}", {}, "t"),
               std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
