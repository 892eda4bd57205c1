// robozoo-evolve publishing live: a run recorded by LCM's own lcm-logger inside a
// private network namespace. Runs alone (RUN_SERIAL), with the publisher niced
// and on one worker, so that lcm-logger has the CPU it needs.
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
  // lcm-logger 1.3.1 itself sometimes drops a burst of packets in user space
  // (the kernel's UDP counters show every datagram delivered; one run in five to
  // one in three here, idle machine or not). A recording can only be complete if
  // the publisher sent every event, so the run is tried up to six times and one
  // complete recording passes; every attempt's shortfall is reported. Poses go out
  // every 25 steps (some 17 per champion rather than 200): lcm-logger loses whole
  // stretches of long bursts, and every kind of message is checked all the same.
  const std::string url = "udpm://239.255.76.67:7667?ttl=0";
  std::string failures;
  for (int attempt = 1; attempt <= 6; ++attempt) {
    TempDir dir;
    const std::string bus_log = dir / "bus.lcmlog";
    const std::string script =
        "ip link set lo up && ip route add 224.0.0.0/4 dev lo && "
        "(lcm-logger -f --lcm-url='" + url + "' '" + bus_log + "' >/dev/null 2>&1 & L=\\$!; sleep 1; " +
        "nice -n 15 " + join(evolve_args(dir / "own.lcmlog", 1, {"--lcm-url", url, "--pose-every", "25"})) +
        "; S=\\$?; sleep 1; kill -INT \\$L; wait \\$L; exit \\$S)";
    const auto o = run_shell("timeout 120 unshare -n sh -c \"" + script + "\"");
    ASSERT_EQ(o.status, 0) << o.output;
    const auto own = read_event_log(dir / "own.lcmlog"), bus = read_event_log(bus_log);
    ASSERT_GT(count_channel(bus, kChannelGeneration), 0u) << "nothing reached lcm-logger";
    const std::string diff = first_log_difference(own, bus);
    if (diff.empty()) {
      if (!failures.empty()) std::cerr << "complete on attempt " << attempt << " after:\n" << failures;
      return;
    }
    failures += "attempt " + std::to_string(attempt) + ": " + diff + " (poses: " +
                std::to_string(count_channel(own, kChannelPose)) + " logged, " +
                std::to_string(count_channel(bus, kChannelPose)) + " received)\n";
  }
  FAIL() << "no complete recording in 6 attempts:\n" << failures;
}

}  // namespace
}  // namespace robozoo
