// robozoo-evolve publishing live: a run recorded by LCM's own lcm-logger inside a
// private network namespace. Runs alone (RUN_SERIAL), with the publisher niced
// and on one worker, so that lcm-logger has the CPU it needs.
#include <fcntl.h>
#include <gtest/gtest.h>

#include "evolve/io/event_log.hpp"
#include "evolve/io/log_compare.hpp"
#include "evolve/messages/build.hpp"
#include "evolve/messages/safe_decode.hpp"
#include "evolve/record/checkpoint.hpp"
#include "tests/support/evolve_runs.hpp"

namespace robozoo {
namespace {

using namespace robozoo::testing;

TEST(EvolveLive, LiveRunIsRecordedCompletelyByLcmLogger) {
  // At the default pacing (evolve/io/bus_pacer.hpp: one message every 20 ms, so
  // LCM's queue of 31 for lcm-logger's subscription never fills) and the default
  // --pose-every, lcm-logger records every event: no attempt is repeated. A
  // missing, changed, extra, repeated or reordered event fails, and so does any
  // publish failure the publisher counted.
  const std::string url = "udpm://239.255.76.67:7667?ttl=0";
  TempDir dir;
  const std::string bus_log = dir / "bus.lcmlog";
  const std::string script =
      "ip link set lo up && ip route add 224.0.0.0/4 dev lo && "
      "(lcm-logger -f --lcm-url='" +
      url + "' '" + bus_log + "' >/dev/null 2>&1 & L=\\$!; sleep 1; " + "nice -n 15 " +
      join(evolve_args(dir / "own.lcmlog", 1, {"--lcm-url", url})) +
      "; S=\\$?; sleep 1; kill -INT \\$L; wait \\$L; exit \\$S)";
  const auto o = run_shell("timeout 120 unshare -n sh -c \"" + script + "\"");
  ASSERT_EQ(o.status, 0) << o.output;
  const auto own = read_event_log(dir / "own.lcmlog"), bus = read_event_log(bus_log);
  // The publisher's own count, said even with --quiet: every message went out.
  size_t published = 0;
  for (const auto& r : own.records) published += r.channel.rfind("ROBOZOO_", 0) == 0;
  ASSERT_NE(o.output.find("bus: " + std::to_string(published) + " messages published, 0 publish failures"),
            std::string::npos)
      << o.output;
  for (const auto& r : bus.records) {
    if (r.channel != kChannelBus) continue;
    bus_status_t s{};
    ASSERT_TRUE(safe_decode(r.data.data(), r.data.size(), s));
    EXPECT_EQ(s.publish_failures, 0);
  }
  ASSERT_GT(count_channel(own, kChannelPose), 31u) << "the run should publish more poses than LCM's queue holds";
  const BusRecording rec = compare_bus_recording(own, bus);
  EXPECT_EQ(rec.defect, "") << "the recording is not what was sent";
  EXPECT_EQ(rec.missing, 0u) << rec.missing << " of " << rec.sent
                             << " events missing (poses: " << count_channel(own, kChannelPose) << " logged, "
                             << count_channel(bus, kChannelPose) << " received)";
}

}  // namespace
}  // namespace robozoo
