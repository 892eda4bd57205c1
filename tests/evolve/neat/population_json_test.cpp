#include "evolve/neat/population_json.hpp"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>

#include "evolve/neat/xor/xor_task.hpp"

namespace robozoo {
namespace {

using nlohmann::json;

uint64_t bits(double x) {
  uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// Through text: dump() then parse(), as a file would.
json through_text(const json& j) { return json::parse(j.dump()); }

std::vector<double> xor_fitness(const Population& pop) {
  std::vector<double> f;
  for (const auto& g : pop.genomes()) f.push_back(evaluate_xor(g).fitness);
  return f;
}

TEST(PopulationJson, WeightsRoundTripBitForBit) {
  Rng rng(1);
  std::vector<double> values = {0.1,
                                1.0 / 3.0,
                                -2.0 / 3.0,
                                5.0,
                                -5.0,
                                0.0,
                                -0.0,
                                std::numeric_limits<double>::min(),
                                std::numeric_limits<double>::denorm_min(),
                                std::numeric_limits<double>::max(),
                                -DBL_EPSILON,
                                std::nextafter(1.0, 2.0),
                                4.999999999999999};
  for (int i = 0; i < 5000; ++i) values.push_back(rng.uniform(-5.0, 5.0));
  for (int i = 0; i < 1000; ++i) {
    // Arbitrary finite bit patterns.
    double x;
    uint64_t b = rng.next_u64();
    std::memcpy(&x, &b, sizeof x);
    if (std::isfinite(x)) values.push_back(x);
  }
  Genome g;
  g.id = 42;
  g.nodes = {{0, NodeKind::Input, Activation::Linear, 0.0},
             {1, NodeKind::Bias, Activation::Linear, 0.0},
             {2, NodeKind::Output, Activation::SignedSigmoid, 1.0},
             {3, NodeKind::Hidden, Activation::Gaussian},
             {4, NodeKind::Hidden, Activation::SignedCosine}};
  for (size_t k = 0; k < values.size(); ++k)
    g.links.push_back({static_cast<int64_t>(k) * 3 + 1, static_cast<int32_t>(k % 5), 2 + static_cast<int32_t>(k % 3),
                       values[k], k % 7 != 0, static_cast<int32_t>(k % 40)});
  const Genome back = genome_from_json(through_text(genome_to_json(g)));
  ASSERT_EQ(back.links.size(), g.links.size());
  for (size_t k = 0; k < g.links.size(); ++k)
    ASSERT_EQ(bits(back.links[k].weight), bits(g.links[k].weight)) << "value " << values[k];
  EXPECT_EQ(back, g);
  EXPECT_EQ(genome_hash(back), genome_hash(g));
  // nlohmann's ADL hooks use the same format.
  const json j = g;
  EXPECT_EQ(j, genome_to_json(g));
  EXPECT_EQ(through_text(j).get<Genome>(), g);
}

TEST(PopulationJson, GenomeFormatIsReadable) {
  Genome g;
  g.id = 7;
  g.nodes = {{0, NodeKind::Bias, Activation::Linear, 0.0}, {1, NodeKind::Output, Activation::SignedSigmoid, 1.0}};
  g.links = {{0, 0, 1, 0.5, true, 3}};
  const json j = genome_to_json(g);
  EXPECT_EQ(j.at("id"), 7);
  EXPECT_EQ(j.at("nodes").at(0).at("kind"), "bias");
  EXPECT_EQ(j.at("nodes").at(1).at("activation"), "signed_sigmoid");
  EXPECT_EQ(j.at("links").at(0).at("weight"), 0.5);
  EXPECT_EQ(j.at("links").at(0).at("born"), 3);
}

TEST(PopulationJson, PopulationStateRoundTripsAndResumesExactly) {
  NeatParams p;
  Rng rng(2);
  Population pop(p, Regime::Recurrent, xor_layout(), rng);
  for (int gen = 0; gen < 12; ++gen) pop.advance(xor_fitness(pop), rng);
  const json j = through_text(population_state_to_json(pop.state()));
  const PopulationState back = population_state_from_json(j);
  ASSERT_EQ(back, pop.state());
  EXPECT_EQ(j.get<PopulationState>(), pop.state());
  // A checkpoint: state + rng state through text, then both runs continue alike.
  Rng rng2;
  rng2.set_state(rng.state());
  Population resumed(p, Regime::Recurrent, xor_layout(), back);
  for (int gen = 0; gen < 5; ++gen) {
    pop.advance(xor_fitness(pop), rng);
    resumed.advance(xor_fitness(resumed), rng2);
  }
  EXPECT_EQ(resumed.state(), pop.state());
  // Species alone, too.
  const Species& s = pop.species().front();
  EXPECT_EQ(species_from_json(through_text(species_to_json(s))), s);
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no std::invalid_argument)";
}

TEST(PopulationJson, MalformedInputNamesThePath) {
  Genome g;
  g.id = 1;
  g.nodes = {{0, NodeKind::Input, Activation::Linear, 0.0}, {1, NodeKind::Output, Activation::SignedSigmoid, 1.0}};
  g.links = {{0, 0, 1, 0.5, true, 0}, {1, 1, 1, -0.5, true, 0}};
  const json good = genome_to_json(g);

  json j = good;
  j["links"][1].erase("weight");
  EXPECT_EQ(error_of([&] { genome_from_json(j); }), "genome.links[1].weight: missing");
  j = good;
  j["links"][0]["weight"] = "0.5";
  EXPECT_EQ(error_of([&] { genome_from_json(j); }), "genome.links[0].weight: expected a number, got string");
  j = good;
  j["links"][0]["enabled"] = 1;
  EXPECT_EQ(error_of([&] { genome_from_json(j); }), "genome.links[0].enabled: expected true or false, got number");
  j = good;
  j["nodes"][1]["id"] = 1.5;
  EXPECT_EQ(error_of([&] { genome_from_json(j); }), "genome.nodes[1].id: expected an integer, got number");
  j = good;
  j["nodes"][1]["id"] = 1LL << 40;
  EXPECT_NE(error_of([&] { genome_from_json(j); }).find("genome.nodes[1].id: out of range"), std::string::npos);
  j = good;
  j["nodes"][0]["kind"] = "sensor";
  EXPECT_NE(error_of([&] { genome_from_json(j); }).find("genome.nodes[0]: unknown node kind 'sensor'"),
            std::string::npos);
  j = good;
  j["nodes"][0]["activation"] = "relu";
  EXPECT_NE(error_of([&] { genome_from_json(j); }).find("genome.nodes[0]: unknown activation function 'relu'"),
            std::string::npos);
  j = good;
  j["links"] = json::object();
  EXPECT_EQ(error_of([&] { genome_from_json(j); }), "genome.links: expected an array, got object");
  EXPECT_EQ(error_of([&] { genome_from_json(json::array()); }), "genome: expected an object, got array");

  NeatParams p;
  p.population = 10;
  Rng rng(3);
  Population pop(p, Regime::FeedForward, xor_layout(), rng);
  json s = population_state_to_json(pop.state());
  s["species"][0]["representative"]["links"][2].erase("innovation");
  EXPECT_EQ(error_of([&] { population_state_from_json(s); }),
            "population.species[0].representative.links[2].innovation: missing");
  s = population_state_to_json(pop.state());
  s.erase("compatibility_threshold");
  EXPECT_EQ(error_of([&] { population_state_from_json(s); }), "population.compatibility_threshold: missing");
  s = population_state_to_json(pop.state());
  s["species_of"][3] = nullptr;
  EXPECT_EQ(error_of([&] { population_state_from_json(s); }),
            "population.species_of[3]: expected an integer, got null");
}

}  // namespace
}  // namespace robozoo
