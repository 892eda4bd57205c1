// The whole-log check on a log from a real short run, then on copies of it with
// one thing changed (written with EventLogWriter, changed messages re-encoded).
#include "replay/check/check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>

#include "tests/replay/replay_fixtures.hpp"

namespace robozoo::replay {
namespace {

using namespace robozoo::testing;

/// The first pose record of the log whose genome is a champion with a trajectory, past step 0.
int64_t some_pose(size_t n = 10) { return nth_on(small_log(), kChannelPose, n); }

TEST(Check, ALogFromARealRunChecksClean) {
  const CheckReport r = check_log_file(small_run_log(), {});
  EXPECT_EQ(r.fatal, "");
  EXPECT_TRUE(r.input_problems.empty());
  ASSERT_EQ(r.champions.size(), 4u);  // one champion per generation
  int64_t poses = 0;
  for (const auto& c : r.champions) {
    EXPECT_EQ(c.status, ChampionResult::Status::Ok) << champion_line(c, false);
    EXPECT_TRUE(c.morphology_logged);
    EXPECT_TRUE(c.fitness_compared);
    EXPECT_EQ(c.logged_fitness, c.recomputed_fitness);
    if (c.poses_logged) {
      EXPECT_EQ(c.poses_logged, c.poses_expected);
    }
    poses += c.poses_compared;
  }
  size_t logged_poses = 0;
  for (const auto& rec : small_log().records) logged_poses += rec.channel == kChannelPose;
  EXPECT_GT(logged_poses, 0u) << "the small run must log a trajectory";
  EXPECT_EQ(poses, static_cast<int64_t>(logged_poses));
  EXPECT_EQ(r.exit_code(), 0);
  ASSERT_EQ(r.runs.size(), 1u);
  EXPECT_EQ(r.runs[0].seed, 7);
}

TEST(Check, OneFlippedBitOfOnePoseNamesChampionStepAndBody) {
  TempDir dir;
  const int64_t target = some_pose();
  ASSERT_GE(target, 0);
  const pose_t original = decode_as<pose_t>(small_log().records[target]);
  ASSERT_GE(original.num_bodies, 1);
  const int body = original.num_bodies - 1;
  write_log(small_log(), dir / "flip.lcmlog", [&](size_t i, LogRecord& r) {
    if (static_cast<int64_t>(i) != target) return true;
    pose_t p = decode_as<pose_t>(r);
    uint64_t bits;
    std::memcpy(&bits, &p.body_position[body][1], 8);
    bits ^= 1;  // the last bit of the mantissa
    std::memcpy(&p.body_position[body][1], &bits, 8);
    r.data = encode_message(p);
    return true;
  });
  const CheckReport r = check_log_file(dir / "flip.lcmlog", {});
  EXPECT_EQ(r.exit_code(), 1);
  int diverged = 0;
  for (const auto& c : r.champions) {
    if (c.status != ChampionResult::Status::Diverged) continue;
    ++diverged;
    EXPECT_EQ(c.genome_id, original.genome_id);
    EXPECT_EQ(c.generation, original.generation);
    EXPECT_EQ(c.mismatch_count, 1);
    EXPECT_EQ(c.poses_diverged, 1);
    EXPECT_EQ(c.first_divergent_step, original.step);
    ASSERT_EQ(c.mismatches.size(), 1u);
    const Mismatch& m = c.mismatches[0];
    EXPECT_EQ(m.what, "pose");
    EXPECT_EQ(m.step, original.step);
    EXPECT_EQ(m.element, "body " + std::to_string(body));
    EXPECT_EQ(m.field, "body_position[" + std::to_string(body) + "][1]");
    EXPECT_EQ(std::stod(m.recomputed), original.body_position[body][1]);
    EXPECT_GT(c.max_error, 0.0);
    EXPECT_LT(c.max_error, 1e-15);
    const std::string line = champion_line(c, false);
    EXPECT_NE(line.find("DIVERGED"), std::string::npos) << line;
    EXPECT_NE(line.find("step " + std::to_string(original.step) + " body " + std::to_string(body)), std::string::npos)
        << line;
  }
  EXPECT_EQ(diverged, 1);
  // Within a tolerance, the same log is clean again.
  CheckOptions loose;
  loose.tolerance = 1e-12;
  EXPECT_EQ(check_log_file(dir / "flip.lcmlog", loose).exit_code(), 0);
}

TEST(Check, AChangedSphereRadiusIsAMorphologyMismatch) {
  TempDir dir;
  const int64_t target = nth_on(small_log(), kChannelMorphology, 1);
  ASSERT_GE(target, 0);
  const morphology_t original = decode_as<morphology_t>(small_log().records[target]);
  const int sphere = original.num_spheres - 1;
  write_log(small_log(), dir / "radius.lcmlog", [&](size_t i, LogRecord& r) {
    if (static_cast<int64_t>(i) != target) return true;
    morphology_t m = decode_as<morphology_t>(r);
    m.spheres[sphere].radius *= 1.5;
    r.data = encode_message(m);
    return true;
  });
  const CheckReport r = check_log_file(dir / "radius.lcmlog", {});
  EXPECT_EQ(r.exit_code(), 1);
  const ChampionResult* hit = nullptr;
  for (const auto& c : r.champions)
    if (c.status == ChampionResult::Status::Diverged) hit = &c;
  ASSERT_NE(hit, nullptr);
  EXPECT_EQ(hit->genome_id, original.genome_id);
  EXPECT_FALSE(hit->morphology_ok);
  ASSERT_EQ(hit->mismatch_count, 1);
  EXPECT_EQ(hit->mismatches[0].what, "morphology");
  EXPECT_EQ(hit->mismatches[0].field, "spheres[" + std::to_string(sphere) + "].radius");
  EXPECT_EQ(std::stod(hit->mismatches[0].recomputed), original.spheres[sphere].radius);
}

TEST(Check, AChangedFitnessIsReported) {
  TempDir dir;
  const int64_t target = nth_on(small_log(), kChannelGenome, 0);
  write_log(small_log(), dir / "fitness.lcmlog", [&](size_t i, LogRecord& r) {
    if (static_cast<int64_t>(i) != target) return true;
    cppn_genome_t g = decode_as<cppn_genome_t>(r);
    g.fitness += 1.0;
    r.data = encode_message(g);
    return true;
  });
  const CheckReport r = check_log_file(dir / "fitness.lcmlog", {});
  EXPECT_EQ(r.exit_code(), 1);
  ASSERT_EQ(r.champions[0].status, ChampionResult::Status::Diverged);
  EXPECT_EQ(r.champions[0].mismatches[0].what, "fitness");
  EXPECT_EQ(r.champions[0].mismatches[0].field, "fitness");
}

TEST(Check, AGenomeReferringToAMissingNodeIsUnusable) {
  TempDir dir;
  const int64_t target = nth_on(small_log(), kChannelGenome, 2);
  write_log(small_log(), dir / "node.lcmlog", [&](size_t i, LogRecord& r) {
    if (static_cast<int64_t>(i) != target) return true;
    cppn_genome_t g = decode_as<cppn_genome_t>(r);
    g.links.back().from_node = 999;
    r.data = encode_message(g);
    return true;
  });
  const CheckReport r = check_log_file(dir / "node.lcmlog", {});
  EXPECT_EQ(r.exit_code(), 2);
  ASSERT_EQ(r.champions.size(), 4u);
  EXPECT_EQ(r.champions[2].status, ChampionResult::Status::Unusable);
  ASSERT_FALSE(r.champions[2].problems.empty());
  EXPECT_NE(r.champions[2].problems[0].find("missing node 999"), std::string::npos) << r.champions[2].problems[0];
  EXPECT_EQ(r.count(ChampionResult::Status::Ok), 3);
}

TEST(Check, AWrongFingerprintIsAnInputProblem) {
  TempDir dir;
  const int64_t target = some_pose(3);
  write_log(small_log(), dir / "fingerprint.lcmlog", [&](size_t i, LogRecord& r) {
    if (static_cast<int64_t>(i) == target) r.data[0] ^= 0x40;
    return true;
  });
  const CheckReport r = check_log_file(dir / "fingerprint.lcmlog", {});
  EXPECT_EQ(r.exit_code(), 2);
  ASSERT_EQ(r.input_problems.size(), 1u);
  EXPECT_EQ(r.input_problems[0].eventnum, target);
  EXPECT_NE(r.input_problems[0].what.find("fingerprint"), std::string::npos) << r.input_problems[0].what;
  // The pose it held is a gap the check cannot call a divergence: that champion's
  // trajectory is unprovable (exit 2), every other champion is ok.
  EXPECT_TRUE(r.structure.empty()) << format_text(r);
  int unusable = 0;
  for (const auto& c : r.champions) {
    if (c.status == ChampionResult::Status::Unusable) {
      ++unusable;
      ASSERT_FALSE(c.problems.empty());
      EXPECT_NE(c.problems[0].find("cannot be proved complete"), std::string::npos) << c.problems[0];
    } else {
      EXPECT_EQ(c.status, ChampionResult::Status::Ok) << champion_line(c, false);
    }
  }
  EXPECT_EQ(unusable, 1);
}

std::vector<uint8_t> bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void put(const std::string& path, const std::vector<uint8_t>& b) {
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
}

TEST(Check, ATruncatedLogIsReportedAndWhatRemainsIsChecked) {
  TempDir dir;
  std::vector<uint8_t> b = bytes_of(small_run_log());
  b.resize(b.size() * 2 / 3);
  put(dir / "cut.lcmlog", b);
  const CheckReport r = check_log_file(dir / "cut.lcmlog", {});
  EXPECT_EQ(r.exit_code(), 2) << format_text(r);
  ASSERT_FALSE(r.input_problems.empty());
  bool cut = false, incomplete = false;
  for (const auto& p : r.input_problems) {
    cut = cut || p.what.find("ends inside an event") != std::string::npos;
    incomplete = incomplete || p.what.find("the log ends before generation") != std::string::npos;
  }
  // Where the cut falls decides how the cut generation is reported: before its genome or
  // morphology as an incomplete generation, inside its champion's trajectory as a trajectory
  // with fewer poses than it has. Either way as input, never as a divergence.
  bool cut_trajectory = false;
  for (const auto& c : r.champions) {
    EXPECT_NE(c.status, ChampionResult::Status::Diverged) << champion_line(c, false);
    cut_trajectory = cut_trajectory || (c.poses_logged > 0 && c.poses_logged < c.poses_expected);
  }
  EXPECT_TRUE(cut) << format_text(r);
  EXPECT_TRUE(incomplete || cut_trajectory)
      << "the cut generation is reported as incomplete input, not as a divergence\n"
      << format_text(r);
  EXPECT_TRUE(r.structure.empty()) << format_text(r);
  EXPECT_FALSE(r.champions.empty());
  for (const auto& c : r.champions) EXPECT_NE(c.status, ChampionResult::Status::Diverged) << champion_line(c, false);
}

TEST(Check, GarbageInTheMiddleIsSkippedAndReported) {
  TempDir dir;
  const ScannedLog clean = scan_event_log(small_run_log());
  std::vector<uint8_t> b = bytes_of(small_run_log());
  const int64_t at = clean.offsets[clean.offsets.size() / 2];
  const std::vector<uint8_t> garbage(1000, 0x5A);
  b.insert(b.begin() + at, garbage.begin(), garbage.end());
  put(dir / "garbage.lcmlog", b);
  const CheckReport r = check_log_file(dir / "garbage.lcmlog", {});
  EXPECT_EQ(r.exit_code(), 2);
  ASSERT_EQ(r.input_problems.size(), 1u);
  EXPECT_NE(r.input_problems[0].what.find("1000 bytes"), std::string::npos) << r.input_problems[0].what;
  EXPECT_NE(r.input_problems[0].what.find(std::to_string(at)), std::string::npos) << r.input_problems[0].what;
  EXPECT_EQ(r.events, static_cast<int64_t>(clean.contents.records.size()));
  for (const auto& c : r.champions) EXPECT_EQ(c.status, ChampionResult::Status::Ok);
}

TEST(Check, AnotherSoftwareVersionIsRefusedUnlessForced) {
  TempDir dir;
  write_log(small_log(), dir / "version.lcmlog", [&](size_t, LogRecord& r) {
    if (r.channel != kChannelRun) return true;
    run_t m = decode_as<run_t>(r);
    m.software_version = "9.9.9";
    r.data = encode_message(m);
    return true;
  });
  const CheckReport refused = check_log_file(dir / "version.lcmlog", {});
  EXPECT_EQ(refused.exit_code(), 2);
  EXPECT_NE(refused.fatal.find("9.9.9"), std::string::npos) << refused.fatal;
  EXPECT_TRUE(refused.champions.empty());
  CheckOptions force;
  force.force = true;
  const CheckReport forced = check_log_file(dir / "version.lcmlog", force);
  EXPECT_EQ(forced.exit_code(), 0) << format_text(forced);
  EXPECT_TRUE(forced.forced);
  EXPECT_NE(format_text(forced).find("note: --force: run feedforward-s7 (robozoo 9.9.9)"), std::string::npos)
      << format_text(forced);
}

TEST(Check, TheConfigurationComesFromTheLogNotFromDefaults) {
  TempDir dir;
  // The small run simulates 400 steps; a check with the default 2,500 would diverge.
  // Removing the key makes the log unusable rather than silently defaulted.
  write_log(small_log(), dir / "nosteps.lcmlog", [&](size_t, LogRecord& r) {
    if (r.channel != kChannelRun) return true;
    run_t m = decode_as<run_t>(r);
    nlohmann::json j = nlohmann::json::parse(m.config_json);
    j["sim"].erase("steps");
    m.config_json = j.dump();
    r.data = encode_message(m);
    return true;
  });
  const CheckReport r = check_log_file(dir / "nosteps.lcmlog", {});
  EXPECT_EQ(r.exit_code(), 2);
  EXPECT_NE(r.fatal.find("sim.steps"), std::string::npos) << r.fatal;
}

TEST(Check, NoRunMessageOrNoFileIsFatal) {
  TempDir dir;
  write_log(small_log(), dir / "norun.lcmlog", [](size_t, LogRecord& r) { return r.channel != kChannelRun; });
  const CheckReport r = check_log_file(dir / "norun.lcmlog", {});
  EXPECT_EQ(r.exit_code(), 2);
  EXPECT_NE(r.fatal.find("no ROBOZOO_RUN"), std::string::npos) << r.fatal;
  const CheckReport missing = check_log_file(dir / "absent.lcmlog", {});
  EXPECT_EQ(missing.exit_code(), 2);
  EXPECT_NE(missing.fatal.find("absent.lcmlog"), std::string::npos) << missing.fatal;
}

/// The small log with its first champion's genome and morphology logged again
/// under a fresh id, as NEAT does when a champion stays best; `fitness_delta`
/// is added to the copy's logged fitness.
LogContents with_champion_copy(double fitness_delta) {
  LogContents log = small_log();
  const LogRecord genome = log.records[nth_on(log, kChannelGenome, 0)];
  const LogRecord morphology = log.records[nth_on(log, kChannelMorphology, 0)];
  cppn_genome_t g = decode_as<cppn_genome_t>(genome);
  morphology_t m = decode_as<morphology_t>(morphology);
  g.genome_id = m.genome_id = 424242;
  g.generation = m.generation = 9;  // a generation with no generation_t: its genome counts as its champion
  g.fitness += fitness_delta;
  LogRecord a = genome, b = morphology;
  a.data = encode_message(g);
  b.data = encode_message(m);
  log.records.push_back(a);
  log.records.push_back(b);
  return log;
}

TEST(Check, RepeatedGenesAreRecomputedOnceButStillCompared) {
  TempDir dir;
  write_log(with_champion_copy(0.0), dir / "copy.lcmlog");
  const CheckReport r = check_log_file(dir / "copy.lcmlog", {});
  // The copy sits where evolve never writes a genome: a message difference, while
  // its own re-computation (from the cache) agrees.
  EXPECT_EQ(r.exit_code(), 1) << format_text(r);
  ASSERT_FALSE(r.structure.empty());
  EXPECT_EQ(r.structure[0].channel, kChannelGenome);
  EXPECT_EQ(r.structure[0].generation, 9);
  ASSERT_EQ(r.champions.size(), 5u);
  for (const auto& c : r.champions) EXPECT_EQ(c.status, ChampionResult::Status::Ok) << champion_line(c, false);
  EXPECT_EQ(r.champions[4].genome_id, 424242);
  EXPECT_EQ(r.champions[4].same_genes_as, r.champions[0].genome_id);
  EXPECT_TRUE(r.champions[4].morphology_ok);
  write_log(with_champion_copy(0.5), dir / "copy_bad.lcmlog");
  const CheckReport bad = check_log_file(dir / "copy_bad.lcmlog", {});
  EXPECT_EQ(bad.exit_code(), 1);
  EXPECT_EQ(bad.champions[4].status, ChampionResult::Status::Diverged);
  EXPECT_EQ(bad.champions[4].mismatches.at(0).field, "fitness");
}

TEST(Check, ProgressIsReportedPerGenome) {
  std::vector<std::pair<size_t, size_t>> calls;
  check_log_file(small_run_log(), {}, [&](size_t done, size_t total) { calls.emplace_back(done, total); });
  ASSERT_EQ(calls.size(), 4u);
  EXPECT_EQ(calls.back(), std::make_pair(size_t{4}, size_t{4}));
}

}  // namespace
}  // namespace robozoo::replay
