// robozoo-evolve publishing live: a run recorded by LCM's own lcm-logger inside a
// private network namespace. Runs alone (RUN_SERIAL): UDP multicast drops packets
// when a starved subscriber's socket buffer overflows, which is not what this tests.
#include <fcntl.h>
#include <gtest/gtest.h>

#include "evolve/io/event_log.hpp"
#include "evolve/io/log_compare.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/run/checkpoint.hpp"
#include "tests/support/subprocess.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

// A small run that still sends robots to the simulator: 4 generations of 24.
const std::vector<std::string> kSmall = {"--seed", "7", "--population", "24", "--generations", "4",
                                         "--steps", "400", "--quiet"};

// A run long enough (about 1.5 s on 2 cores) to be interrupted at several moments.
const std::vector<std::string> kLonger = {"--seed", "7", "--population", "40", "--generations", "8",
                                          "--steps", "1000", "--quiet"};

std::vector<std::string> evolve_args(const std::string& log, int workers, std::vector<std::string> extra = {},
                                     const std::vector<std::string>& size = kSmall) {
  std::vector<std::string> a = {bin("robozoo-evolve"), "--log", log, "--workers", std::to_string(workers)};
  a.insert(a.end(), size.begin(), size.end());
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += "'" + x + "' ";
  return s;
}


size_t count_channel(const LogContents& log, const std::string& channel) {
  size_t n = 0;
  for (const auto& r : log.records) n += r.channel == channel;
  return n;
}

TEST(EvolveLive, LiveRunIsRecordedCompletelyByLcmLogger) {
  TempDir dir;
  const std::string url = "udpm://239.255.76.67:7667?ttl=0";
  const std::string script =
      "ip link set lo up && ip route add 224.0.0.0/4 dev lo && "
      "(lcm-logger -f --lcm-url='" + url + "&recv_buf_size=4194304' '" + (dir / "bus.lcmlog") + "' >/dev/null 2>&1 & L=\\$!; sleep 1; " +
      join(evolve_args(dir / "own.lcmlog", 2, {"--lcm-url", url})) +
      "; S=\\$?; sleep 1; kill -INT \\$L; wait \\$L; exit \\$S)";
  const auto o = run_shell("timeout 120 unshare -n sh -c \"" + script + "\"");
  ASSERT_EQ(o.status, 0) << o.output;
  const auto own = read_event_log(dir / "own.lcmlog"), bus = read_event_log(dir / "bus.lcmlog");
  EXPECT_EQ(first_log_difference(own, bus), "")
      << "poses: " << count_channel(own, kChannelPose) << " logged, " << count_channel(bus, kChannelPose)
      << " received";
  EXPECT_GT(count_channel(bus, kChannelGeneration), 0u);
}

}  // namespace
}  // namespace robozoo
