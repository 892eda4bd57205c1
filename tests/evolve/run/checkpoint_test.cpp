#include "evolve/run/checkpoint.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "evolve/config/run_config.hpp"
#include "evolve/cppn/genome.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using robozoo::testing::TempDir;

Checkpoint sample() {
  RunConfig cfg;
  cfg.neat.population = 12;
  Rng rng(4);
  Population pop(cfg.neat, Regime::Recurrent, robot_layout(), rng);
  std::vector<double> fitness(12);
  for (size_t i = 0; i < fitness.size(); ++i) fitness[i] = 1.0 + 0.1 * static_cast<double>(i);
  pop.advance(fitness, rng);
  Checkpoint c;
  c.run_id = "recurrent-s4";
  c.software_version = "9.9";
  c.config = config_to_json(cfg);
  c.population = pop.state();
  c.rng_state = rng.state();
  c.evaluations = 12;
  c.best_so_far = 2.1;
  c.last_champion_hash = 0xfedcba9876543210ull;
  c.log_bytes = 1234;
  c.log_events = 17;
  c.elapsed_seconds = 3.5;
  return c;
}

TEST(Checkpoint, RoundTripsExactly) {
  TempDir dir;
  const Checkpoint c = sample();
  write_checkpoint(dir / "c", c);
  EXPECT_FALSE(robozoo::testing::file_exists(dir / "c.tmp"));
  const Checkpoint d = read_checkpoint(dir / "c");
  EXPECT_EQ(d.run_id, c.run_id);
  EXPECT_EQ(d.config, c.config);
  EXPECT_TRUE(d.population == c.population);
  EXPECT_EQ(d.rng_state, c.rng_state);
  EXPECT_EQ(d.evaluations, c.evaluations);
  EXPECT_EQ(d.best_so_far, c.best_so_far);
  EXPECT_EQ(d.last_champion_hash, c.last_champion_hash);
  EXPECT_EQ(d.log_bytes, c.log_bytes);
  EXPECT_EQ(d.log_events, c.log_events);
  EXPECT_FALSE(d.finished);
}

TEST(Checkpoint, ReplacingKeepsEitherOldOrNew) {
  TempDir dir;
  Checkpoint c = sample();
  write_checkpoint(dir / "c", c);
  c.evaluations = 24;
  write_checkpoint(dir / "c", c);
  EXPECT_EQ(read_checkpoint(dir / "c").evaluations, 24);
}

TEST(Checkpoint, MalformedFilesAreClearErrors) {
  TempDir dir;
  EXPECT_THROW(read_checkpoint(dir / "missing"), std::runtime_error);
  std::ofstream(dir / "junk") << "{\"format\": \"something else\"}";
  try {
    read_checkpoint(dir / "junk");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("not a robozoo checkpoint"), std::string::npos);
  }
  // A checkpoint of format 1 (before drawing positions) is refused with a clear message.
  std::ofstream(dir / "v1") << "{\"format\": \"robozoo-checkpoint\", \"format_version\": 1}";
  try {
    read_checkpoint(dir / "v1");
    FAIL();
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("format version 1 is not the supported 2"), std::string::npos) << what;
    EXPECT_NE(what.find("older robozoo"), std::string::npos) << what;
  }
  write_checkpoint(dir / "c", sample());
  const std::string text = robozoo::testing::read_file(dir / "c");
  std::ofstream(dir / "cut") << text.substr(0, text.size() / 2);
  EXPECT_THROW(read_checkpoint(dir / "cut"), std::runtime_error);
}

}  // namespace
}  // namespace robozoo
