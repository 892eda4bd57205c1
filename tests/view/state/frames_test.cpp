// The robot frame carries what the page draws of a champion: its spheres, its
// sensors and its CPPN (nodes with drawing positions, links with weights).
#include "view/state/frames.hpp"

#include <gtest/gtest.h>

#include "tests/render/messages.hpp"

namespace robozoo::view {
namespace {

using namespace robozoo::render::testing;

cppn_genome_t genome_with_cppn() {
  cppn_genome_t g = genome_message("run", 3, 42, 17.5);
  g.nodes = {{0, 0, 0, 0.0}, {4, 1, 0, 0.0}, {9, 2, 0, 1.0}, {10, 2, 0, 1.0}, {20, 3, 2, 0.5}};
  g.num_nodes = static_cast<int32_t>(g.nodes.size());
  g.links = {{1, 0, 9, 2.5, true},        // forward, input to output
             {2, 9, 10, -1.23456, true},  // output to output (recurrent)
             {3, 4, 20, 0.5, false},      // disabled
             {4, 20, 20, -4.0, true}};    // self-loop
  g.num_links = static_cast<int32_t>(g.links.size());
  return g;
}

TEST(RobotFrame, CarriesTheGenomesNodesAndLinks) {
  morphology_t m = morphology_message("run", 3, 42);
  m.num_sensors = 2;
  m.sensor_sphere = {0, 2};
  m.sensor_type = {1, 3};
  m.w_sensor_neuron.assign(2, std::vector<double>(static_cast<size_t>(m.num_neurons), 0.0));
  const nlohmann::json j = robot_json(genome_with_cppn(), m, true, false);
  ASSERT_TRUE(j.contains("cppn"));
  const auto& nodes = j["cppn"]["nodes"];
  const auto& links = j["cppn"]["links"];
  ASSERT_EQ(nodes.size(), 5u);
  ASSERT_EQ(links.size(), 4u);
  EXPECT_EQ(nodes[4], (nlohmann::json{{"id", 20}, {"kind", 3}, {"act", 2}, {"pos", 0.5}}));
  EXPECT_EQ(nodes[2]["pos"], 1.0);
  EXPECT_EQ(links[1]["from"], 9);
  EXPECT_EQ(links[1]["to"], 10);
  EXPECT_NEAR(links[1]["w"].get<double>(), -1.2346, 1e-12);  // rounded to 1e-4
  EXPECT_EQ(links[2]["on"], false);
  EXPECT_EQ(links[3]["inn"], 4);
  EXPECT_EQ(j["sensor_sphere"], (nlohmann::json{0, 2}));
  EXPECT_EQ(j["sensor_type"], (nlohmann::json{1, 3}));
}

TEST(RobotFrame, AGenomeWithoutGenesHasAnEmptyCppn) {
  const nlohmann::json j = robot_json(genome_message("run", 0, 1, 1.0), morphology_message("run", 0, 1), false, true);
  EXPECT_TRUE(j["cppn"]["nodes"].empty());
  EXPECT_TRUE(j["cppn"]["links"].empty());
  EXPECT_EQ(j["replay"], true);
}

}  // namespace
}  // namespace robozoo::view
