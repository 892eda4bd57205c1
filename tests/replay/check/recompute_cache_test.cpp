#include "replay/check/recompute_cache.hpp"

#include <gtest/gtest.h>

namespace robozoo::replay {
namespace {

Genome genes(double w) {
  Genome g;
  g.id = 5;
  const GenomeLayout l = robot_layout();
  for (int i = 0; i < l.num_inputs + l.num_outputs; ++i)
    g.nodes.push_back({i,
                       i == l.bias_input  ? NodeKind::Bias
                       : i < l.num_inputs ? NodeKind::Input
                                          : NodeKind::Output,
                       Activation::SignedSigmoid});
  g.links.push_back({1, 4, 9, w, true, 0});
  return g;
}

TEST(RecomputeCache, FindsTheSameGenesUnderAnyIdAndTheSameConfigurationOnly) {
  RecomputeCache cache;
  RecomputeCache::Entry e;
  e.genes = genes(0.5);
  e.config = "{\"a\":1}";
  e.first_genome_id = 5;
  e.first_generation = 2;
  e.robot.r_term = 3.0;
  const auto& stored = cache.add(e);
  EXPECT_EQ(stored.genes.id, 0);
  Genome copy = genes(0.5);
  copy.id = 77;  // NEAT's copy of a champion under a fresh id
  const auto* hit = cache.find(copy, "{\"a\":1}");
  ASSERT_NE(hit, nullptr);
  EXPECT_EQ(hit->first_genome_id, 5);
  EXPECT_EQ(hit->robot.r_term, 3.0);
  EXPECT_EQ(cache.hits(), 1);
  EXPECT_EQ(cache.find(copy, "{\"a\":2}"), nullptr);
  EXPECT_EQ(cache.find(genes(0.5000000001), "{\"a\":1}"), nullptr);
  EXPECT_EQ(cache.find(genes(-0.0), "{\"a\":1}"), nullptr);
  EXPECT_EQ(cache.size(), 1u);
  EXPECT_EQ(cache.hits(), 1);
}

}  // namespace
}  // namespace robozoo::replay
