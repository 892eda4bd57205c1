#include "evolve/record/checkpoint.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>

#include <nlohmann/json.hpp>

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

// Found by fuzz_checkpoint: an integer field written as a float too large for its
// type (last_champion_hash 1.02872e+20) was converted by a plain cast, undefined
// behaviour. Every integer field now takes JSON integers in its type's range only.
TEST(Checkpoint, IntegerFieldsRefuseFloatsAndOutOfRangeValues) {
  TempDir dir;
  nlohmann::json good = nlohmann::json::parse([&] {
    write_checkpoint(dir / "c", sample());
    return robozoo::testing::read_file(dir / "c");
  }());
  struct Case {
    const char* key;
    nlohmann::json value;
    const char* says;
  };
  const std::vector<Case> cases = {
      {"last_champion_hash", 1.02872e20, "checkpoint.last_champion_hash: expected an integer, got number"},
      {"last_champion_hash", -1, "checkpoint.last_champion_hash: out of range"},
      {"evaluations", 12.5, "checkpoint.evaluations: expected an integer"},
      {"log_bytes", 1e300, "checkpoint.log_bytes: expected an integer"},
      {"log_events", "17", "checkpoint.log_events: expected an integer, got string"},
      {"format_version", 2.0, "checkpoint.format_version: expected an integer"},
      {"finished", 0, "checkpoint.finished: expected true or false"},
      {"best_so_far", "x", "checkpoint.best_so_far: expected a number"},
  };
  for (const Case& k : cases) {
    nlohmann::json bad = good;
    bad[k.key] = k.value;
    std::ofstream(dir / "bad") << bad.dump();
    try {
      read_checkpoint(dir / "bad");
      ADD_FAILURE() << k.key << " = " << k.value.dump() << " was accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(k.says), std::string::npos) << e.what();
    }
  }
  // The largest hash a checkpoint can hold still reads back.
  nlohmann::json top = good;
  top["last_champion_hash"] = UINT64_MAX;
  std::ofstream(dir / "top") << top.dump();
  EXPECT_EQ(read_checkpoint(dir / "top").last_champion_hash, UINT64_MAX);
}

}  // namespace
}  // namespace robozoo
