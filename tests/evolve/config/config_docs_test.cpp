#include "evolve/config/config_docs.hpp"

#include <gtest/gtest.h>

#include <set>

#include "evolve/config/run_config.hpp"

namespace robozoo {
namespace {

void keys_of(const nlohmann::json& j, const std::string& prefix, std::set<std::string>& out) {
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string key = prefix.empty() ? it.key() : prefix + "." + it.key();
    if (it->is_object())
      keys_of(*it, key, out);
    else
      out.insert(key);
  }
}

TEST(ConfigDocs, EveryKeyHasAMeaningAndEveryMeaningAKey) {
  std::set<std::string> keys;
  keys_of(config_to_json(RunConfig{}), "", keys);
  ASSERT_GT(keys.size(), 90u);
  for (const auto& k : keys) {
    ASSERT_TRUE(config_docs().count(k)) << k << " has no meaning in evolve/config/config_docs.cpp";
    EXPECT_GT(config_docs().at(k).size(), 5u) << k;
  }
  for (const auto& [k, doc] : config_docs()) EXPECT_TRUE(keys.count(k)) << k << " is no configuration key";
}

TEST(ConfigDocs, ExplainedConfigurationIsOneLinePerKeyWithItsValue) {
  RunConfig c;
  c.eval.growth.bias_input = 1.0;
  const std::string text = explain_config(c);
  std::set<std::string> keys;
  keys_of(config_to_json(c), "", keys);
  EXPECT_EQ(static_cast<size_t>(std::count(text.begin(), text.end(), '\n')), keys.size());
  EXPECT_NE(text.find("\ngrowth.bias_input = 1.0  # value of the CPPN's constant bias input"), std::string::npos);
  EXPECT_NE(text.find("\nneat.population = 150  # genomes per generation (count)\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace robozoo
