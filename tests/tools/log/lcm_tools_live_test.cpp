// LCM's own tools carry a robozoo run whole: lcm-logger recording a live
// robozoo-evolve run, and lcm-logplayer replaying a run's log into lcm-logger
// at 1x and 20x. Each recording is compared with the run's own log by
// robozoo-log bus: every robozoo event, unchanged, in order. Each runs in a
// private network namespace (multicast on the loopback interface only), alone
// (RUN_SERIAL: the name ends in _live_test), with the default pacing
// (evolve/io/bus_pacer.hpp) and lcm-logger's default settings. No retries: a
// recording that lacks one event fails, and its message gives the namespace's
// kernel UDP counters, which tell a loss in the kernel (a full socket receive
// buffer) from one inside the LCM tools (every datagram delivered).
#include <fcntl.h>  // tests/support/subprocess.hpp uses open()
#include <gtest/gtest.h>

#include <sstream>

#include "evolve/io/event_log.hpp"
#include "evolve/messages/build.hpp"
#include "tests/support/evolve_runs.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

const std::string kUrl = "udpm://239.255.76.67:7667?ttl=0";

// Population 30, 3 generations of 600 steps: each new champion's trajectory is
// 151 poses at the default --pose-every 4, five times LCM's queue of 31.
// Recurrent CPPNs with the default configuration: two new champions' trajectories.
const std::vector<std::string> kRun = {"--regime",      "recurrent", "--seed",  "1",   "--population", "30",
                                       "--generations", "3",         "--steps", "600", "--quiet"};

/// Runs `inner` (a shell script) in a private network namespace with multicast
/// on the loopback interface.
testing::Outcome in_namespace(const std::string& inner) {
  return run_shell("timeout 300 unshare -n sh -c \"ip link set lo up && ip route add 224.0.0.0/4 dev lo && " + inner +
                   "\"");
}

/// `feed` (shell) while lcm-logger records the bus into `recording`. The
/// output ends with the namespace's own UDP counters (/proc/net/snmp: its
/// only traffic is this bus), which say where a lost event was lost.
testing::Outcome record(const std::string& feed, const std::string& recording) {
  return in_namespace("(lcm-logger -q -f --lcm-url='" + kUrl + "' '" + recording +
                      "' >/dev/null 2>&1 & L=\\$!; sleep 1; " + feed +
                      "; S=\\$?; sleep 1; kill -INT \\$L; wait \\$L; grep ^Udp: /proc/net/snmp; exit \\$S)");
}

/// What the namespace's UDP counters in `recorded` (record()'s output) say:
/// datagrams the kernel delivered to sockets and those it dropped for a full
/// receive buffer, or that they are missing.
std::string kernel_udp(const std::string& recorded) {
  const size_t header = recorded.find("Udp: InDatagrams");
  if (header == std::string::npos) return "no UDP counters in the output";
  const size_t values = recorded.find("Udp: ", header + 1);
  if (values == std::string::npos) return "no UDP counter values in the output";
  std::istringstream names(recorded.substr(header + 5, recorded.find('\n', header) - header - 5));
  std::istringstream counts(recorded.substr(values + 5, recorded.find('\n', values) - values - 5));
  std::string name, out = "the namespace's kernel UDP counters:";
  long long count = 0;
  while (names >> name && counts >> count)
    if (name == "InDatagrams" || name == "RcvbufErrors" || name == "InErrors" || name == "MemErrors")
      out += " " + name + " " + std::to_string(count);
  return out;
}

/// robozoo-log bus SENT RECORDED: the recording holds every robozoo event
/// sent. `recorded` is record()'s output, shown with a failure.
void expect_whole(const std::string& sent, const std::string& recording, const std::string& recorded) {
  // The counters are there to be read when something is lost.
  EXPECT_NE(kernel_udp(recorded).find(" RcvbufErrors "), std::string::npos) << kernel_udp(recorded);
  const auto o = run_shell(bin("robozoo-log") + " bus '" + sent + "' '" + recording + "'");
  const size_t poses = count_channel(read_event_log(sent), kChannelPose);
  ASSERT_GT(poses, 151u) << "the run should have published more than one trajectory";
  EXPECT_EQ(o.status, 0) << o.output << "(" << count_channel(read_event_log(recording), kChannelPose) << " of " << poses
                         << " poses recorded; " << kernel_udp(recorded) << ")";
  EXPECT_NE(o.output.find(", missing 0"), std::string::npos) << o.output << kernel_udp(recorded);
}

TEST(LcmTools, LcmLoggerRecordsALiveRunWhole) {
  TempDir dir;
  const std::string own = dir / "own.lcmlog", bus = dir / "bus.lcmlog";
  const auto o = record("nice -n 15 " + join(evolve_args(own, 1, {"--lcm-url", kUrl}, kRun)), bus);
  ASSERT_EQ(o.status, 0) << o.output;
  expect_whole(own, bus, o.output);
}

/// A run's log (no bus) played by lcm-logplayer at `speed` into lcm-logger.
void play_and_record(const std::string& speed) {
  TempDir dir;
  const std::string own = dir / "own.lcmlog", bus = dir / "bus.lcmlog";
  const auto evolve = run_shell(join(evolve_args(own, 1, {}, kRun)));
  ASSERT_EQ(evolve.status, 0) << evolve.output;
  const auto o = record("lcm-logplayer -s " + speed + " -l '" + kUrl + "' '" + own + "' >/dev/null", bus);
  ASSERT_EQ(o.status, 0) << o.output;
  expect_whole(own, bus, o.output);
}

TEST(LcmTools, LcmLogplayerAt1xIntoLcmLoggerIsWhole) { play_and_record("1"); }

TEST(LcmTools, LcmLogplayerAt20xIntoLcmLoggerIsWhole) { play_and_record("20"); }

}  // namespace
}  // namespace robozoo
