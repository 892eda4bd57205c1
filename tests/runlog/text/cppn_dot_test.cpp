#include "runlog/text/cppn_dot.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "util/run_program.hpp"

namespace robozoo {
namespace {

cppn_node_t node(int32_t id, int8_t kind, int8_t activation, double position) {
  cppn_node_t n{};
  n.id = id;
  n.kind = kind;
  n.activation = activation;
  n.position = position;
  return n;
}

link_t link(int64_t innovation, int32_t from, int32_t to, double weight, bool enabled = true) {
  link_t l{};
  l.innovation = innovation;
  l.from_node = from;
  l.to_node = to;
  l.weight = weight;
  l.enabled = enabled;
  return l;
}

cppn_genome_t genome() {
  cppn_genome_t g{};
  g.genome_id = 42;
  g.generation = 3;
  g.fitness = 1.5;
  g.nodes = {node(0, 0, 0, 0.0), node(4, 1, 0, 0.0), node(9, 2, 0, 1.0), node(20, 3, 2, 0.5)};
  g.num_nodes = 4;
  g.links = {link(1, 0, 20, 2.5), link(2, 20, 9, -5.0), link(3, 9, 20, 1.0), link(4, 20, 20, -0.5),
             link(5, 4, 9, 3.0, false)};
  g.num_links = 5;
  return g;
}

TEST(CppnDot, RecurrentMeansAgainstTheDrawingOrder) {
  EXPECT_FALSE(is_recurrent_link(0.0, 0.5));
  EXPECT_TRUE(is_recurrent_link(1.0, 0.5));
  EXPECT_TRUE(is_recurrent_link(0.5, 0.5));  // self-loops and links within a column
}

TEST(CppnDot, ActivationLabels) {
  EXPECT_EQ(activation_label(0), "sigmoid");
  EXPECT_EQ(activation_label(1), "cos");
  EXPECT_EQ(activation_label(2), "gauss");
  EXPECT_EQ(activation_label(9), "act 9");
}

TEST(CppnDot, LinksColouredSizedAndDashedByHand) {
  const std::string dot = cppn_to_dot(genome());
  // weight 2.5 of 5: width 0.6 + 0.5 * 3.4 = 2.30, positive blue, forward (solid)
  EXPECT_NE(dot.find("n0 -> n20 [color=\"#2b6cb0\", penwidth=2.30, tooltip=\"weight 2.5000\"]"), std::string::npos)
      << dot;
  // weight -5: widest, red
  EXPECT_NE(dot.find("n20 -> n9 [color=\"#c53030\", penwidth=4.00, tooltip"), std::string::npos) << dot;
  // output back to hidden: recurrent, dashed, no say in the layout
  EXPECT_NE(dot.find("n9 -> n20 [color=\"#2b6cb0\", penwidth=1.28, style=dashed, constraint=false"), std::string::npos)
      << dot;
  EXPECT_NE(dot.find("n20 -> n20 [color=\"#c53030\", penwidth=0.94, style=dashed"), std::string::npos) << dot;
  EXPECT_NE(dot.find("n4 -> n9 [color=\"#b0b0b0\", style=dotted"), std::string::npos) << dot;
}

TEST(CppnDot, NodesInColumnsByPositionWithLabels) {
  const std::string dot = cppn_to_dot(genome());
  EXPECT_NE(dot.find("{ rank=same; n0; n4; n0 -> n4 [style=invis]; }"), std::string::npos) << dot;
  EXPECT_NE(dot.find("{ rank=same; n20; }"), std::string::npos) << dot;
  EXPECT_NE(dot.find("{ rank=same; n9; }"), std::string::npos) << dot;
  // columns chained in position order: 0 -> 0.5 -> 1
  EXPECT_LT(dot.find("n0 -> n20 [style=invis"), dot.find("n20 -> n9 [style=invis"));
  EXPECT_NE(dot.find("label=\"in 0\""), std::string::npos);
  EXPECT_NE(dot.find("label=\"bias\""), std::string::npos);
  EXPECT_NE(dot.find("label=\"out 0\\nsigmoid\""), std::string::npos);
  EXPECT_NE(dot.find("label=\"h20\\ngauss\""), std::string::npos);
  EXPECT_NE(dot.find("genome 42, generation 3, fitness 1.500"), std::string::npos);
}

TEST(CppnDot, RobozooLayoutGetsTheMethodsNames) {
  cppn_genome_t g{};
  for (int32_t id = 0; id < 9; ++id) g.nodes.push_back(node(id, id == 4 ? 1 : 0, 0, 0.0));
  for (int32_t id = 9; id < 20; ++id) g.nodes.push_back(node(id, 2, 0, 1.0));
  g.num_nodes = 20;
  const std::string dot = cppn_to_dot(g);
  EXPECT_NE(dot.find("n3 [label=\"r_parent\""), std::string::npos) << dot;
  EXPECT_NE(dot.find("n4 [label=\"bias\""), std::string::npos) << dot;
  EXPECT_NE(dot.find("n5 [label=\"s_distance\""), std::string::npos) << dot;
  EXPECT_NE(dot.find("n9 [label=\"m\\nsigmoid\""), std::string::npos) << dot;
  EXPECT_NE(dot.find("n19 [label=\"w\\nsigmoid\""), std::string::npos) << dot;
}

TEST(CppnDot, LinkToAMissingNodeIsAnError) {
  cppn_genome_t g = genome();
  g.links.push_back(link(6, 0, 77, 1.0));
  g.num_links = 6;
  EXPECT_THROW(cppn_to_dot(g), std::invalid_argument);
}

TEST(CppnDot, GraphvizDrawsIt) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto in = dir / "robozoo_cppn_dot_test.dot", out = dir / "robozoo_cppn_dot_test.svg";
  std::ofstream(in) << cppn_to_dot(genome());
  const ProgramResult r = run_program({"dot", "-Tsvg", in.string(), "-o", out.string()});
  EXPECT_EQ(r.status, 0) << r.output;
  std::ifstream svg(out);
  const std::string text((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("stroke-dasharray"), std::string::npos);  // the dashed recurrent links
  std::filesystem::remove(in);
  std::filesystem::remove(out);
}

}  // namespace
}  // namespace robozoo
