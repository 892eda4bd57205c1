// The continuation of a log in its run messages: taken out, the configuration
// text is exactly the uninterrupted run's; a malformed one is refused.
#include "evolve/messages/log_continuation.hpp"

#include <gtest/gtest.h>

#include "evolve/messages/build.hpp"

namespace robozoo {
namespace {

TEST(LogContinuation, TakenOutTheConfigurationIsTheUninterruptedRunsText) {
  RunConfig config;
  config.seed = 9;
  const run_t plain = make_run_message("r", config, 0);
  const LogContinuation c{3, 450, 12.625, 0xfedcba9876543210ull};
  const run_t marked = mark_continued(plain, c);
  EXPECT_NE(marked.config_json, plain.config_json);
  EXPECT_EQ(marked.seed, plain.seed);
  const SplitRunConfig split = split_run_config(marked.config_json);
  EXPECT_EQ(split.config_json, plain.config_json);
  ASSERT_TRUE(split.continues.has_value());
  EXPECT_TRUE(*split.continues == c);
  EXPECT_EQ(split.continues->last_champion_key, 0xfedcba9876543210ull);

  const SplitRunConfig none = split_run_config(plain.config_json);
  EXPECT_EQ(none.config_json, plain.config_json);
  EXPECT_FALSE(none.continues.has_value());
  EXPECT_EQ(split_run_config("not json").config_json, "not json");
}

TEST(LogContinuation, AMalformedContinuationIsRefused) {
  const std::string config = make_run_message("r", RunConfig{}, 0).config_json;
  auto with = [&config](const nlohmann::json& value) {
    nlohmann::json j = nlohmann::json::parse(config);
    j[kLogContinuesKey] = value;
    return j.dump();
  };
  nlohmann::json good = log_continuation_to_json({2, 20, 1.5, 7});
  EXPECT_NO_THROW(split_run_config(with(good)));
  for (const auto& [key, value] : std::vector<std::pair<std::string, nlohmann::json>>{
           {"from_generation", 0}, {"evaluations_before", -1}, {"best_so_far_before", "x"}, {"extra", 1}}) {
    nlohmann::json bad = good;
    bad[key] = value;
    EXPECT_THROW(split_run_config(with(bad)), std::invalid_argument) << key;
  }
  try {
    split_run_config(with(nlohmann::json::array()));
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("run_t.config_json: log_continues: not a JSON object"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace robozoo
