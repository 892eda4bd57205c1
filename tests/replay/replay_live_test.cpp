// robozoo-replay on a real LCM bus: play and sim recorded by LCM's own
// lcm-logger inside a private network namespace (docs/method.md section 5). Runs
// alone (RUN_SERIAL): a starved subscriber drops multicast packets.
#include <fcntl.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <iostream>
#include <regex>

#include "evolve/io/log_compare.hpp"
#include "tests/replay/replay_fixtures.hpp"

namespace robozoo::replay {
namespace {

using namespace robozoo::testing;

const std::string kUrl = "udpm://239.255.76.67:7667?ttl=0";

/// Runs `command` (a robozoo-replay command line, quoted for sh) while lcm-logger
/// records the bus into `recording`; returns robozoo-replay's outcome.
testing::Outcome recorded(const std::string& command, const std::string& recording) {
  const std::string script =
      "ip link set lo up && ip route add 224.0.0.0/4 dev lo && "
      "(lcm-logger -f --lcm-url='" +
      kUrl + "&recv_buf_size=4194304' '" + recording + "' >/dev/null 2>&1 & L=\\$!; sleep 1; " + command +
      "; S=\\$?; sleep 1; kill -INT \\$L; wait \\$L; exit \\$S)";
  return run_shell("timeout 120 unshare -n sh -c \"" + script + "\"");
}

/// lcm-logger 1.3.1 now and then loses a stretch of a burst in user space: LCM
/// keeps at most 31 undispatched messages for its subscription and drops what
/// arrives beyond (README, "What a log holds"), and --speed 50 sends a
/// trajectory's poses under a millisecond apart. So a recording with fewer robozoo events than
/// `expected` is made again, up to `attempts` times; the checks then run on the
/// last recording, and a publisher that really loses or adds events fails them.
testing::Outcome recorded_completely(const std::string& command, const std::string& recording, size_t expected,
                                     const std::string& channels, int attempts = 4);

std::string replay_cmd(const std::string& args) { return "'" + bin("robozoo-replay") + "' " + args; }

/// The robozoo events of `log` whose channel matches `regex`, as (channel, bytes).
std::vector<std::pair<std::string, std::vector<uint8_t>>> events(const LogContents& log, const std::string& regex) {
  std::vector<std::pair<std::string, std::vector<uint8_t>>> out;
  const std::regex re(regex);
  for (const auto& r : log.records)
    if (std::regex_match(r.channel, re)) out.emplace_back(r.channel, r.data);
  return out;
}

testing::Outcome recorded_completely(const std::string& command, const std::string& recording, size_t expected,
                                     const std::string& channels, int attempts) {
  testing::Outcome o;
  for (int attempt = 1; attempt <= attempts; ++attempt) {
    std::remove(recording.c_str());
    o = recorded(command, recording);
    if (o.status != 0) return o;
    const size_t got = events(read_event_log(recording), channels).size();
    if (got == expected) return o;
    std::cerr << "attempt " << attempt << ": lcm-logger recorded " << got << " of " << expected
              << " events; recording again\n";
  }
  return o;
}

TEST(ReplayLive, PlayIsRecordedByLcmLoggerEventForEventInOrder) {
  TempDir dir;
  const LogContents own = read_event_log(small_run_log());
  const auto o = recorded_completely(replay_cmd("play '" + small_run_log() + "' --lcm-url '" + kUrl + "' --speed 50"),
                                     dir / "bus.lcmlog", events(own, "ROBOZOO_.*").size(), "ROBOZOO_.*");
  ASSERT_EQ(o.status, 0) << o.output;
  const LogContents bus = read_event_log(dir / "bus.lcmlog");
  EXPECT_EQ(first_log_difference(own, bus), "");
  EXPECT_EQ(events(bus, "ROBOZOO_.*"), events(own, "ROBOZOO_.*"));  // the very bytes, utime included
}

TEST(ReplayLive, ChosenChannelsArriveInOrderWithTheStateBeforeThePoses) {
  TempDir dir;
  const LogContents own = read_event_log(small_run_log());
  const std::string chosen = "ROBOZOO_(GENERATION|POSE)";
  const auto o = recorded_completely(replay_cmd("play '" + small_run_log() + "' --lcm-url '" + kUrl +
                                                "' --speed 50 --channels 'ROBOZOO_(GENERATION|POSE)'"),
                                     dir / "bus.lcmlog", events(own, chosen).size(), chosen);
  ASSERT_EQ(o.status, 0) << o.output;
  const LogContents bus = read_event_log(dir / "bus.lcmlog");
  EXPECT_EQ(events(bus, chosen), events(own, chosen));
  // Each trajectory is preceded by its run, and its own genome and morphology.
  int64_t last_genome = -1, genome_seen = -1, morphology_seen = -1;
  bool run = false;
  int trajectories = 0;
  for (const auto& r : bus.records) {
    if (r.channel == kChannelRun) run = true;
    if (r.channel == kChannelGenome) genome_seen = decode_as<cppn_genome_t>(r).genome_id;
    if (r.channel == kChannelMorphology) morphology_seen = decode_as<morphology_t>(r).genome_id;
    if (r.channel != kChannelPose) continue;
    const pose_t p = decode_as<pose_t>(r);
    if (p.genome_id != last_genome) {
      ++trajectories;
      EXPECT_TRUE(run) << "pose of genome " << p.genome_id << " before any run message";
      EXPECT_EQ(genome_seen, p.genome_id);
      EXPECT_EQ(morphology_seen, p.genome_id);
      last_genome = p.genome_id;
    }
  }
  EXPECT_GT(trajectories, 0);
}

TEST(ReplayLive, SimPublishesStateThenEveryStep) {
  TempDir dir;
  const LogContents own = read_event_log(small_run_log());
  int64_t id = -1;
  int last_step = -1;  // the logged trajectory ends with the episode's last step
  for (const auto& r : own.records)
    if (r.channel == kChannelPose) {
      const pose_t p = decode_as<pose_t>(r);
      id = p.genome_id;
      last_step = p.step;
    }
  ASSERT_GE(id, 0);
  const auto o = recorded_completely(
      replay_cmd("sim '" + small_run_log() + "' --lcm-url '" + kUrl + "' --speed 20 --genome " + std::to_string(id)),
      dir / "bus.lcmlog", static_cast<size_t>(last_step + 1) + 3, "ROBOZOO_.*");
  ASSERT_EQ(o.status, 0) << o.output;
  const LogContents bus = read_event_log(dir / "bus.lcmlog");
  const auto robozoo = events(bus, "ROBOZOO_.*");
  ASSERT_GT(robozoo.size(), 3u);
  EXPECT_EQ(robozoo[0].first, kChannelRun);
  EXPECT_EQ(robozoo[1].first, kChannelGenome);
  EXPECT_EQ(robozoo[2].first, kChannelMorphology);
  for (size_t i = 3; i < robozoo.size(); ++i) {
    ASSERT_EQ(robozoo[i].first, kChannelPose);
    EXPECT_EQ(decode_as<pose_t>(LogRecord{0, 0, kChannelPose, robozoo[i].second}).step, static_cast<int>(i - 3));
  }
  EXPECT_EQ(robozoo.size() - 3, static_cast<size_t>(last_step + 1));
}

}  // namespace
}  // namespace robozoo::replay
