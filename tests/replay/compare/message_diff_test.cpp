// Naming the first differing field of two messages.
#include "replay/compare/message_diff.hpp"

#include <gtest/gtest.h>

#include "evolve/messages/build.hpp"

namespace robozoo::replay {
namespace {

generation_t some_generation() {
  generation_t g{};
  g.run_id = "r";
  g.generation = 3;
  g.best_fitness = 2.5;
  return g;
}

TEST(MessageDiff, NamesTheScalarFieldAndBothValues) {
  generation_t a = some_generation(), b = some_generation();
  b.best_fitness = 2.75;
  const FieldDifference d = first_field_difference(kChannelGeneration, encode_message(a), encode_message(b));
  EXPECT_EQ(d.field, "best_fitness");
  EXPECT_EQ(d.a, "2.5");
  EXPECT_EQ(d.b, "2.75");
}

TEST(MessageDiff, NamesAnArrayElementsField) {
  cppn_genome_t a{};
  a.run_id = "r";
  a.num_links = 3;
  a.links.resize(3);
  for (int i = 0; i < 3; ++i) a.links[i].weight = i;
  cppn_genome_t b = a;
  b.links[2].weight = 7.0;
  const FieldDifference d = first_field_difference(kChannelGenome, encode_message(a), encode_message(b));
  EXPECT_EQ(d.field, "links[2].weight");
  EXPECT_EQ(d.a, "2.0");
  EXPECT_EQ(d.b, "7.0");
}

TEST(MessageDiff, IgnoredFieldsAndEqualMessages) {
  generation_t a = some_generation(), b = some_generation();
  b.utime = 99;
  EXPECT_EQ(first_field_difference(kChannelGeneration, encode_message(a), encode_message(b), {"utime"}).field, "");
  EXPECT_EQ(first_field_difference(kChannelGeneration, encode_message(a), encode_message(b)).field, "utime");
}

TEST(MessageDiff, BytesThatDoNotDecodeAreNamed) {
  std::vector<uint8_t> good = encode_message(some_generation());
  std::vector<uint8_t> bad = good;
  bad[0] ^= 0x40;
  const FieldDifference d = first_field_difference(kChannelGeneration, good, bad);
  EXPECT_EQ(d.field, "(bytes)");
  EXPECT_EQ(d.a, "a valid message");
  EXPECT_NE(d.b.find("not a valid message"), std::string::npos) << d.b;
}

}  // namespace
}  // namespace robozoo::replay
