// robozoo-replay as a user runs it, on a log written by robozoo-evolve itself.
#include <fcntl.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/replay/replay_fixtures.hpp"

namespace robozoo::replay {
namespace {

using namespace robozoo::testing;

/// A short run by robozoo-evolve with two worker processes, made once.
const std::string& evolve_log() {
  static TempDir dir;
  static const std::string path = [] {
    const std::string p = dir / "run.lcmlog";
    const auto o = run_shell(bin("robozoo-evolve") + " --log '" + p +
                             "' --workers 2 --seed 7 --population 24 --generations 4 --steps 400 --quiet "
                             "--set growth.bias_input=1.0");  // M1/M2's bias input: feed-forward robots grow
    if (o.status != 0) throw std::runtime_error("robozoo-evolve failed: " + o.output);
    return p;
  }();
  return path;
}

testing::Outcome replay(const std::string& args) { return run_shell(bin("robozoo-replay") + " " + args); }

TEST(ReplayCli, HelpNamesTheSubcommandsAndTheirOptions) {
  const auto o = replay("--help");
  EXPECT_EQ(o.status, 0);
  for (const char* s : {"check", "play", "sim"}) EXPECT_NE(o.output.find(s), std::string::npos) << s;
  const auto c = replay("check --help");
  for (const char* s : {"--tolerance", "--json", "--force", "--all-genomes", "--progress"})
    EXPECT_NE(c.output.find(s), std::string::npos) << s;
  const auto p = replay("play --help");
  for (const char* s : {"--lcm-url", "--speed", "--channels", "--loop", "--start-generation"})
    EXPECT_NE(p.output.find(s), std::string::npos) << s;
  const auto s = replay("sim --help");
  for (const char* f : {"--genome", "--lcm-url", "--speed"}) EXPECT_NE(s.output.find(f), std::string::npos) << f;
  EXPECT_EQ(replay("").status, 2);  // a subcommand is required
}

TEST(ReplayCli, ALogOfRobozooEvolveChecksClean) {
  const auto o = replay("check '" + evolve_log() + "'");
  EXPECT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("4 genomes checked: 4 ok, 0 diverged, 0 unusable"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("bit for bit"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("checking ["), std::string::npos) << "no progress bar when stderr is no terminal";
  const auto bar = replay("check --progress '" + evolve_log() + "'");
  EXPECT_NE(bar.output.find("checking ["), std::string::npos) << bar.output;
  EXPECT_EQ(replay("check -q '" + evolve_log() + "'").output, "");
}

TEST(ReplayCli, JsonReportParses) {
  const auto o = replay("check --json '" + evolve_log() + "'");
  EXPECT_EQ(o.status, 0) << o.output;
  const auto j = nlohmann::json::parse(o.output);
  EXPECT_EQ(j["summary"]["exit_code"], 0);
  EXPECT_EQ(j["summary"]["ok"], 4);
  EXPECT_EQ(j["runs"][0]["seed"], 7);
  EXPECT_EQ(j["champions"].size(), 4u);
}

TEST(ReplayCli, ADivergenceExitsOneAndNamesIt) {
  TempDir dir;
  const LogContents log = read_event_log(evolve_log());
  const int64_t target = nth_on(log, kChannelPose, 5);
  ASSERT_GE(target, 0);
  const pose_t original = decode_as<pose_t>(log.records[target]);
  write_log(log, dir / "flip.lcmlog", [&](size_t i, LogRecord& r) {
    if (static_cast<int64_t>(i) != target) return true;
    pose_t p = decode_as<pose_t>(r);
    p.sensor_value.at(0) = -p.sensor_value.at(0) - 1.0;
    r.data = encode_message(p);
    return true;
  });
  const auto o = replay("check '" + (dir / "flip.lcmlog") + "'");
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("DIVERGED gen " + std::to_string(original.generation) + "  genome " +
                          std::to_string(original.genome_id)),
            std::string::npos)
      << o.output;
  EXPECT_NE(o.output.find("pose step " + std::to_string(original.step) + " sensor 0 sensor_value[0]"),
            std::string::npos)
      << o.output;
}

TEST(ReplayCli, UnusableInputExitsTwoWithoutACrash) {
  TempDir dir;
  const auto missing = replay("check '" + (dir / "nothing.lcmlog") + "'");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.output.find("nothing.lcmlog"), std::string::npos) << missing.output;
  run_shell("head -c 100000 /dev/urandom > '" + (dir / "noise.lcmlog") + "'");
  const auto noise = replay("check '" + (dir / "noise.lcmlog") + "'");
  EXPECT_EQ(noise.status, 2) << noise.output;
  EXPECT_NE(noise.output.find("UNUSABLE"), std::string::npos) << noise.output;
  run_shell("head -c -500 '" + evolve_log() + "' > '" + (dir / "cut.lcmlog") + "'");
  const auto cut = replay("check '" + (dir / "cut.lcmlog") + "'");
  EXPECT_EQ(cut.status, 2) << cut.output;
  EXPECT_NE(cut.output.find("ends inside an event"), std::string::npos) << cut.output;
  EXPECT_EQ(replay("check --tolerance -1 '" + evolve_log() + "'").status, 2);
}

TEST(ReplayCli, PlayAndSimRefuseBadInputWithExitTwo) {
  TempDir dir;
  const auto regex = replay("play '" + evolve_log() + "' --lcm-url memq:// --channels 'ROBOZOO_('");
  EXPECT_EQ(regex.status, 2);
  EXPECT_NE(regex.output.find("not a regular expression"), std::string::npos) << regex.output;
  const auto gen = replay("play '" + evolve_log() + "' --lcm-url memq:// --start-generation 99");
  EXPECT_EQ(gen.status, 2);
  EXPECT_NE(gen.output.find("last generation is 3"), std::string::npos) << gen.output;
  const auto genome = replay("sim '" + evolve_log() + "' --lcm-url memq:// --genome 123456");
  EXPECT_EQ(genome.status, 2);
  EXPECT_NE(genome.output.find("not in the log"), std::string::npos) << genome.output;
  EXPECT_EQ(replay("sim '" + (dir / "none.lcmlog") + "' --genome 1").status, 2);
}

TEST(ReplayCli, PlayAndSimRunToTheEndOnAnInProcessBus) {
  const auto play = replay("play '" + evolve_log() + "' --lcm-url memq:// --speed 1000");
  EXPECT_EQ(play.status, 0) << play.output;
  EXPECT_NE(play.output.find("in 1 pass"), std::string::npos) << play.output;
  const LogContents log = read_event_log(evolve_log());
  const cppn_genome_t champion = decode_as<cppn_genome_t>(log.records[nth_on(log, kChannelGenome, 3)]);
  const auto sim = replay("sim '" + evolve_log() + "' --lcm-url memq:// --speed 1000 --genome " +
                          std::to_string(champion.genome_id));
  EXPECT_EQ(sim.status, 0) << sim.output;
  EXPECT_NE(sim.output.find("re-simulated genome " + std::to_string(champion.genome_id)), std::string::npos)
      << sim.output;
}

}  // namespace
}  // namespace robozoo::replay
