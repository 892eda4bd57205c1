// robozoo-replay check --lcm-url against a running robozoo-evolve, in a private
// network namespace: a clean run gives 0, and a replay whose physics differs
// (a configuration only the replay sees) gives 1. Runs alone (RUN_SERIAL).
#include <fcntl.h>
#include <gtest/gtest.h>

#include "tests/replay/replay_fixtures.hpp"
#include "tests/support/evolve_runs.hpp"

namespace robozoo::replay {
namespace {

using namespace robozoo::testing;

const std::string kUrl = "udpm://239.255.76.67:7667?ttl=0";

/// robozoo-replay check --lcm-url (with `extra`) following a small run; its outcome.
testing::Outcome follow(const std::string& extra, TempDir& dir) {
  const std::string replay = "'" + bin("robozoo-replay") + "' check --lcm-url '" + kUrl +
                             "&recv_buf_size=4194304' --idle-exit 3 " + extra + " > '" + (dir / "replay.txt") +
                             "' 2>&1";
  const std::string script = "ip link set lo up && ip route add 224.0.0.0/4 dev lo && (" + replay +
                             " & R=\\$!; sleep 1; " + join(evolve_args(dir / "own.lcmlog", 1, {"--lcm-url", kUrl})) +
                             " >/dev/null 2>&1; wait \\$R)";
  testing::Outcome o = run_shell("timeout 180 unshare -n sh -c \"" + script + "\"");
  o.output = read_file(dir / "replay.txt");
  return o;
}

TEST(LiveCheckLive, ACleanRunIsProvedWhileItRuns) {
  // UDP may lose a datagram; the checker then says "bus loss" (exit 2). Only that,
  // measured and named, is tried again; a divergence fails at once.
  std::string lost;
  for (int attempt = 1; attempt <= 3; ++attempt) {
    TempDir dir;
    const testing::Outcome o = follow("", dir);
    ASSERT_NE(o.status, 1) << o.output;
    if (o.status == 0) {
      EXPECT_NE(o.output.find("run feedforward-s7"), std::string::npos) << o.output;
      EXPECT_NE(o.output.find("summary: 4 champions checked: 4 ok, 0 diverged, 0 unusable, 0 with bus loss"),
                std::string::npos)
          << o.output;
      if (!lost.empty()) std::cerr << "clean on attempt " << attempt << " after bus loss:\n" << lost;
      return;
    }
    ASSERT_TRUE(o.output.find("BUS LOSS") != std::string::npos || o.output.find("bus loss:") != std::string::npos)
        << "exit " << o.status << " without bus loss:\n"
        << o.output;
    lost += "attempt " + std::to_string(attempt) + ":\n" + o.output;
  }
  FAIL() << "bus loss in 3 attempts:\n" << lost;
}

TEST(LiveCheckLive, APhysicsOnlyTheReplaySeesDiverges) {
  TempDir dir;
  const testing::Outcome o = follow("--set sim.friction=0.5", dir);
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("DIVERGED"), std::string::npos) << o.output;
}

}  // namespace
}  // namespace robozoo::replay
