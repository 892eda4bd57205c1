#include "evolve/neat/population.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

#include "evolve/neat/xor/xor_task.hpp"

namespace robozoo {
namespace {

std::vector<double> xor_fitness(const Population& pop) {
  std::vector<double> f;
  for (const auto& g : pop.genomes()) f.push_back(evaluate_xor(g).fitness);
  return f;
}

uint64_t population_hash(const Population& pop) {
  uint64_t h = 0;
  for (const auto& g : pop.genomes()) h = h * 1000003u ^ genome_hash(g);
  for (size_t i = 0; i < pop.genomes().size(); ++i) h = h * 31u + static_cast<uint64_t>(pop.species_of(i));
  return h;
}

bool same_genes(const Genome& a, const Genome& b) { return a.nodes == b.nodes && a.links == b.links; }

TEST(Population, GenerationZero) {
  NeatParams p;
  Rng rng(1);
  Population pop(p, Regime::FeedForward, xor_layout(), rng);
  ASSERT_EQ(pop.genomes().size(), 150u);
  EXPECT_EQ(pop.generation(), 0);
  for (size_t i = 0; i < pop.genomes().size(); ++i) {
    EXPECT_EQ(pop.genomes()[i].id, static_cast<int64_t>(i));
    validate_genome(pop.genomes()[i], xor_layout());
  }
  size_t members = 0;
  for (const auto& s : pop.species()) {
    members += s.members.size();
    for (int m : s.members) EXPECT_EQ(pop.species_of(static_cast<size_t>(m)), s.id);
  }
  EXPECT_EQ(members, 150u);
}

TEST(Population, ChampionIsCopiedUnchangedAndIdsIncrease) {
  NeatParams p;
  Rng rng(2);
  Population pop(p, Regime::FeedForward, xor_layout(), rng);
  int64_t max_id = 149;
  for (int gen = 0; gen < 15; ++gen) {
    const std::vector<Genome> before = pop.genomes();
    const std::vector<double> f = xor_fitness(pop);
    pop.advance(f, rng);
    const GenerationReport& rep = pop.last_report();
    size_t best = 0;
    for (size_t i = 1; i < f.size(); ++i)
      if (f[i] > f[best]) best = i;
    EXPECT_EQ(rep.champion, best);
    EXPECT_EQ(rep.champion_fitness, f[best]);
    ASSERT_TRUE(same_genes(pop.genomes()[0], before[best])) << "generation " << gen;
    for (const auto& g : pop.genomes()) {
      EXPECT_GT(g.id, max_id);
      max_id = g.id;
    }
    EXPECT_EQ(pop.generation(), gen + 1);
  }
}

TEST(Population, OffspringSumToPopulationAndBigSpeciesKeepTheirChampion) {
  NeatParams p;
  Rng rng(3);
  Population pop(p, Regime::FeedForward, xor_layout(), rng);
  int elite_checks = 0;
  for (int gen = 0; gen < 25; ++gen) {
    const std::vector<Genome> before = pop.genomes();
    const std::vector<Species> species = pop.species();
    const std::vector<double> f = xor_fitness(pop);
    pop.advance(f, rng);
    const GenerationReport& rep = pop.last_report();
    ASSERT_EQ(rep.offspring.size(), species.size());
    int total = 0;
    for (int c : rep.offspring) total += c;
    ASSERT_EQ(total, p.population);
    for (size_t si = 0; si < species.size(); ++si) {
      if (rep.offspring[si] < p.species_elitism_min_offspring) continue;
      // The species champion: its best member (first in population order on ties).
      int champ = species[si].members.front();
      for (int m : species[si].members)
        if (f[static_cast<size_t>(m)] > f[static_cast<size_t>(champ)]) champ = m;
      bool found = false;
      for (const auto& g : pop.genomes()) found |= same_genes(g, before[static_cast<size_t>(champ)]);
      EXPECT_TRUE(found) << "species " << species[si].id << " lost its champion";
      ++elite_checks;
    }
  }
  EXPECT_GT(elite_checks, 50);
}

TEST(Population, SameSeedSamePopulationDifferentSeedDifferent) {
  NeatParams p;
  auto run = [&](uint64_t seed, Regime regime) {
    Rng rng(seed);
    Population pop(p, regime, xor_layout(), rng);
    for (int gen = 0; gen < 20; ++gen) pop.advance(xor_fitness(pop), rng);
    return std::make_pair(population_hash(pop), rng.next_u64());
  };
  for (Regime regime : {Regime::FeedForward, Regime::Recurrent}) {
    const auto a = run(17, regime), b = run(17, regime), c = run(18, regime);
    EXPECT_EQ(a, b);
    EXPECT_NE(a.first, c.first);
  }
}

TEST(Population, ResumesFromItsStateExactly) {
  NeatParams p;
  Rng rng(5);
  Population pop(p, Regime::Recurrent, xor_layout(), rng);
  for (int gen = 0; gen < 6; ++gen) pop.advance(xor_fitness(pop), rng);
  const PopulationState saved = pop.state();
  const std::string rng_state = rng.state();
  for (int gen = 0; gen < 8; ++gen) pop.advance(xor_fitness(pop), rng);

  Rng rng2;
  rng2.set_state(rng_state);
  Population resumed(p, Regime::Recurrent, xor_layout(), saved);
  for (int gen = 0; gen < 8; ++gen) resumed.advance(xor_fitness(resumed), rng2);
  EXPECT_EQ(resumed.state(), pop.state());
  EXPECT_EQ(population_hash(resumed), population_hash(pop));
}

TEST(Population, RejectsBadFitness) {
  NeatParams p;
  p.population = 20;
  Rng rng(6);
  Population pop(p, Regime::FeedForward, xor_layout(), rng);
  std::vector<double> f(20, 1.0);
  f[3] = -0.5;
  EXPECT_THROW(pop.advance(f, rng), std::invalid_argument);
  f[3] = std::nan("");
  EXPECT_THROW(pop.advance(f, rng), std::invalid_argument);
  EXPECT_THROW(pop.advance(std::vector<double>(19, 1.0), rng), std::invalid_argument);
  EXPECT_EQ(pop.generation(), 0);
  pop.advance(std::vector<double>(20, 0.0), rng);  // all zero is allowed
  EXPECT_EQ(pop.generation(), 1);
}

TEST(Population, StagnantSpeciesDropOff) {
  // Equal fitness for all: only the champion's species (the first genome's)
  // ever counts as improving after its first generation; others stagnate
  // after dropoff_age generations and lose their offspring. (robozoo's
  // mechanics: HyperNEAT's stagnation and rounding are tested in
  // hyperneat_test.cpp.)
  NeatParams p;
  apply_neat_mechanics(p, NeatMechanics::Robozoo);
  Rng rng(7);
  Population pop(p, Regime::FeedForward, xor_layout(), rng);
  int stagnant_seen = 0;
  for (int gen = 0; gen < 60; ++gen) {
    const int32_t champion_species = pop.species_of(0);
    pop.advance(std::vector<double>(150, 1.0), rng);
    const GenerationReport& rep = pop.last_report();
    EXPECT_EQ(rep.champion, 0u);
    for (size_t si = 0; si < rep.species_ids.size(); ++si) {
      if (rep.species_ids[si] == champion_species) {
        EXPECT_FALSE(rep.stagnant[si]);
      }
      if (rep.stagnant[si]) {
        ++stagnant_seen;
        EXPECT_EQ(rep.offspring[si], 0);
        EXPECT_NEAR(rep.adjusted[si], 0.001, 1e-15);
      }
    }
  }
  EXPECT_GT(stagnant_seen, 0);
}

TEST(Population, StructureStaysConsistent) {
  // Over a run: feed-forward genomes never have a cycle, an innovation number
  // always names the same link, a node id always the same node gene.
  for (Regime regime : {Regime::FeedForward, Regime::Recurrent}) {
    NeatParams p;
    p.add_link_probability = 0.3;
    p.add_node_probability = 0.1;
    Rng rng(8);
    Population pop(p, regime, xor_layout(), rng);
    std::map<int64_t, std::pair<int32_t, int32_t>> links;
    std::map<int32_t, NodeGene> nodes;
    int cyclic = 0;
    for (int gen = 0; gen < 30; ++gen) {
      for (const auto& g : pop.genomes()) {
        validate_genome(g, xor_layout());
        const bool cycle = has_cycle(g);
        cyclic += cycle;
        if (regime == Regime::FeedForward) {
          ASSERT_FALSE(cycle);
        }
        for (const auto& l : g.links) {
          const auto [it, fresh] = links.emplace(l.innovation, std::make_pair(l.from, l.to));
          ASSERT_EQ(it->second, std::make_pair(l.from, l.to)) << "innovation " << l.innovation;
          (void)fresh;
        }
        for (const auto& n : g.nodes) {
          const auto [it, fresh] = nodes.emplace(n.id, n);
          ASSERT_EQ(it->second, n) << "node " << n.id;
          (void)fresh;
        }
      }
      pop.advance(xor_fitness(pop), rng);
    }
    if (regime == Regime::Recurrent) {
      EXPECT_GT(cyclic, 0);
    }
  }
}

TEST(Population, ValidatesParametersAndStates) {
  NeatParams p;
  Rng rng(9);
  NeatParams bad = p;
  bad.population = 0;
  EXPECT_THROW(Population(bad, Regime::FeedForward, xor_layout(), rng), std::invalid_argument);
  bad = p;
  bad.hidden_activations = 0;
  EXPECT_THROW(Population(bad, Regime::FeedForward, xor_layout(), rng), std::invalid_argument);
  bad = p;
  bad.survival_threshold = 1.5;
  EXPECT_THROW(Population(bad, Regime::FeedForward, xor_layout(), rng), std::invalid_argument);

  Population pop(p, Regime::FeedForward, xor_layout(), rng);
  PopulationState s = pop.state();
  EXPECT_NO_THROW(Population(p, Regime::FeedForward, xor_layout(), s));
  NeatParams smaller = p;
  smaller.population = 100;
  EXPECT_THROW(Population(smaller, Regime::FeedForward, xor_layout(), s), std::invalid_argument);
  s.species_of.pop_back();
  EXPECT_THROW(Population(p, Regime::FeedForward, xor_layout(), s), std::invalid_argument);
  s = pop.state();
  s.next_genome_id = 10;
  EXPECT_THROW(Population(p, Regime::FeedForward, xor_layout(), s), std::invalid_argument);
  s = pop.state();
  s.species[0].members.push_back(s.species[0].members[0]);
  EXPECT_THROW(Population(p, Regime::FeedForward, xor_layout(), s), std::invalid_argument);
}

}  // namespace
}  // namespace robozoo
