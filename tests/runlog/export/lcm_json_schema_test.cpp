#include "runlog/export/lcm_json_schema.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "robozoo/cppn_genome_t.hpp"
#include "robozoo/generation_t.hpp"
#include "robozoo/morphology_t.hpp"
#include "robozoo/pose_t.hpp"
#include "robozoo/run_t.hpp"
#include "runlog/text/message_json.hpp"

namespace robozoo {
namespace {

using nlohmann::json;

/// A small validator for the keywords lcm_json_schema uses, so the schemas
/// can be checked against message_json's output without a library.
bool valid(const json& schema, const json& value, std::string& why, const std::string& at = "$") {
  const std::string type = schema.at("type");
  if (type == "object") {
    if (!value.is_object()) return why = at + ": not an object", false;
    for (const auto& key : schema.at("required"))
      if (!value.contains(key)) return why = at + ": no " + key.get<std::string>(), false;
    for (const auto& [key, v] : value.items()) {
      if (!schema.at("properties").contains(key)) return why = at + ": extra " + key, false;
      if (!valid(schema["properties"][key], v, why, at + "." + key)) return false;
    }
    return true;
  }
  if (type == "array") {
    if (!value.is_array()) return why = at + ": not an array", false;
    if (schema.contains("minItems") && value.size() < schema["minItems"].get<size_t>())
      return why = at + ": short", false;
    if (schema.contains("maxItems") && value.size() > schema["maxItems"].get<size_t>())
      return why = at + ": long", false;
    for (size_t i = 0; i < value.size(); ++i)
      if (!valid(schema.at("items"), value[i], why, at + "[" + std::to_string(i) + "]")) return false;
    return true;
  }
  if (type == "integer") {
    if (!value.is_number_integer()) return why = at + ": not an integer", false;
    if (schema.contains("minimum") && value.get<long long>() < schema["minimum"].get<long long>())
      return why = at + ": low", false;
    if (schema.contains("maximum") && value.get<long long>() > schema["maximum"].get<long long>())
      return why = at + ": high", false;
    return true;
  }
  if (type == "number") return value.is_number() || (why = at + ": not a number", false);
  if (type == "string") return value.is_string() || (why = at + ": not a string", false);
  if (type == "boolean") return value.is_boolean() || (why = at + ": not a boolean", false);
  return why = at + ": unknown type " + type, false;
}

TEST(LcmJsonSchema, HandWrittenTypeGivesTheExpectedSchema) {
  const std::map<std::string, std::string> sources = {
      {"a_t",
       "package p;\n// a comment\nstruct a_t {\n  int8_t k; // kind\n  double v[2][n];\n  int32_t n;\n"
       "  b_t inner;\n}\n"},
      {"b_t", "package p; struct b_t { boolean on; string name; /* block */ }"}};
  const json want = json::parse(R"({
    "title": "robozoo.a_t", "type": "object", "additionalProperties": false,
    "required": ["k", "v", "n", "inner"],
    "properties": {
      "k": {"type": "integer", "minimum": -128, "maximum": 127},
      "v": {"type": "array", "minItems": 2, "maxItems": 2, "items": {"type": "array", "items": {"type": "number"}}},
      "n": {"type": "integer", "minimum": -2147483648, "maximum": 2147483647},
      "inner": {"title": "robozoo.b_t", "type": "object", "additionalProperties": false, "required": ["on", "name"],
                "properties": {"on": {"type": "boolean"}, "name": {"type": "string"}}}
    }})");
  EXPECT_EQ(lcm_json_schema("a_t", sources), want) << lcm_json_schema("a_t", sources).dump(2);
}

TEST(LcmJsonSchema, UnknownTypesAndUnreadableDeclarationsAreErrors) {
  EXPECT_THROW(lcm_json_schema("nope_t"), std::invalid_argument);
  EXPECT_THROW(lcm_json_schema("a_t", {{"a_t", "struct a_t { int8_t ; }"}}), std::invalid_argument);
  EXPECT_THROW(lcm_json_schema("a_t", {{"a_t", "struct a_t { c_t x; }"}}), std::invalid_argument);
}

TEST(LcmJsonSchema, EveryRobozooTypeIsEmbedded) {
  for (const char* t :
       {"run_t", "generation_t", "cppn_genome_t", "cppn_node_t", "link_t", "morphology_t", "sphere_t", "pose_t"})
    EXPECT_NO_THROW(lcm_json_schema(t)) << t;
  EXPECT_EQ(lcm_type_of_channel("ROBOZOO_POSE"), "pose_t");
  EXPECT_EQ(lcm_type_of_channel("ROBOZOO_GENOME"), "cppn_genome_t");
  EXPECT_EQ(lcm_type_of_channel("OTHER"), "");
}

template <class T>
json as_json(T& m, const char* channel) {
  std::vector<uint8_t> bytes(m.getEncodedSize());
  EXPECT_EQ(m.encode(bytes.data(), 0, static_cast<int>(bytes.size())), static_cast<int>(bytes.size()));
  json out;
  std::string why;
  EXPECT_TRUE(message_to_json(channel, bytes.data(), bytes.size(), out, why)) << why;
  return out;
}

TEST(LcmJsonSchema, MessageJsonOutputValidates) {
  cppn_genome_t g{};
  g.run_id = "r";
  g.nodes.resize(1);
  g.num_nodes = 1;
  g.links.resize(1);
  g.num_links = 1;
  g.links[0].enabled = 1;
  std::string why;
  EXPECT_TRUE(valid(lcm_json_schema("cppn_genome_t"), as_json(g, "ROBOZOO_GENOME"), why)) << why;

  morphology_t m{};
  m.num_spheres = 2;
  m.spheres.resize(2);
  m.num_neurons = 1;
  m.tau = {1.0};
  m.omega = {0.0};
  m.num_sensors = 1;
  m.sensor_sphere = {1};
  m.sensor_type = {2};
  m.w_sensor_neuron = {{0.5}};
  m.w_neuron_neuron = {{0.25}};
  EXPECT_TRUE(valid(lcm_json_schema("morphology_t"), as_json(m, "ROBOZOO_MORPHOLOGY"), why)) << why;

  pose_t p{};
  p.num_bodies = 1;
  p.body_position = {{1, 2, 3}};
  p.body_quaternion = {{1, 0, 0, 0}};
  p.num_spheres = 1;
  p.sphere_center = {{1, 2, 3}};
  EXPECT_TRUE(valid(lcm_json_schema("pose_t"), as_json(p, "ROBOZOO_POSE"), why)) << why;

  run_t r{};
  EXPECT_TRUE(valid(lcm_json_schema("run_t"), as_json(r, "ROBOZOO_RUN"), why)) << why;
  generation_t gen{};
  EXPECT_TRUE(valid(lcm_json_schema("generation_t"), as_json(gen, "ROBOZOO_GENERATION"), why)) << why;

  // And the validator itself rejects what the schema forbids.
  json bad = as_json(g, "ROBOZOO_GENOME");
  bad["links"][0]["enabled"] = 1;
  EXPECT_FALSE(valid(lcm_json_schema("cppn_genome_t"), bad, why));
  bad = as_json(p, "ROBOZOO_POSE");
  bad["sphere_center"][0].push_back(4.0);
  EXPECT_FALSE(valid(lcm_json_schema("pose_t"), bad, why));
}

}  // namespace
}  // namespace robozoo
