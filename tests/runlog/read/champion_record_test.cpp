// runlog/read/champion_record: a committed compact result's champion, replayed in
// memory, as the run record robozoo-render and robozoo-view draw: one complete
// champion at the generation it won, its pose stream, and with the run's history
// every generation record of the run.
#include "runlog/read/champion_record.hpp"

#include <gtest/gtest.h>

#include <string>

#include "evolve/record/run_results.hpp"

namespace robozoo {
namespace {

const std::string kResult =
    std::string(ROBOZOO_SOURCE_DIR) + "/media/experiment/paper/m2/results/recurrent-s98.results.json";

TEST(ChampionRecord, OneCompleteChampionAtTheGenerationItWon) {
  const RunResults r = read_run_results(kResult);
  const ChampionReplay replay = replay_champion(r, true);
  ASSERT_FALSE(replay.poses.empty());
  const RunRecord run = champion_run_record(replay, kResult);
  EXPECT_EQ(run.source, kResult);
  EXPECT_EQ(run.run.generations, replay.generations);
  ASSERT_EQ(run.genomes.size(), 1u);
  const GenomeRecord& g = *run.genomes.front();
  EXPECT_TRUE(g.champion);
  EXPECT_TRUE(g.has_morphology);
  EXPECT_EQ(g.stream, GenomeRecord::Stream::Complete);
  EXPECT_EQ(g.genome.generation, replay.generation);
  EXPECT_EQ(g.morphology.generation, replay.generation);
  EXPECT_EQ(g.genome.fitness, replay.genome.fitness);
  ASSERT_EQ(g.poses.size(), replay.poses.size());
  EXPECT_EQ(g.pose_count, static_cast<int64_t>(replay.poses.size()));
  EXPECT_EQ(g.last_step, replay.poses.back().step);
  for (const pose_t& p : g.poses) EXPECT_EQ(p.generation, replay.generation);
  EXPECT_EQ(run.find(g.genome.genome_id), &g);
  // Without the history: the generation it won; with it: every generation of the run.
  ASSERT_EQ(run.generations.size(), 1u);
  EXPECT_EQ(run.generations.front().generation, replay.generation);
  const RunRecord whole = champion_run_record(replay, kResult, &r.run);
  ASSERT_EQ(whole.generations.size(), r.run.generations.size());
  for (size_t k = 0; k < whole.generations.size(); ++k) {
    EXPECT_EQ(whole.generations[k].generation, r.run.generations[k].generation);
    EXPECT_EQ(whole.generations[k].best_fitness, r.run.generations[k].best_fitness);
  }
}

TEST(ChampionRecord, WithoutPosesTheChampionHasNoStream) {
  const ChampionReplay replay = replay_champion(read_run_results(kResult), false);
  const RunRecord run = champion_run_record(replay, kResult);
  ASSERT_EQ(run.genomes.size(), 1u);
  EXPECT_EQ(run.genomes.front()->stream, GenomeRecord::Stream::None);
  EXPECT_EQ(run.genomes.front()->last_step, -1);
}

}  // namespace
}  // namespace robozoo
