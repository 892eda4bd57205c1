// robozoo-evolve publishing live: a run recorded by LCM's own lcm-logger inside a
// private network namespace. Runs alone (RUN_SERIAL), and the publisher runs
// niced with one worker: lcm-logger 1.3.1 silently drops packets when its
// dispatch thread is starved of CPU (the kernel's UDP counters show every
// datagram delivered), which is not what this tests.
#include <fcntl.h>
#include <gtest/gtest.h>

#include "evolve/io/event_log.hpp"
#include "evolve/io/log_compare.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/run/checkpoint.hpp"
#include "tests/support/evolve_runs.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;


TEST(EvolveLive, LiveRunIsRecordedCompletelyByLcmLogger) {
  TempDir dir;
  const std::string url = "udpm://239.255.76.67:7667?ttl=0";
  const std::string script =
      "ip link set lo up && ip route add 224.0.0.0/4 dev lo && "
      "(lcm-logger -f --lcm-url='" + url + "&recv_buf_size=4194304' '" + (dir / "bus.lcmlog") + "' >/dev/null 2>&1 & L=\\$!; sleep 1; " +
      "nice -n 15 " + join(evolve_args(dir / "own.lcmlog", 1, {"--lcm-url", url})) +
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
