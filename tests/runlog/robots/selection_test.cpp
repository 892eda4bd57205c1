#include "runlog/robots/selection.hpp"

#include <gtest/gtest.h>

#include "runlog/read/message_collector.hpp"
#include "tests/render/messages.hpp"

namespace robozoo {
namespace {

using namespace robozoo::render::testing;

// A run whose champions have these fitnesses, generation by generation; the
// genome of generation g has id 100 + g and a link weight `genes[g]`.
std::unique_ptr<MessageCollector> run_with(const std::string& id, std::vector<double> fitness,
                                           std::vector<double> genes) {
  auto c = std::make_unique<MessageCollector>();
  auto send = [&](const char* ch, const auto& m) {
    const auto b = encode_message(m);
    c->ingest(ch, b.data(), b.size());
  };
  send(kChannelRun, run_message(id));
  for (size_t g = 0; g < fitness.size(); ++g) {
    const int64_t gid = 100 + static_cast<int64_t>(g);
    send(kChannelGeneration, generation_message(id, static_cast<int32_t>(g), gid));
    cppn_genome_t gm = genome_message(id, static_cast<int32_t>(g), gid, fitness[g]);
    link_t l{};
    l.innovation = 1;
    l.weight = genes[g];
    gm.links.push_back(l);
    gm.num_links = 1;
    send(kChannelGenome, gm);
    send(kChannelMorphology, morphology_message(id, static_cast<int32_t>(g), gid));
  }
  return c;
}

std::vector<int64_t> ids(const std::vector<Pick>& p) {
  std::vector<int64_t> out;
  for (const Pick& x : p) out.push_back(x.genome->genome.genome_id);
  return out;
}

TEST(Selection, BestOfRunTopAndGeneration) {
  auto a = run_with("a", {5, 15, 17, 17, 16}, {1, 2, 3, 3, 4});  // generation 3 copies generation 2
  auto b = run_with("b", {5, 20}, {1, 2});
  const std::vector<const RunRecord*> runs = {a->runs()[0].get(), b->runs()[0].get()};
  EXPECT_EQ(ids(best_of_run(runs)), (std::vector<int64_t>{102, 101}));                 // ties: the earliest
  EXPECT_EQ(ids(top_champions({runs[0]}, 3)), (std::vector<int64_t>{102, 104, 101}));  // copy counted once
  EXPECT_EQ(ids(top_champions({runs[0]}, 100)).size(), 4u);
  EXPECT_EQ(ids(generation_champions(runs, 1)), (std::vector<int64_t>{101, 101}));
  EXPECT_EQ(ids(generation_champions(runs, 4)), (std::vector<int64_t>{104}));
  EXPECT_TRUE(generation_champions(runs, 9).empty());
  EXPECT_EQ(ids(genome_by_id(runs, 103)), (std::vector<int64_t>{103}));
  EXPECT_EQ(champions(*runs[0]).size(), 5u);
}

TEST(Selection, GeneHashIgnoresIdsAndScores) {
  cppn_genome_t x = genome_message("r", 0, 1, 1.0), y = genome_message("r", 5, 2, 9.0);
  EXPECT_EQ(gene_hash(x), gene_hash(y));
  link_t l{};
  l.weight = 0.5;
  y.links.push_back(l);
  EXPECT_NE(gene_hash(x), gene_hash(y));
}

}  // namespace
}  // namespace robozoo
