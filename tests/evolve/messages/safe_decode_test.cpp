#include "evolve/messages/safe_decode.hpp"

#include <gtest/gtest.h>

#include "evolve/core/rng.hpp"
#include "evolve/messages/build.hpp"

namespace robozoo {
namespace {

morphology_t morphology(int spheres, int neurons, int sensors) {
  morphology_t m{};
  m.run_id = "r";
  m.num_spheres = spheres;
  m.spheres.resize(spheres);
  m.num_bodies = 1;
  m.num_neurons = neurons;
  m.tau.assign(neurons, 0.5);
  m.omega.assign(neurons, 0.1);
  m.num_sensors = sensors;
  m.sensor_sphere.assign(sensors, 0);
  m.sensor_type.assign(sensors, 1);
  m.w_sensor_neuron.assign(sensors, std::vector<double>(neurons, 0.25));
  m.w_neuron_neuron.assign(neurons, std::vector<double>(neurons, -0.25));
  return m;
}

pose_t pose(int bodies, int spheres, int neurons, int sensors) {
  pose_t m{};
  m.run_id = "run";
  m.num_bodies = bodies;
  m.body_position.assign(bodies, {1, 2, 3});
  m.body_quaternion.assign(bodies, {1, 0, 0, 0});
  m.num_spheres = spheres;
  m.sphere_center.assign(spheres, {4, 5, 6});
  m.num_neurons = neurons;
  m.neuron_output.assign(neurons, 0.5);
  m.num_sensors = sensors;
  m.sensor_value.assign(sensors, 0.75);
  return m;
}

cppn_genome_t genome(int nodes, int links) {
  cppn_genome_t m{};
  m.run_id = "g";
  m.num_nodes = nodes;
  m.nodes.resize(nodes);
  m.num_links = links;
  m.links.resize(links);
  return m;
}

template <class T>
void expect_walk_matches(const T& m) {
  const auto bytes = encode_message(m);
  std::string why;
  EXPECT_EQ(wire_size(static_cast<const T*>(nullptr), bytes.data(), bytes.size(), &why),
            static_cast<int64_t>(bytes.size()))
      << why;
  T out;
  EXPECT_TRUE(safe_decode(bytes.data(), bytes.size(), out, &why)) << why;
  EXPECT_EQ(encode_message(out), bytes);
}

TEST(SafeDecode, LayoutWalkMatchesEncodedSizeOfEveryType) {
  for (int a : {0, 1, 7})
    for (int b : {0, 2, 5}) {
      expect_walk_matches(morphology(a, b, a + b));
      expect_walk_matches(pose(a, b, a, b));
      expect_walk_matches(genome(a, b));
    }
  run_t r{};
  r.run_id = "x";
  r.software_version = "0.1";
  r.config_json = "{}";
  expect_walk_matches(r);
  generation_t g{};
  g.run_id = "abc";
  expect_walk_matches(g);
  eval_result_t e{};
  expect_walk_matches(e);
}

void put_i32(std::vector<uint8_t>& b, size_t at, int32_t v) {
  for (int i = 0; i < 4; ++i) b[at + i] = static_cast<uint8_t>(static_cast<uint32_t>(v) >> (24 - 8 * i));
}

TEST(SafeDecode, RejectsHugeOrNegativeCountsWithoutAllocating) {
  auto bytes = encode_message(pose(2, 3, 1, 1));
  // num_bodies sits after hash(8) utime(8) run_id(4+4) generation(4) genome_id(8) step(4) sim_time(8).
  const size_t at = 8 + 8 + 4 + 4 + 4 + 8 + 4 + 8;
  for (int32_t bad : {-1, 1 << 30, 3, 0x7fffffff}) {
    auto b = bytes;
    put_i32(b, at, bad);
    pose_t out;
    std::string why;
    EXPECT_FALSE(safe_decode(b.data(), b.size(), out, &why)) << bad;
    EXPECT_FALSE(why.empty());
  }
}

TEST(SafeDecode, RejectsTruncationTrailingBytesAndWrongType) {
  const auto bytes = encode_message(morphology(3, 2, 2));
  morphology_t out;
  std::string why;
  for (size_t cut = 0; cut < bytes.size(); cut += 7) EXPECT_FALSE(safe_decode(bytes.data(), cut, out, &why)) << cut;
  auto longer = bytes;
  longer.push_back(0);
  EXPECT_FALSE(safe_decode(longer.data(), longer.size(), out, &why));
  EXPECT_NE(why.find("after the end"), std::string::npos);
  pose_t wrong;
  EXPECT_FALSE(safe_decode(bytes.data(), bytes.size(), wrong, &why));
  EXPECT_NE(why.find("fingerprint"), std::string::npos);
}

TEST(SafeDecode, RandomGarbageNeverDecodesOrThrows) {
  Rng rng(11);
  const auto good = encode_message(genome(4, 6));
  for (int t = 0; t < 2000; ++t) {
    auto b = good;
    const int flips = 1 + static_cast<int>(rng.uniform_int(0, 4));
    for (int f = 0; f < flips; ++f) b[rng.index(b.size())] ^= static_cast<uint8_t>(1 + rng.uniform_int(0, 254));
    cppn_genome_t out;
    // Must not throw; may decode if only payload bytes changed.
    EXPECT_NO_THROW(safe_decode(b.data(), b.size(), out));
  }
}

// Found by fuzz/messages/fuzz_run_t: LCM's decoder accepts a string with a zero byte
// inside (or without its terminator), and its encoder then cuts the string at
// the first zero, so the message did not re-encode to itself and two logs
// whose config_json differed after such a byte compared equal.
TEST(SafeDecode, RejectsStringsThatWouldNotReencodeToThemselves) {
  run_t m{};
  m.run_id = "run";
  m.software_version = "v";
  m.config_json = "{\"a\":1}";
  const auto good = encode_message(m);
  run_t out;
  std::string why;
  ASSERT_TRUE(safe_decode(good.data(), good.size(), out, &why)) << why;
  // config_json is last: its terminator is the message's last byte.
  auto inside = good;
  inside[good.size() - 3] = 0;
  EXPECT_FALSE(safe_decode(inside.data(), inside.size(), out, &why));
  EXPECT_EQ(why, "config_json: zero byte inside the string");
  auto unterminated = good;
  unterminated.back() = 'x';
  EXPECT_FALSE(safe_decode(unterminated.data(), unterminated.size(), out, &why));
  EXPECT_EQ(why, "config_json: string without its terminating zero byte");
  // run_id of a pose: "run" starts after the fingerprint, utime and length.
  auto p = encode_message(pose(1, 1, 1, 1));
  p[8 + 8 + 4 + 1] = 0;
  pose_t pout;
  EXPECT_FALSE(safe_decode(p.data(), p.size(), pout, &why));
  EXPECT_EQ(why, "run_id: zero byte inside the string");
}

TEST(SafeDecode, AGenomeOfAnOlderRobozooIsNamedAsSuch) {
  // genome_t had no node positions; a log that holds one was written before
  // HyperNEAT's topology rules and cannot be replayed by this robozoo.
  genome_t old{};
  old.run_id = "old";
  old.num_nodes = 1;
  old.nodes.resize(1);
  const auto bytes = encode_message(old);
  cppn_genome_t out;
  std::string why;
  EXPECT_FALSE(safe_decode(bytes.data(), bytes.size(), out, &why));
  EXPECT_NE(why.find("older robozoo"), std::string::npos) << why;
  EXPECT_NE(why.find("cppn_genome_t"), std::string::npos) << why;
  // The new type carries each node's position through the wire.
  cppn_genome_t g = genome(2, 0);
  g.nodes[1].position = 0.625;
  const auto nb = encode_message(g);
  ASSERT_TRUE(safe_decode(nb.data(), nb.size(), out, &why)) << why;
  EXPECT_EQ(out.nodes[1].position, 0.625);
}

}  // namespace
}  // namespace robozoo
