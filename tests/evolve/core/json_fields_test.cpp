#include "evolve/core/json_fields.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <functional>
#include <stdexcept>

namespace robozoo::json_fields {
namespace {

using nlohmann::json;

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(JsonFields, IntegersOnlyAndWithinTheirType) {
  EXPECT_EQ(as_i64(json(-5), "a"), -5);
  EXPECT_EQ(as_i32(json(2147483647), "a"), 2147483647);
  EXPECT_EQ(error_of([] { as_i32(json(2147483648LL), "g.x"); }), "g.x: out of range: 2147483648");
  EXPECT_EQ(error_of([] { as_i64(json(std::numeric_limits<uint64_t>::max()), "g.x"); }), "g.x: out of range");
  // Floats are refused, also whole ones and ones beyond every integer type.
  EXPECT_EQ(error_of([] { as_i64(json(2.0), "g.x"); }), "g.x: expected an integer, got number");
  EXPECT_EQ(error_of([] { as_u64(json(1.02872e20), "g.h"); }), "g.h: expected an integer, got number");
  EXPECT_EQ(error_of([] { as_int(json(7), "g.n", 0, 5); }), "g.n: out of range: 7");
  EXPECT_EQ(as_u64(json(std::numeric_limits<uint64_t>::max()), "h"), std::numeric_limits<uint64_t>::max());
  EXPECT_EQ(error_of([] { as_u64(json(-1), "g.h"); }), "g.h: out of range: -1");
}

TEST(JsonFields, OtherTypesAndPaths) {
  const json j = json::parse(R"({"a": [1, "two"], "b": true, "c": 0.5})");
  EXPECT_EQ(error_of([&] { field(j, "z", "top"); }), "top.z: missing");
  EXPECT_EQ(error_of([&] { field(j["a"], "z", "top.a"); }), "top.a: expected an object, got array");
  EXPECT_EQ(as_array(field(j, "a", "top"), "top.a").size(), 2u);
  EXPECT_EQ(error_of([&] { as_string(j["a"][0], at("top.a", 0)); }), "top.a[0]: expected a string, got number");
  EXPECT_EQ(as_string(j["a"][1], "s"), "two");
  EXPECT_TRUE(as_bool(j["b"], "b"));
  EXPECT_EQ(error_of([&] { as_bool(j["c"], "top.c"); }), "top.c: expected true or false, got number");
  EXPECT_EQ(as_double(j["c"], "c"), 0.5);
  EXPECT_EQ(as_double(json(3), "c"), 3.0);  // an integer is a number
  EXPECT_EQ(error_of([&] { as_double(j["b"], "top.b"); }), "top.b: expected a number, got boolean");
}

}  // namespace
}  // namespace robozoo::json_fields
