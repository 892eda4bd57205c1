#include "evolve/config/run_config.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

namespace robozoo {
namespace {

std::string error_of(const nlohmann::json& j) {
  try {
    config_from_json(j);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(RunConfig, DefaultsRoundTripExactly) {
  RunConfig c;
  c.seed = -77;
  c.eval.sim.friction = 0.1 + 0.2;  // not representable in short decimal
  c.neat.hidden_activations = 0b101;
  const nlohmann::json j = config_to_json(c);
  const RunConfig d = config_from_json(nlohmann::json::parse(j.dump()));
  EXPECT_EQ(config_to_json(d), j);
  EXPECT_EQ(d.eval.sim.friction, 0.1 + 0.2);
  EXPECT_EQ(d.seed, -77);
  EXPECT_EQ(d.neat.hidden_activations, 0b101u);
}

TEST(RunConfig, DefaultsMatchDesign) {
  const auto j = config_to_json(RunConfig{});
  EXPECT_EQ(j["neat"]["population"], 150);
  EXPECT_EQ(j["generations"], 500);
  EXPECT_EQ(j["sim"]["steps"], 2500);
  EXPECT_EQ(j["growth"]["cloud_points"], 629);
  EXPECT_EQ(j["regime"], "feedforward");
  EXPECT_EQ(j["neat"]["hidden_activations"], nlohmann::json({"signed_sigmoid", "signed_cosine", "gaussian"}));
}

TEST(RunConfig, DefaultsAreTheAuthorsBiasWeightMappingAndAddNodeNumbers) {
  const auto j = config_to_json(RunConfig{});
  EXPECT_EQ(j["growth"]["bias_input"], 0.3);
  EXPECT_EQ(j["growth"]["weight_mapping"], "rescaled");
  EXPECT_EQ(j["neat"]["add_node_innovations"], "fresh");
  const RunConfig c = config_from_json(
      {{"growth", {{"weight_mapping", "proportional"}}}, {"neat", {{"add_node_innovations", "shared"}}}});
  EXPECT_EQ(c.eval.growth.weight_mapping, WeightMapping::Proportional);
  EXPECT_EQ(c.neat.add_node_innovations, AddNodeInnovations::Shared);
  EXPECT_NE(error_of({{"growth", {{"weight_mapping", "linear"}}}}).find("growth.weight_mapping"), std::string::npos);
  EXPECT_NE(error_of({{"neat", {{"add_node_innovations", 1}}}}).find("neat.add_node_innovations"), std::string::npos);
}

TEST(RunConfig, ARecordWithoutTheNewerKeysMeansTheBehaviourItRanWith) {
  // A configuration as logs, checkpoints and compact results recorded it before these keys existed.
  nlohmann::json old = config_to_json(RunConfig{});
  old["growth"].erase("weight_mapping");
  old["growth"].erase("bias_input");
  old["neat"].erase("add_node_innovations");
  const RunConfig c = config_from_record(old);
  EXPECT_EQ(c.eval.growth.bias_input, 1.0);
  EXPECT_EQ(c.eval.growth.weight_mapping, WeightMapping::Proportional);
  EXPECT_EQ(c.neat.add_node_innovations, AddNodeInnovations::Shared);
  // What a record says is what runs, old keys and new.
  old["growth"]["bias_input"] = 0.5;
  old["growth"]["weight_mapping"] = "rescaled";
  old["neat"]["add_node_innovations"] = "fresh";
  const RunConfig d = config_from_record(old);
  EXPECT_EQ(d.eval.growth.bias_input, 0.5);
  EXPECT_EQ(d.eval.growth.weight_mapping, WeightMapping::Rescaled);
  EXPECT_EQ(d.neat.add_node_innovations, AddNodeInnovations::Fresh);
  // A new record reads back as written.
  EXPECT_EQ(config_to_json(config_from_record(config_to_json(RunConfig{}))), config_to_json(RunConfig{}));
}

TEST(RunConfig, OverlayChangesOnlyGivenKeys) {
  const auto c = config_from_json({{"regime", "recurrent"}, {"neat", {{"population", 20}}}});
  EXPECT_EQ(c.regime, Regime::Recurrent);
  EXPECT_EQ(c.neat.population, 20);
  EXPECT_EQ(c.neat.add_node_probability, NeatParams{}.add_node_probability);
}

TEST(RunConfig, ErrorsNameTheKey) {
  EXPECT_NE(error_of({{"nope", 1}}).find("nope: unknown key"), std::string::npos);
  EXPECT_NE(error_of({{"neat", {{"populaton", 5}}}}).find("neat.populaton: unknown key"), std::string::npos);
  EXPECT_NE(error_of({{"neat", {{"population", -5}}}}).find("neat.population: must be in [2,"), std::string::npos);
  EXPECT_NE(error_of({{"growth", {{"t_matter", 1.5}}}}).find("growth.t_matter"), std::string::npos);
  EXPECT_NE(error_of({{"sim", {{"dt", "fast"}}}}).find("sim.dt: must be a number"), std::string::npos);
  EXPECT_NE(error_of({{"regime", "sideways"}}).find("regime: unknown regime"), std::string::npos);
  EXPECT_NE(error_of({{"growth", {{"r_min", 0.6}}}}).find("growth.r_min"), std::string::npos);
  EXPECT_NE(error_of({{"neat", {{"hidden_activations", {"tanh"}}}}}).find("neat.hidden_activations"),
            std::string::npos);
  EXPECT_NE(error_of({{"sim", {{"rolling_spin_rule", 1}}}}).find("sim.rolling_spin_rule: must be true or false"),
            std::string::npos);
}

std::string write_temp(const std::string& suffix, const std::string& text) {
  std::string path = "/tmp/robozoo_config_test_" + std::to_string(::getpid()) + suffix;
  std::ofstream(path) << text;
  return path;
}

TEST(RunConfig, ReadsTomlAndJsonFiles) {
  const auto toml = write_temp(".toml", "regime = \"recurrent\"\n[neat]\npopulation = 30\n[sim]\nfriction = 0.5\n");
  const auto c = load_config_file(toml);
  EXPECT_EQ(c.regime, Regime::Recurrent);
  EXPECT_EQ(c.neat.population, 30);
  EXPECT_EQ(c.eval.sim.friction, 0.5);
  const auto json = write_temp(".json", R"({"generations": 7, "growth": {"max_spheres": 12}})");
  const auto d = load_config_file(json);
  EXPECT_EQ(d.generations, 7);
  EXPECT_EQ(d.eval.growth.max_spheres, 12);
  std::remove(toml.c_str());
  std::remove(json.c_str());
}

TEST(RunConfig, BadFilesNameTheFile) {
  EXPECT_THROW(load_config_file("/nonexistent/robozoo.json"), ConfigError);
  const auto bad = write_temp(".json", "{ not json");
  try {
    load_config_file(bad);
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(bad), std::string::npos);
  }
  const auto badtoml = write_temp(".toml", "[neat\npopulation = ");
  EXPECT_THROW(load_config_file(badtoml), ConfigError);
  const auto unknown = write_temp(".toml", "[sim]\nwobble = 3\n");
  try {
    load_config_file(unknown);
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("sim.wobble: unknown key"), std::string::npos);
  }
  for (const auto& p : {bad, badtoml, unknown}) std::remove(p.c_str());
}

std::string text_error(const std::string& text, ConfigFormat format) {
  try {
    config_from_text(text, format, "cfg");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

// TOML has nan and inf literals, and JSON numbers can overflow a double: no
// non-finite value may reach the configuration (checked by fuzz/files/fuzz_config_*).
TEST(RunConfig, NanAndInfinityAreRefusedNamingTheKey) {
  for (const char* v : {"nan", "+nan", "-nan", "inf", "+inf", "-inf"}) {
    const std::string e = text_error(std::string("[sim]\ndt = ") + v + "\n", ConfigFormat::Toml);
    EXPECT_NE(e.find("cfg: sim.dt: must be in"), std::string::npos) << v << ": " << e;
  }
  EXPECT_NE(text_error("[growth]\nr_max = nan\n", ConfigFormat::Toml).find("growth.r_max"), std::string::npos);
  EXPECT_NE(text_error("[neat]\npopulation = inf\n", ConfigFormat::Toml).find("neat.population: must be an integer"),
            std::string::npos);
  const std::string big = text_error(R"({"sim": {"dt": 1e999}})", ConfigFormat::Json);
  EXPECT_NE(big, "");
  EXPECT_NE(big.find("cfg"), std::string::npos) << big;
}

TEST(RunConfig, AbsurdSizesAreRefusedNamingTheKey) {
  EXPECT_NE(text_error("[neat]\npopulation = 9223372036854775807\n", ConfigFormat::Toml).find("neat.population"),
            std::string::npos);
  EXPECT_NE(text_error(R"({"generations": 1e300})", ConfigFormat::Json).find("generations"), std::string::npos);
  EXPECT_NE(text_error(R"({"generations": -1})", ConfigFormat::Json).find("generations"), std::string::npos);
  EXPECT_NE(text_error(R"({"generations": 18446744073709551615})", ConfigFormat::Json).find("generations"),
            std::string::npos);
  // Deep nesting is an error, not a stack overflow.
  EXPECT_NE(text_error(std::string(100000, '[') + std::string(100000, ']'), ConfigFormat::Json), "");
  EXPECT_NE(text_error("a = " + std::string(100000, '[') + std::string(100000, ']'), ConfigFormat::Toml), "");
}

TEST(RunConfig, TextAndFileReadTheSame) {
  const std::string text = "regime = \"recurrent\"\n[neat]\npopulation = 30\n";
  const auto toml = write_temp(".toml", text);
  EXPECT_EQ(config_to_json(load_config_file(toml)), config_to_json(config_from_text(text, ConfigFormat::Toml, "x")));
  std::remove(toml.c_str());
}

TEST(RunConfig, TopologyRulesAreKeysWithHyperNeatDefaults) {
  const nlohmann::json j = config_to_json(RunConfig{});
  EXPECT_EQ(j["neat"]["link_rule"], "positions");
  EXPECT_EQ(j["neat"]["self_loops"], false);
  EXPECT_EQ(j["neat"]["initial_links"], "all_allowed");
  EXPECT_EQ(j["neat"]["add_link"], "uniform");
  EXPECT_EQ(j["neat"]["add_node"], "hyperneat");
  EXPECT_EQ(j["neat"]["compatibility"], "hyperneat");
  EXPECT_EQ(j["neat"]["disabled_gene_probability"], 0.0);
  EXPECT_EQ(j["sim"]["target_x"], 50.0);
  EXPECT_EQ(j["sim"]["distance_sensor_range"], 100.0);
  // The classic variants are reachable, and a wrong name is refused naming the key and the choices.
  const RunConfig c = config_from_json({{"neat",
                                         {{"link_rule", "cycle_test"},
                                          {"initial_links", "inputs_to_outputs"},
                                          {"add_link", "tries"},
                                          {"add_node", "classic"},
                                          {"compatibility", "classic"},
                                          {"self_loops", true}}}});
  EXPECT_EQ(c.neat.link_rule, LinkRule::CycleTest);
  EXPECT_EQ(c.neat.initial_links, InitialLinks::InputsToOutputs);
  EXPECT_EQ(c.neat.add_link, AddLinkRule::Tries);
  EXPECT_EQ(c.neat.add_node, AddNodeRule::Classic);
  EXPECT_EQ(c.neat.compatibility, CompatibilityRule::Classic);
  EXPECT_TRUE(c.neat.self_loops);
  EXPECT_EQ(config_from_json(config_to_json(c)).neat.add_node, AddNodeRule::Classic);
  try {
    config_from_json({{"neat", {{"add_node", "split"}}}});
    FAIL() << "accepted an unknown add-node rule";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("neat.add_node"), std::string::npos) << what;
    EXPECT_NE(what.find("hyperneat, classic"), std::string::npos) << what;
  }
  EXPECT_THROW(config_from_json({{"neat", {{"link_rule", 3}}}}), ConfigError);
  EXPECT_THROW(config_from_json({{"neat", {{"disabled_gene_probability", 1.5}}}}), ConfigError);
}

TEST(RunConfig, AssignmentsSetOneKey) {
  EXPECT_EQ(config_assignment("neat.initial_links=inputs_to_outputs"),
            nlohmann::json({{"neat", {{"initial_links", "inputs_to_outputs"}}}}));
  EXPECT_EQ(config_assignment("sim.target_x=20"), nlohmann::json({{"sim", {{"target_x", 20}}}}));
  EXPECT_EQ(config_assignment("neat.self_loops=true"), nlohmann::json({{"neat", {{"self_loops", true}}}}));
  EXPECT_EQ(config_assignment("regime=\"recurrent\""), nlohmann::json({{"regime", "recurrent"}}));
  const RunConfig c = config_from_json(config_assignment("neat.initial_links=inputs_to_outputs"));
  EXPECT_EQ(c.neat.initial_links, InitialLinks::InputsToOutputs);
  EXPECT_THROW(config_assignment("neat.initial_links"), ConfigError);
  EXPECT_THROW(config_assignment("=3"), ConfigError);
  EXPECT_THROW(config_assignment("neat..x=3"), ConfigError);
  EXPECT_THROW(config_from_json(config_assignment("neat.no_such_key=1")), ConfigError);
}

}  // namespace
}  // namespace robozoo
